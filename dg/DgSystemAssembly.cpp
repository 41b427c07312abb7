#include "dg/DgSystemAssembly.hpp"

#include <omp.h>

#include <algorithm>
#include <optional>
#include <vector>

#include "core/solve/LowerBlockAssembler.hpp"

namespace vorodg {
namespace {

/// The elements in assembly order: cells [0, nc), then interfaces [nc, nc + ni).
class DgElements {
 public:
  DgElements(const DgSpace& space, const DirichletConstraints& constraints)
      : space_(space), constraints_(constraints), nc_(space.mesh().num_cells()) {}

  int count() const { return nc_ + static_cast<int>(space_.interfaces().size()); }
  /// Element e's DOFs: a cell's own, or an interface's first cell's then second cell's.
  void dofs(int e, std::vector<int>& out) const {
    out.clear();
    if (e < nc_) return append_cell(e, out);
    const Interface& f = space_.interfaces()[e - nc_];
    append_cell(f.cell[0], out);
    append_cell(f.cell[1], out);
  }
  /// Element e's free nodes: a node is a DOF pair (2k, 2k + 1) of the free unknowns, or -1 where
  /// the pair is prescribed (both components of a vertex copy are prescribed or free together).
  void nodes(int e, std::vector<int>& out) const {
    dofs(e, scratch());
    out.clear();
    for (std::size_t k = 0; k < scratch().size(); k += 2) {
      const int f = constraints_.free_index(scratch()[k]);
      out.push_back(f < 0 ? -1 : f / 2);
    }
  }

 private:
  void append_cell(int c, std::vector<int>& out) const {
    for (int k = 0; k < space_.mesh().cell_size(c); ++k) {
      out.push_back(space_.dof(c, k));
      out.push_back(space_.dof(c, k) + 1);
    }
  }
  static std::vector<int>& scratch() {
    thread_local std::vector<int> dofs;
    return dofs;
  }

  const DgSpace& space_;
  const DirichletConstraints& constraints_;
  int nc_;
};

/// Adds element e's block to the triplets: free-prescribed entries to `fixed`, and free-free
/// entries to `free` unless it is null. Column by column, as the triplet assembly always ran.
void add_triplets(const DirichletConstraints& constraints, const std::vector<int>& dofs,
                  const Eigen::Ref<const Eigen::MatrixXd>& block,
                  std::vector<Eigen::Triplet<double>>& fixed,
                  std::vector<Eigen::Triplet<double>>* free) {
  const int m = static_cast<int>(dofs.size());
  for (int j = 0; j < m; ++j) {
    const int fj = constraints.free_index(dofs[j]);
    if (fj >= 0 && !free) continue;
    for (int i = 0; i < m; ++i) {
      const int fi = constraints.free_index(dofs[i]);
      if (fi < 0) continue;
      if (fj < 0)
        fixed.emplace_back(fi, dofs[j], block(i, j));
      else
        free->emplace_back(fi, fj, block(i, j));
    }
  }
}

bool touches_prescribed(const DirichletConstraints& constraints, const std::vector<int>& dofs) {
  return std::any_of(dofs.begin(), dofs.end(),
                     [&](int d) { return constraints.free_index(d) < 0; });
}

}  // namespace

DgSystem assemble_dg_system(const DgSpace& space, const DirichletConstraints& constraints,
                            const ElasticityIntegrator::CellMatrices& cells,
                            const InterfaceBlock& interface_block, bool symmetric, int threads) {
  const DgElements elements(space, constraints);
  const int nc = space.mesh().num_cells(), ne = elements.count();
  const int n_free = constraints.num_free(), nodes = n_free / 2;
  const LowerBlockAssembler::ElementNodes element_nodes = [&](int e, std::vector<int>& out) {
    elements.nodes(e, out);
  };
  std::optional<LowerBlockAssembler> lower;
  if (symmetric) lower.emplace(nodes, ne, element_nodes);
  std::vector<Eigen::Triplet<double>> fixed, free;

  // Interface blocks are computed a chunk at a time (in parallel, each into its own slot), which
  // bounds their memory; cells come first as chunk 0 from the matrices given.
  constexpr int kChunk = 8192;
  std::vector<Eigen::MatrixXd> blocks(kChunk);
  const auto block_of = [&](int e, int first) -> Eigen::Ref<const Eigen::MatrixXd> {
    if (e < nc) return cells.block(e, space.cell_dof_count(e));
    return blocks[e - first];
  };
  std::vector<int> dofs;
  for (int first = 0; first < ne;) {
    const int last = first < nc ? nc : std::min(first + kChunk, ne);
    if (first >= nc) {
#pragma omp parallel for schedule(dynamic, 64) num_threads(threads)
      for (int e = first; e < last; ++e)
        blocks[e - first] = interface_block(static_cast<std::size_t>(e - nc));
    }
    if (lower)  // entries sum in element order, whatever the thread count
      lower->add_in_parallel(first, last, threads, element_nodes,
                             [&](int e) { return block_of(e, first); });
    for (int e = first; e < last; ++e) {
      elements.dofs(e, dofs);
      if (!lower || touches_prescribed(constraints, dofs))
        add_triplets(constraints, dofs, block_of(e, first), fixed, lower ? nullptr : &free);
    }
    first = last;
  }

  DgSystem system;
  if (lower) {
    system.matrix = lower->release();
  } else {
    system.matrix.resize(n_free, n_free);
    system.matrix.setFromTriplets(free.begin(), free.end());
  }
  system.fixed.resize(n_free, space.num_dofs());
  system.fixed.setFromTriplets(fixed.begin(), fixed.end());
  return system;
}

}  // namespace vorodg
