#pragma once
// The small-strain operator of a cell's nodal shape functions, shared by the cell stiffness and
// the DG interface tractions so that both use the same Voigt convention and DOF order.
#include <Eigen/Core>
#include <span>

namespace vorodg {

/// Voigt strain (eps_xx, eps_yy, 2 eps_xy) of a cell's DOF vector (u_x, u_y per vertex): 3 x 2n.
using StrainOperator = Eigen::Matrix<double, 3, Eigen::Dynamic>;

/// B from the gradients of the n shape functions at one point (rows xx, yy, xy).
void strain_operator(const Eigen::Vector2d* gradients, int n, StrainOperator& B);

/// K = sum_q w_q B_q^T D B_q (2n x 2n, exactly symmetric) for the standard B at the points of
/// `weights`, from the n gradients of each point stored one point after another, for any
/// symmetric D.
void standard_strain_stiffness(std::span<const double> weights, const Eigen::Vector2d* gradients,
                               int n, const Eigen::Matrix3d& D, Eigen::MatrixXd& K);

}  // namespace vorodg
