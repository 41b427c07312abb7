#pragma once
// The linear system of a DG formulation, assembled in place: the elements are the cells (their
// stiffness blocks) followed by the interfaces (a block on both cells' DOFs), and every entry
// receives its contributions in that order, whatever the thread count. A symmetric system keeps
// the lower triangle of its free-free block only, added in place into a pattern built once
// (LowerBlockAssembler, as CG's); a non-symmetric one (NIPG) is summed from triplets into the
// whole free-free block. The free rows of the prescribed columns, which move the prescribed
// displacements to the right side, are summed from triplets of the few elements that touch
// prescribed DOFs.
#include <Eigen/Core>
#include <Eigen/SparseCore>
#include <functional>

#include "core/element/ElasticityIntegrator.hpp"
#include "core/solve/DirichletConstraints.hpp"
#include "interfaces/DgSpace.hpp"

namespace vorodg {

struct DgSystem {
  /// The free-free block: its lower triangle if symmetric, else all of it.
  Eigen::SparseMatrix<double> matrix;
  /// Free rows, prescribed columns (columns numbered as all DOFs).
  Eigen::SparseMatrix<double> fixed;
};

/// Interface i's block, on the DOFs of its first cell followed by those of its second.
using InterfaceBlock = std::function<Eigen::MatrixXd(std::size_t interface)>;

/// Assembles the cells' blocks and the interfaces' blocks; `interface_block` is called
/// concurrently from `threads` threads.
DgSystem assemble_dg_system(const DgSpace& space, const DirichletConstraints& constraints,
                            const ElasticityIntegrator::CellMatrices& cells,
                            const InterfaceBlock& interface_block, bool symmetric, int threads);

}  // namespace vorodg
