#include "core/util/BlasInfo.hpp"

#include <dlfcn.h>
#include <link.h>

#include <climits>
#include <cstdlib>

namespace vorodg {

std::string blas_description() {
  // The BLAS behind libblas.so.3 (Debian's alternatives choose it), loaded if no one has yet.
  void* handle = dlopen("libblas.so.3", RTLD_LAZY | RTLD_NOLOAD);
  if (!handle) handle = dlopen("libblas.so.3", RTLD_LAZY | RTLD_LOCAL);
  if (!handle) return "no libblas.so.3 found";
  std::string path = "?";
  link_map* map = nullptr;
  if (dlinfo(handle, RTLD_DI_LINKMAP, &map) == 0 && map && map->l_name) {
    char resolved[PATH_MAX];
    path = realpath(map->l_name, resolved) ? resolved : map->l_name;
  }
  using ConfigFn = char* (*)();
  auto config = reinterpret_cast<ConfigFn>(dlsym(handle, "openblas_get_config"));
  std::string name = "reference BLAS (netlib)";
  if (config) {
    name = config();
    if (name.rfind("OpenBLAS", 0) != 0) name = "OpenBLAS " + name;
  }
  return name + " [" + path + "]";
}

}  // namespace vorodg
