#pragma once
// The mean infinitesimal rotation of each cell, omega_c = mean over the cell of
// (du_y/dx - du_x/dy) / 2, by the divergence theorem from the displacements of the cell's
// nodes (linear along each edge):
//     omega_c = 1/(2 A_c) sum over edges a->b of ((uy_a + uy_b) dy + (ux_a + ux_b) dx) / 2,
// with (dx, dy) = X_b - X_a and A_c the signed area, so that either orientation gives the same
// value; a rigid rotation u = theta (-y, x) gives theta exactly.
//
// Why: the dynamics is small-strain. A body rotated by theta is stress-free, but its drawn and
// contact position X + u is stretched by sqrt(1 + theta^2) - 1, about theta^2 / 2: the model
// describes spinning fragments only while their rotations stay small (docs/fragmentation.md).
#include <Eigen/Core>

#include "core/dofs/SplitDofMap.hpp"
#include "core/mesh/PolygonMesh.hpp"

namespace vorodg {

/// omega_c of cell c for node displacements u (2 per node of `dofs`).
double cell_rotation(const PolygonMesh& mesh, const SplitDofMap& dofs, const Eigen::VectorXd& u,
                     int c);
/// The largest |omega_c| over the cells.
double max_cell_rotation(const PolygonMesh& mesh, const SplitDofMap& dofs,
                         const Eigen::VectorXd& u);

}  // namespace vorodg
