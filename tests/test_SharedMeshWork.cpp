// Work shared by the runs on one mesh (verification/solve/SharedMeshWork,
// core/solve/SymbolicAnalyses):
// 1. A factorization with a kept symbolic analysis solves to the same bits as one that analyzed
//    afresh; the second factorization of a pattern reports the analysis as shared, with the
//    first one's analysis time; another pattern, or another ordering, gets its own analysis.
// 2. run_solve with the shared work gives the same errors and DOFs, bit for bit, as run_solve
//    alone, for cg, dg-nitsche, dg-al and symmetric dg-sipg run one after another on one mesh
//    (the order a study runs them), and names the stages it shared.
// 3. An element setting that changes the table gets a table of its own; the thread count does
//    not.
#include <gtest/gtest.h>

#include <Eigen/SparseCore>
#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "core/solve/SparseCholesky.hpp"
#include "core/solve/SymbolicAnalyses.hpp"
#include "support/ElementTestMeshes.hpp"
#include "verification/solve/SharedMeshWork.hpp"
#include "verification/solve/SolveRun.hpp"

namespace vorodg {
namespace {

using testing::make_mesh;

/// The lower triangle of a 2D grid Laplacian (n x n nodes, two DOFs per node) plus `shift` I.
Eigen::SparseMatrix<double> grid_matrix(int n, double shift, bool diagonal_neighbours) {
  std::vector<Eigen::Triplet<double>> t;
  const auto id = [n](int i, int j) { return i * n + j; };
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j) {
      const int a = id(i, j);
      for (int d = 0; d < 2; ++d) t.emplace_back(2 * a + d, 2 * a + d, 4.0 + shift);
      std::vector<int> next;
      if (i + 1 < n) next.push_back(id(i + 1, j));
      if (j + 1 < n) next.push_back(id(i, j + 1));
      if (diagonal_neighbours && i + 1 < n && j + 1 < n) next.push_back(id(i + 1, j + 1));
      for (int b : next)
        for (int d = 0; d < 2; ++d) t.emplace_back(2 * b + d, 2 * a + d, -1.0);
    }
  Eigen::SparseMatrix<double> m(2 * n * n, 2 * n * n);
  m.setFromTriplets(t.begin(), t.end());
  return m;
}

TEST(SymbolicAnalyses, ASharedAnalysisSolvesToTheSameBits) {
  const int n = 50;  // 5000 DOFs: the node-METIS ordering is used
  SymbolicAnalyses analyses;
  const Eigen::VectorXd b = Eigen::VectorXd::LinSpaced(2 * n * n, -1.0, 2.0);
  SparseCholesky fresh, first, second;
  const auto A1 = grid_matrix(n, 0.5, false), A2 = grid_matrix(n, 2.0, false);
  const FactorizationReport r1 = first.factorize(A1, {.shared_analyses = &analyses});
  const FactorizationReport r2 = second.factorize(A2, {.shared_analyses = &analyses});
  fresh.factorize(A2);
  EXPECT_FALSE(r1.analysis_shared);
  EXPECT_TRUE(r2.analysis_shared);
  EXPECT_EQ(r2.seconds_analyze, r1.seconds_analyze);
  EXPECT_EQ(analyses.size(), 1);
  const Eigen::VectorXd x_shared = second.solve(b), x_fresh = fresh.solve(b);
  for (Eigen::Index i = 0; i < b.size(); ++i) ASSERT_EQ(x_shared[i], x_fresh[i]) << "entry " << i;
}

TEST(SymbolicAnalyses, AnotherPatternOrOrderingIsAnalyzedAgain) {
  SymbolicAnalyses analyses;
  SparseCholesky a, b, c;
  a.factorize(grid_matrix(50, 1.0, false), {.shared_analyses = &analyses});
  const auto other = b.factorize(grid_matrix(50, 3.0, true), {.shared_analyses = &analyses});
  const auto amd = c.factorize(grid_matrix(50, 1.0, false),
                               {.ordering = FillOrdering::node_amd, .shared_analyses = &analyses});
  EXPECT_FALSE(other.analysis_shared);
  EXPECT_FALSE(amd.analysis_shared);
  EXPECT_EQ(analyses.size(), 3);
}

TEST(SharedMeshWork, RunsOnOneMeshGiveTheSameBitsAsRunsAlone) {
  const PolygonMesh mesh = make_mesh(MeshFamily::rcp, Rectangle(0.0, -0.5, 4.0, 0.5), 0.1, 11);
  SharedMeshWork shared(mesh);
  SolveSettings base;
  base.problem = "beam";
  base.element.threads = 2;
  const std::vector<std::pair<std::string, double>> runs = {
      {"cg", 0.0}, {"dg-nitsche", 1e3}, {"dg-al", 1e3}, {"dg-nitsche", 1e1}, {"dg-sipg", 1e3}};
  for (std::size_t k = 0; k < runs.size(); ++k) {
    SolveSettings s = base;
    s.formulation = runs[k].first;
    s.dg.kp = runs[k].second;
    if (s.formulation == "dg-sipg") s.dg.penalty = PenaltyScaling::h_avg;
    const SolveResult alone = run_solve(mesh, s);
    const SolveResult with = run_solve(mesh, s, &shared);
    SCOPED_TRACE(s.formulation + " k_p " + std::to_string(runs[k].second));
    EXPECT_EQ(with.l2_error, alone.l2_error);
    EXPECT_EQ(with.energy_error, alone.energy_error);
    ASSERT_EQ(with.cell_dof_values.size(), alone.cell_dof_values.size());
    EXPECT_TRUE(with.cell_dof_values == alone.cell_dof_values);
    EXPECT_TRUE(alone.shared_stages.empty());
    const auto& st = with.shared_stages;
    const bool element = std::find(st.begin(), st.end(), "element") != st.end();
    const bool analysis = std::find(st.begin(), st.end(), "analysis") != st.end();
    EXPECT_EQ(element, k > 0);   // the first run builds the table
    EXPECT_EQ(analysis, k > 1);  // cg and the first DG run analyze their own patterns
  }
}

TEST(SharedMeshWork, OneTablePerElementSetting) {
  const PolygonMesh mesh = make_mesh(MeshFamily::rcp, Rectangle(0.0, 0.0, 1.0, 1.0), 0.2, 3);
  SharedMeshWork shared(mesh);
  double seconds = 0.0;
  bool reused = true;
  ElementOptions one;
  const ElementTable& a = shared.element_table(one, seconds, reused);
  EXPECT_FALSE(reused);
  ElementOptions threads = one;
  threads.threads = 2;
  EXPECT_EQ(&shared.element_table(threads, seconds, reused), &a);
  EXPECT_TRUE(reused);
  ElementOptions six = one;
  six.rule_points = 6;
  EXPECT_NE(&shared.element_table(six, seconds, reused), &a);
  EXPECT_FALSE(reused);
}

}  // namespace
}  // namespace vorodg
