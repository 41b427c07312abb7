#include "core/util/BlasInfo.hpp"

#include <dlfcn.h>
#include <link.h>
#include <omp.h>

#include <climits>
#include <cstdlib>

namespace vorodg {

namespace {
void* blas_handle() {
  void* handle = dlopen("libblas.so.3", RTLD_LAZY | RTLD_NOLOAD);
  if (!handle) handle = dlopen("libblas.so.3", RTLD_LAZY | RTLD_LOCAL);
  return handle;
}
}  // namespace

int set_blas_threads(int threads) {
  void* handle = blas_handle();
  if (!handle) return 1;
  using GetFn = int (*)();
  using SetFn = void (*)(int);
  auto get = reinterpret_cast<GetFn>(dlsym(handle, "openblas_get_num_threads"));
  auto set = reinterpret_cast<SetFn>(dlsym(handle, "openblas_set_num_threads"));
  if (!get || !set) return 1;
  const int previous = get();
  set(threads);
  return previous;
}

ScopedSerialOpenMp::ScopedSerialOpenMp() : previous_levels_(omp_get_max_active_levels()) {
  omp_set_max_active_levels(0);  // every region opened meanwhile runs on this thread alone
}

ScopedSerialOpenMp::~ScopedSerialOpenMp() {
  omp_set_max_active_levels(previous_levels_);
}

std::string blas_description() {
  // The BLAS behind libblas.so.3 (Debian's alternatives choose it), loaded if no one has yet.
  void* handle = blas_handle();
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
