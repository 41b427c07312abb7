# FindHYPRE
# ---------
# Finds hypre (Debian's libhypre-dev 2.26 ships no CMake config) and defines the imported target
# HYPRE::HYPRE. Debian builds hypre against Open MPI with 32-bit indices and no OpenMP: every
# hypre object lives on an MPI communicator, and one process runs hypre on one thread.
#
# Result variables: HYPRE_FOUND, HYPRE_INCLUDE_DIR, HYPRE_LIBRARY, HYPRE_VERSION.

find_path(HYPRE_INCLUDE_DIR HYPRE.h PATH_SUFFIXES hypre)
find_library(HYPRE_LIBRARY NAMES HYPRE)

if(HYPRE_INCLUDE_DIR AND EXISTS "${HYPRE_INCLUDE_DIR}/HYPRE_config.h")
  file(STRINGS "${HYPRE_INCLUDE_DIR}/HYPRE_config.h" _ver REGEX "^#define HYPRE_RELEASE_VERSION ")
  string(REGEX REPLACE ".*\"([0-9.]+)\".*" "\\1" HYPRE_VERSION "${_ver}")
endif()

include(FindPackageHandleStandardArgs)
find_package_handle_standard_args(HYPRE
  REQUIRED_VARS HYPRE_LIBRARY HYPRE_INCLUDE_DIR
  VERSION_VAR HYPRE_VERSION)

if(HYPRE_FOUND AND NOT TARGET HYPRE::HYPRE)
  add_library(HYPRE::HYPRE UNKNOWN IMPORTED)
  set_target_properties(HYPRE::HYPRE PROPERTIES
    IMPORTED_LOCATION "${HYPRE_LIBRARY}"
    INTERFACE_INCLUDE_DIRECTORIES "${HYPRE_INCLUDE_DIR}")
endif()
mark_as_advanced(HYPRE_INCLUDE_DIR HYPRE_LIBRARY)
