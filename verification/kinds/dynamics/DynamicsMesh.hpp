#pragma once
// The mesh of a dynamics run: one mesh per body (generated on the body's rectangle, or read),
// joined into one PolygonMesh, because contact between bodies is contact between the surface
// cells of one mesh. The bodies share no vertex, so no cell of one is a neighbour of a cell of
// the other and the element layer sees them as separate (a weight function's patch never
// crosses between them).
#include <cstdint>
#include <string>
#include <vector>

#include "core/mesh/PolygonMesh.hpp"
#include "verification/harness/EnsembleRun.hpp"
#include "verification/kinds/dynamics/DynamicsScene.hpp"

namespace vorodg {

struct BodiesMesh {
  PolygonMesh mesh;  // its domain is the bounding box of the bodies
  /// Body b owns cells [first_cell[b], first_cell[b + 1]) and their vertices.
  std::vector<int> first_cell;
  int body_of_cell(int c) const;
  /// sqrt(area of the bodies / cells): the mesh's h_avg, without the space between bodies.
  double h_avg = 0.0;
};

/// Builds and validates the bodies' mesh of one run. Body 0 is meshed with the run's seed; body
/// 1 (two-blocks) with a seed derived from it, or, for family file, as body 0's mesh moved.
/// The problem adjusts body 0's spec and checks the mesh (DynamicsProblem::mesh_spec, check_mesh).
/// Throws InputError for a bad mesh spec or a mesh the problem cannot use, NumericalError for an
/// invalid mesh.
BodiesMesh bodies_mesh(const DynamicsScene& scene, const EnsembleRunId& run);

}  // namespace vorodg
