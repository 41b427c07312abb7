#pragma once
// A mesh with everything explicit dynamics needs, for the dynamics tests: element table, lumped
// masses, cell matrices, the stable step, and an integrator on the continuous DOF map.
#include <memory>

#include "core/dofs/SplitDofMap.hpp"
#include "core/element/ElasticityIntegrator.hpp"
#include "core/element/ElementTable.hpp"
#include "core/material/IsotropicElasticity.hpp"
#include "core/meshgen/MeshFamily.hpp"
#include "core/util/Random.hpp"
#include "dynamics/CentralDifference.hpp"
#include "dynamics/InternalForce.hpp"
#include "dynamics/LumpedMass.hpp"
#include "dynamics/StableTimeStep.hpp"

namespace vorodg::testing {

inline MeshSpec mesh_spec(MeshFamily family, const Rectangle& domain, double size,
                          std::uint64_t seed = 5) {
  MeshSpec spec;
  spec.family = family;
  spec.domain = domain;
  spec.size = size;
  spec.seed = seed;
  return spec;
}

/// Not movable: the table refers to the mesh.
struct DynamicsModel {
  PolygonMesh mesh;
  ElementTable table;
  LumpedMass mass;
  ElasticityIntegrator integrator;
  ElasticityIntegrator::CellMatrices matrices;
  StableTimeStep limit;

  DynamicsModel(const MeshSpec& spec, const IsotropicElasticity& material, double density,
                bool mean_dilation = false)
      : mesh(generate_mesh(spec).mesh),
        table(mesh, ElementOptions{}),
        mass(table, density),
        integrator(table, material, mean_dilation),
        matrices(integrator.all_cell_matrices(1)),
        limit(mesh, matrices, mass) {}
  DynamicsModel(const DynamicsModel&) = delete;

  std::unique_ptr<CentralDifference> integrator_with(double dt,
                                                     DynamicsOptions options = {}) const {
    return std::make_unique<CentralDifference>(mesh, mass, InternalForce(mesh, matrices),
                                               SplitDofMap::continuous(mesh), dt, options);
  }
};

/// Uniform random values in [-amplitude, amplitude), one per entry, from a fixed seed.
inline Eigen::VectorXd random_vector(int size, double amplitude, std::uint64_t seed) {
  Random random(seed);
  Eigen::VectorXd x(size);
  for (int i = 0; i < size; ++i) x[i] = random.uniform(-amplitude, amplitude);
  return x;
}

}  // namespace vorodg::testing
