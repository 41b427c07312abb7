#pragma once
// The mesh of a dynamics run from its scene: one mesh per body (generated on the body's rectangle,
// or read), joined into one BodiesMesh (dynamics/BodiesMesh.hpp).
#include <cstdint>
#include <string>
#include <vector>

#include "core/mesh/PolygonMesh.hpp"
#include "dynamics/BodiesMesh.hpp"
#include "verification/harness/EnsembleRun.hpp"
#include "verification/kinds/dynamics/DynamicsScene.hpp"

namespace vorodg {

/// Builds and validates the bodies' mesh of one run. Body 0 is meshed with the run's seed; body
/// 1 (two-blocks) with a seed derived from it, or, for family file, as body 0's mesh moved.
/// The problem adjusts body 0's spec and checks the mesh (DynamicsProblem::mesh_spec, check_mesh).
/// Throws InputError for a bad mesh spec or a mesh the problem cannot use, NumericalError for an
/// invalid mesh.
BodiesMesh bodies_mesh(const DynamicsScene& scene, const EnsembleRunId& run);

}  // namespace vorodg
