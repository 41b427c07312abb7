#include "core/solve/LowerBlockAssembler.hpp"

#include <omp.h>

#include <algorithm>

#include "core/util/Errors.hpp"

namespace vorodg {

LowerBlockAssembler::LowerBlockAssembler(int num_nodes, int num_elements,
                                         const ElementNodes& element_nodes)
    : num_nodes_(num_nodes) {
  // Node -> elements, by counting.
  std::vector<int> node_elem_start(num_nodes + 1, 0), node_elems;
  std::vector<int> nodes;
  for (int e = 0; e < num_elements; ++e) {
    element_nodes(e, nodes);
    for (int a : nodes)
      if (a >= 0) ++node_elem_start[a + 1];
  }
  for (int a = 0; a < num_nodes; ++a) node_elem_start[a + 1] += node_elem_start[a];
  node_elems.resize(node_elem_start.back());
  std::vector<int> fill(node_elem_start.begin(), node_elem_start.end() - 1);
  for (int e = 0; e < num_elements; ++e) {
    element_nodes(e, nodes);
    for (int a : nodes)
      if (a >= 0) node_elems[fill[a]++] = e;
  }
  // Node b's lower neighbours: every node a >= b sharing an element with it (b itself first).
  neighbor_start_.assign(num_nodes + 1, 0);
  std::vector<int> coupled;
  for (int b = 0; b < num_nodes; ++b) {
    coupled.clear();
    for (int q = node_elem_start[b]; q < node_elem_start[b + 1]; ++q) {
      element_nodes(node_elems[q], nodes);
      for (int a : nodes)
        if (a >= b) coupled.push_back(a);
    }
    if (coupled.empty()) coupled.push_back(b);  // an isolated node keeps its diagonal
    std::sort(coupled.begin(), coupled.end());
    coupled.erase(std::unique(coupled.begin(), coupled.end()), coupled.end());
    neighbors_.insert(neighbors_.end(), coupled.begin(), coupled.end());
    neighbor_start_[b + 1] = static_cast<int>(neighbors_.size());
  }
  // Unknown-level compressed columns: column 2b holds rows 2a, 2a+1 of every neighbour a
  // (b included); column 2b+1 the same without row 2b.
  const int n = 2 * num_nodes;
  matrix_.resize(n, n);
  matrix_.resizeNonZeros(static_cast<Eigen::Index>(4 * neighbors_.size() - num_nodes));
  int* outer = matrix_.outerIndexPtr();
  int* inner = matrix_.innerIndexPtr();
  outer[0] = 0;
  int k = 0;
  for (int b = 0; b < num_nodes; ++b)
    for (int d = 0; d < 2; ++d) {
      for (int q = neighbor_start_[b]; q < neighbor_start_[b + 1]; ++q) {
        const int a = neighbors_[q];
        if (!(a == b && d == 1)) inner[k++] = 2 * a;
        inner[k++] = 2 * a + 1;
      }
      outer[2 * b + d + 1] = k;
    }
  std::fill(matrix_.valuePtr(), matrix_.valuePtr() + k, 0.0);
}

int LowerBlockAssembler::entry(int a, int b, int d) const {
  const int* begin = neighbors_.data() + neighbor_start_[b];
  const int* end = neighbors_.data() + neighbor_start_[b + 1];
  const int* it = std::lower_bound(begin, end, a);
  if (it == end || *it != a) throw NumericalError("internal: node outside the assembled pattern");
  const int t = static_cast<int>(it - begin);
  // Column 2b: two rows per neighbour. Column 2b+1: row 2b+1 for b itself, then two per node.
  return matrix_.outerIndexPtr()[2 * b + d] + (d == 0 ? 2 * t : std::max(2 * t - 1, 0));
}

void LowerBlockAssembler::add(std::span<const int> nodes,
                              const Eigen::Ref<const Eigen::MatrixXd>& Ke, int node_begin,
                              int node_end) {
  double* values = matrix_.valuePtr();
  const int m = static_cast<int>(nodes.size());
  for (int jb = 0; jb < m; ++jb) {
    const int b = nodes[jb];
    if (b < node_begin || b >= node_end) continue;
    for (int ia = 0; ia < m; ++ia) {
      const int a = nodes[ia];
      if (a < b) continue;  // upper triangle or a prescribed node
      for (int dj = 0; dj < 2; ++dj) {
        const int pos = entry(a, b, dj);
        if (a == b) {
          // Diagonal node block: rows 2b (only in column 2b) and 2b+1.
          if (dj == 0) values[pos] += Ke(2 * ia, 2 * jb);
          values[pos + (dj == 0 ? 1 : 0)] += Ke(2 * ia + 1, 2 * jb + dj);
        } else {
          values[pos] += Ke(2 * ia, 2 * jb + dj);
          values[pos + 1] += Ke(2 * ia + 1, 2 * jb + dj);
        }
      }
    }
  }
}

void LowerBlockAssembler::add_in_parallel(int first, int last, int threads,
                                          const ElementNodes& element_nodes,
                                          const ElementBlock& block) {
#pragma omp parallel num_threads(std::max(threads, 1))
  {
    const int t = omp_get_thread_num(), nt = omp_get_num_threads();
    const int node_begin = static_cast<int>(static_cast<long>(num_nodes_) * t / nt);
    const int node_end = static_cast<int>(static_cast<long>(num_nodes_) * (t + 1) / nt);
    std::vector<int> nodes;
    for (int e = first; e < last; ++e) {
      element_nodes(e, nodes);
      add(nodes, block(e), node_begin, node_end);
    }
  }
}

Eigen::SparseMatrix<double> LowerBlockAssembler::release() {
  return std::move(matrix_);
}

}  // namespace vorodg
