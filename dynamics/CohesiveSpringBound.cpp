// The cohesive faces' springs at their stiffest: their share of the explicit step, as a
// Gershgorin bound and as a stiffness matrix for the Lanczos estimate (CohesiveForces.hpp).
#include <Eigen/SparseCore>
#include <algorithm>
#include <cmath>

#include "core/quadrature/TriangleRule.hpp"
#include "dynamics/CohesiveForces.hpp"

namespace vorodg {

double CohesiveForces::stiffest_spring(const CohesiveLaw& law, int e, double friction,
                                       const ClosureStiffness& closure) {
  const double beta = law.parameters().shear_factor, k0 = law.parameters().initial_stiffness;
  // The law's tangent never exceeds K0 diag(1, beta^2) on any branch; the closure k adds
  // diag(k, 0) in compression, and a sticking face diag(0, k) beside it. The face's spring is
  // diagonal in its frame: its largest stiffness is the larger of the two.
  const double k = closure.of_edge(e, k0);
  return std::max({k0, k, k0 * beta * beta + (friction > 0.0 ? k : 0.0)});
}

double CohesiveForces::eigenvalue_bound(const PolygonMesh& mesh, const LumpedMass& mass,
                                        const CohesiveLaw& law, const std::vector<char>& eligible,
                                        double friction, const ClosureStiffness& closure) {
  std::vector<std::vector<double>> row(mesh.num_cells());
  for (int c = 0; c < mesh.num_cells(); ++c) row[c].assign(mesh.cell_size(c), 0.0);
  const SegmentRule& rule = gauss2_segment();
  for (int e = 0; e < mesh.num_edges(); ++e) {
    if (!eligible[e] || mesh.edge(e).cell1 < 0) continue;
    const Face f = make_face(mesh, e);
    const int cells[4] = {mesh.edge(e).cell0, mesh.edge(e).cell0, mesh.edge(e).cell1,
                          mesh.edge(e).cell1};
    const int local[4] = {f.side0[0], f.side0[1], f.side1[0], f.side1[1]};
    for (int q = 0; q < 2; ++q) {
      const double s = rule.t[q],
                   k = stiffest_spring(law, e, friction, closure) * rule.weights[q] * f.length;
      double b[4], sum = 0.0;
      for (int j = 0; j < 4; ++j) {
        b[j] = (j % 2 == 0 ? 1.0 - s : s) / std::sqrt(mass.pair_mass(cells[j], local[j]));
        sum += b[j];
      }
      for (int j = 0; j < 4; ++j) row[cells[j]][local[j]] += k * b[j] * sum;
    }
  }
  double most = 0.0;
  for (const auto& r : row)
    for (double x : r) most = std::max(most, x);
  return most;
}

Eigen::SparseMatrix<double> CohesiveForces::spring_stiffness(
    const PolygonMesh& mesh, const SplitDofMap& dofs, const CohesiveLaw& law,
    const std::vector<char>& eligible, double friction, const ClosureStiffness& closure) {
  std::vector<Eigen::Triplet<double>> entries;
  const SegmentRule& rule = gauss2_segment();
  for (int e = 0; e < mesh.num_edges(); ++e) {
    if (!eligible[e] || mesh.edge(e).cell1 < 0) continue;
    const Face f = make_face(mesh, e);
    const int c0 = mesh.edge(e).cell0, c1 = mesh.edge(e).cell1;
    const int node[4] = {dofs.node(c0, f.side0[0]), dofs.node(c0, f.side0[1]),
                         dofs.node(c1, f.side1[0]), dofs.node(c1, f.side1[1])};
    for (int q = 0; q < 2; ++q) {
      // The opening g = u_cell1 - u_cell0 at the point, each side linear between its two ends;
      // the spring k I (its stiffest direction taken for both) stores k w |g|^2 / 2.
      const double s = rule.t[q],
                   k = stiffest_spring(law, e, friction, closure) * rule.weights[q] * f.length;
      const double b[4] = {-(1.0 - s), -s, 1.0 - s, s};
      for (int i = 0; i < 4; ++i)
        for (int j = 0; j < 4; ++j)
          for (int d = 0; d < 2; ++d)
            entries.emplace_back(2 * node[i] + d, 2 * node[j] + d, k * b[i] * b[j]);
    }
  }
  Eigen::SparseMatrix<double> K(dofs.num_dofs(), dofs.num_dofs());
  K.setFromTriplets(entries.begin(), entries.end());
  return K;
}

double CohesiveForces::stable_step(const StableTimeStep& cells, const PolygonMesh& mesh,
                                   const LumpedMass& mass, const CohesiveLaw& law,
                                   const std::vector<char>& eligible, double safety,
                                   double friction, const ClosureStiffness& closure) {
  return safety * 2.0 /
         std::sqrt(cells.max_eigenvalue() +
                   eigenvalue_bound(mesh, mass, law, eligible, friction, closure));
}

}  // namespace vorodg
