#pragma once
// What a problem does to an explicit run beyond ExplicitParameters: where its cracks may form and
// where they are at t = 0, its prescribed velocities and loads, and the velocities it adds at
// t = 0 beyond each body's rigid motion. A study's problem implements it; a library user may pass
// ExplicitLoading{} for none of them.
#include <Eigen/Core>
#include <vector>

#include "core/mesh/PolygonMesh.hpp"
#include "dynamics/CentralDifference.hpp"
#include "dynamics/ExplicitParameters.hpp"

namespace vorodg {

/// Where a fragmentation run's cracks may form, and those there at t = 0, by mesh edge.
struct CrackSites {
  std::vector<char> eligible;  // per edge: checked by the insertion criterion (empty: every edge)
  std::vector<int> pre_inserted;  // cohesive faces from t = 0, the law from zero opening
  std::vector<int> free;          // split from t = 0 with no cohesive traction (a notch)
};

class ExplicitLoading {
 public:
  virtual ~ExplicitLoading() = default;
  /// Fragmentation: where cracks may form and where they are at t = 0; by default every interior
  /// edge may crack and none has.
  virtual CrackSites crack_sites(const PolygonMesh&) const { return {}; }
  /// Prescribed velocities and loads (gravity is the parameters').
  virtual void add_boundaries(const PolygonMesh&, CentralDifference&) const {}
  /// What is added to a node's velocity at t = 0 beyond its body's rigid motion.
  virtual void add_initial_velocity(const DynamicsBody&, const Eigen::Vector2d&,
                                    Eigen::Ref<Eigen::Vector2d>) const {}
};

}  // namespace vorodg
