# FindCHOLMOD
# -----------
# Finds SuiteSparse's CHOLMOD (Debian's SuiteSparse 5.12 ships no CMake config) and defines the
# imported target SuiteSparse::CHOLMOD, the name SuiteSparse 7 exports, so that moving to a newer
# SuiteSparse needs no change in the targets that link it.
#
# Result variables: CHOLMOD_FOUND, CHOLMOD_INCLUDE_DIR, CHOLMOD_LIBRARY, CHOLMOD_VERSION.

find_path(CHOLMOD_INCLUDE_DIR cholmod.h PATH_SUFFIXES suitesparse)
find_library(CHOLMOD_LIBRARY NAMES cholmod)
find_library(SUITESPARSE_CONFIG_LIBRARY NAMES suitesparseconfig)
foreach(_dep amd camd colamd ccolamd)
  string(TOUPPER ${_dep} _DEP)
  find_library(${_DEP}_LIBRARY NAMES ${_dep})
endforeach()

if(CHOLMOD_INCLUDE_DIR AND EXISTS "${CHOLMOD_INCLUDE_DIR}/cholmod_core.h")
  file(STRINGS "${CHOLMOD_INCLUDE_DIR}/cholmod_core.h" _ver REGEX "^#define CHOLMOD_(MAIN|SUB)_VERSION +[0-9]+")
  string(REGEX REPLACE ".*MAIN_VERSION +([0-9]+).*" "\\1" _major "${_ver}")
  string(REGEX REPLACE ".*SUB_VERSION +([0-9]+).*" "\\1" _minor "${_ver}")
  set(CHOLMOD_VERSION "${_major}.${_minor}")
endif()

include(FindPackageHandleStandardArgs)
find_package_handle_standard_args(CHOLMOD
  REQUIRED_VARS CHOLMOD_LIBRARY CHOLMOD_INCLUDE_DIR SUITESPARSE_CONFIG_LIBRARY
  VERSION_VAR CHOLMOD_VERSION)

if(CHOLMOD_FOUND AND NOT TARGET SuiteSparse::CHOLMOD)
  add_library(SuiteSparse::CHOLMOD UNKNOWN IMPORTED)
  set(_deps "${SUITESPARSE_CONFIG_LIBRARY}")
  foreach(_lib AMD_LIBRARY CAMD_LIBRARY COLAMD_LIBRARY CCOLAMD_LIBRARY)
    if(${_lib})
      list(APPEND _deps "${${_lib}}")
    endif()
  endforeach()
  set_target_properties(SuiteSparse::CHOLMOD PROPERTIES
    IMPORTED_LOCATION "${CHOLMOD_LIBRARY}"
    INTERFACE_INCLUDE_DIRECTORIES "${CHOLMOD_INCLUDE_DIR}"
    INTERFACE_LINK_LIBRARIES "${_deps}")
endif()
mark_as_advanced(CHOLMOD_INCLUDE_DIR CHOLMOD_LIBRARY SUITESPARSE_CONFIG_LIBRARY
  AMD_LIBRARY CAMD_LIBRARY COLAMD_LIBRARY CCOLAMD_LIBRARY)
