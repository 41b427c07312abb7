#pragma once
// What the benchmarks share: rcp meshes of about n cells on the 4 x 1 domain (seed 11), one
// object per mesh size built once for the whole program (an element table, a model), and the
// element setup options of their models.
#include <cmath>
#include <map>
#include <memory>

#include "core/element/ElementTable.hpp"
#include "core/meshgen/MeshFamily.hpp"

namespace vorodg::bench {

/// Element setup for the benchmarks' models: two threads (setup is not what they measure).
inline ElementOptions setup_options() {
  ElementOptions o;
  o.threads = 2;
  return o;
}

/// An rcp spec of about n cells on [0, 4] x [0, 1].
inline MeshSpec rcp_spec(int n) {
  MeshSpec spec;
  spec.family = MeshFamily::rcp;
  spec.domain = Rectangle(0, 0, 4, 1);
  spec.size = std::sqrt(0.7 * spec.domain.area() / n);
  spec.seed = 11;
  return spec;
}

/// A T built from rcp_spec(n), once per n.
template <class T>
const T& once_per_size(int n) {
  static std::map<int, std::unique_ptr<T>> cache;
  auto& slot = cache[n];
  if (!slot) slot = std::make_unique<T>(rcp_spec(n));
  return *slot;
}

}  // namespace vorodg::bench
