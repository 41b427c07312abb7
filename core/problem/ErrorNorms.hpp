#pragma once
// Discretization errors against an exact solution, integrated cell by cell with a rule finer
// than the assembly rule: the 7-point (degree 5) rule on every sub-triangle of the weight
// functions' lattice. The shape functions are only piecewise smooth (their gradients kink
// along those sub-triangles), so a rule that straddles them would misjudge the energy error.
// Gradients are the shape functions' own (the divergence correction is a quadrature device).
#include <Eigen/Core>
#include <functional>
#include <vector>

#include "core/element/ElementTable.hpp"
#include "core/problem/ExactSolution.hpp"

namespace vorodg {

struct ErrorReport {
  double l2_error = 0.0;      // ||u_h - u|| / ||u||, L2 over the domain
  double energy_error = 0.0;  // a(u_h - u, u_h - u)^1/2 / a(u, u)^1/2
  double l2_absolute = 0.0, energy_absolute = 0.0;
  std::vector<double> cell_l2_density;      // per cell: int |u_h - u|^2 / area
  std::vector<double> cell_energy_density;  // per cell: int (eps_h - eps) D (eps_h - eps) / area
};

/// `cell_dofs(c)` gives the DOF vector (u_x, u_y per vertex in loop order) of cell c: the same
/// call serves CG (gathered from vertices) and DG (the cell's own copies).
/// With `dilatation_mean` (mean dilation) the discrete strain in the energy norm is the one the
/// method uses: its in-plane dilatation replaced by the cell mean that dilatation_mean(c, u)
/// gives (otherwise, near incompressibility, the lambda-weighted pointwise dilatation that mean
/// dilation leaves uncontrolled swamps the norm).
using CellDilatationMean = std::function<double(int, const Eigen::VectorXd&)>;
ErrorReport compute_errors(const ElementTable& table, const ExactSolution& exact,
                           const std::function<Eigen::VectorXd(int)>& cell_dofs, bool energy = true,
                           int threads = 1, const CellDilatationMean& dilatation_mean = {});

}  // namespace vorodg
