#pragma once
// The right-hand side l(v) = (b, v) + <t, v> on traction sides, for any DOF numbering: CG numbers
// a vertex's DOFs once, DG once per cell copy. `first_dof(c, k)` gives the x DOF of cell c's
// vertex k (y follows it).
#include <Eigen/Core>
#include <functional>

#include "core/element/ElementTable.hpp"
#include "core/problem/BoundaryValueProblem.hpp"

namespace vorodg {

using DofOf = std::function<int(int cell, int k)>;

/// Adds the body force, integrated with the element table's rule.
void add_body_force(const ElementTable& table, const BoundaryValueProblem& problem,
                    const DofOf& first_dof, Eigen::VectorXd& f);
/// Adds the tractions of traction sides; shape functions are linear along edges, so the two-point
/// Gauss rule is exact for linear tractions.
void add_boundary_tractions(const PolygonMesh& mesh, const BoundaryValueProblem& problem,
                            const DofOf& first_dof, Eigen::VectorXd& f);
/// Marks the vertices on Dirichlet sides (the Kronecker-delta property puts the data there).
std::vector<char> dirichlet_vertices(const PolygonMesh& mesh, const BoundaryValueProblem& problem);

}  // namespace vorodg
