#pragma once
// The small-strain operator of a cell's nodal shape functions, shared by the cell stiffness and
// the DG interface tractions so that both use the same Voigt convention and DOF order.
#include <Eigen/Core>

namespace vorodg {

/// Voigt strain (eps_xx, eps_yy, 2 eps_xy) of a cell's DOF vector (u_x, u_y per vertex): 3 x 2n.
using StrainOperator = Eigen::Matrix<double, 3, Eigen::Dynamic>;

/// B from the gradients of the n shape functions at one point (rows xx, yy, xy).
void strain_operator(const Eigen::Vector2d* gradients, int n, StrainOperator& B);

}  // namespace vorodg
