// The DG system assembled in place (dg/DgSystemAssembly) against a dense reference built entry
// by entry from the same blocks: cells' stiffness matrices and, per interface, a made-up block
// on its two cells' DOFs (symmetric, or not, to exercise both storages).
// 1. Symmetric: the matrix holds exactly the lower triangle of the free-free block, to 1e-14 of
//    the largest entry; the prescribed columns match too (patch problem: prescribed on all sides).
// 2. Non-symmetric: the whole free-free block, same tolerance.
// 3. One and two threads give the same bits (values and pattern).
#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <cmath>

#include "core/element/ElasticityIntegrator.hpp"
#include "core/element/ElementTable.hpp"
#include "core/problem/AffineField.hpp"
#include "core/solve/DirichletConstraints.hpp"
#include "dg/DgSystemAssembly.hpp"
#include "interfaces/DgSpace.hpp"
#include "support/ElementTestMeshes.hpp"

namespace vorodg {
namespace {

using testing::make_mesh;

struct Fixture {
  PolygonMesh mesh = make_mesh(MeshFamily::rcp, Rectangle(0.0, 0.0, 2.0, 1.0), 0.2, 7);
  IsotropicElasticity material{1.0, 0.3, PlaneModel::stress};
  ElementTable table{mesh, ElementOptions{}};
  ElasticityIntegrator integrator{table, material, false};
  AffineField field{material, AffineField::Supports::dirichlet};
  DgSpace space{mesh};
  DirichletConstraints constraints{mesh, field, [this](int c, int k) { return space.dof(c, k); },
                                   space.num_dofs()};
  ElasticityIntegrator::CellMatrices cells = integrator.all_cell_matrices(1);
};

/// A deterministic block for interface i on m DOFs; symmetric if asked.
Eigen::MatrixXd made_up_block(std::size_t i, int m, bool symmetric) {
  Eigen::MatrixXd B(m, m);
  for (int c = 0; c < m; ++c)
    for (int r = 0; r < m; ++r) B(r, c) = std::sin(1.0 + 0.37 * r + 0.91 * c + 0.13 * i);
  if (symmetric) B = (B + B.transpose()).eval();
  return B;
}

InterfaceBlock blocks_of(const Fixture& f, bool symmetric) {
  return [&f, symmetric](std::size_t i) {
    const Interface& face = f.space.interfaces()[i];
    const int m = f.space.cell_dof_count(face.cell[0]) + f.space.cell_dof_count(face.cell[1]);
    return made_up_block(i, m, symmetric);
  };
}

/// The whole matrix on all DOFs, dense, from the same blocks.
Eigen::MatrixXd dense_reference(const Fixture& f, bool symmetric) {
  const int n = f.space.num_dofs();
  Eigen::MatrixXd A = Eigen::MatrixXd::Zero(n, n);
  const auto scatter = [&](const std::vector<int>& dofs, const Eigen::MatrixXd& B) {
    for (std::size_t j = 0; j < dofs.size(); ++j)
      for (std::size_t i = 0; i < dofs.size(); ++i) A(dofs[i], dofs[j]) += B(i, j);
  };
  for (int c = 0; c < f.mesh.num_cells(); ++c)
    scatter(f.space.cell_dofs(c), f.cells.block(c, f.space.cell_dof_count(c)));
  const auto block = blocks_of(f, symmetric);
  for (std::size_t i = 0; i < f.space.interfaces().size(); ++i) {
    const Interface& face = f.space.interfaces()[i];
    std::vector<int> dofs = f.space.cell_dofs(face.cell[0]);
    const std::vector<int> second = f.space.cell_dofs(face.cell[1]);
    dofs.insert(dofs.end(), second.begin(), second.end());
    scatter(dofs, block(i));
  }
  return A;
}

void expect_matches(const Fixture& f, bool symmetric) {
  const DgSystem system =
      assemble_dg_system(f.space, f.constraints, f.cells, blocks_of(f, symmetric), symmetric, 2);
  const Eigen::MatrixXd A = dense_reference(f, symmetric);
  const int nf = f.constraints.num_free();
  ASSERT_GT(nf, 0);
  ASSERT_LT(nf, f.space.num_dofs());  // some DOFs prescribed
  Eigen::MatrixXd free(nf, nf), fixed = Eigen::MatrixXd::Zero(nf, f.space.num_dofs());
  for (int j = 0; j < nf; ++j)
    for (int i = 0; i < nf; ++i)
      free(i, j) = A(f.constraints.free_dof(i), f.constraints.free_dof(j));
  for (int j = 0; j < f.space.num_dofs(); ++j)
    if (f.constraints.free_index(j) < 0)
      for (int i = 0; i < nf; ++i) fixed(i, j) = A(f.constraints.free_dof(i), j);
  const Eigen::MatrixXd expected =
      symmetric ? Eigen::MatrixXd(free.triangularView<Eigen::Lower>()) : free;
  const double scale = A.cwiseAbs().maxCoeff();
  EXPECT_LT((Eigen::MatrixXd(system.matrix) - expected).cwiseAbs().maxCoeff(), 1e-14 * scale);
  EXPECT_LT((Eigen::MatrixXd(system.fixed) - fixed).cwiseAbs().maxCoeff(), 1e-14 * scale);
}

TEST(DgSystemAssembly, SymmetricKeepsTheLowerTriangleOfTheFreeBlock) {
  const Fixture f;
  expect_matches(f, true);
}

TEST(DgSystemAssembly, NonSymmetricKeepsTheWholeFreeBlock) {
  const Fixture f;
  expect_matches(f, false);
}

TEST(DgSystemAssembly, ThreadCountDoesNotChangeABit) {
  const Fixture f;
  for (bool symmetric : {true, false}) {
    const auto blocks = blocks_of(f, symmetric);
    const DgSystem one = assemble_dg_system(f.space, f.constraints, f.cells, blocks, symmetric, 1);
    const DgSystem two = assemble_dg_system(f.space, f.constraints, f.cells, blocks, symmetric, 2);
    for (const auto& [a, b] : {std::pair{&one.matrix, &two.matrix}, {&one.fixed, &two.fixed}}) {
      ASSERT_EQ(a->nonZeros(), b->nonZeros());
      for (Eigen::Index k = 0; k < a->nonZeros(); ++k) {
        EXPECT_EQ(a->valuePtr()[k], b->valuePtr()[k]);
        EXPECT_EQ(a->innerIndexPtr()[k], b->innerIndexPtr()[k]);
      }
    }
  }
}

}  // namespace
}  // namespace vorodg
