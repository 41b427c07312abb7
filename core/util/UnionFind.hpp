#pragma once
// Disjoint sets over 0..n-1 with path halving: the DOF map's node classes, fragments, crack
// networks. The root of a class is always its smallest member (the larger root is hung under the
// smaller), so labels derived from roots depend only on the sets, not on the order of the joins.
#include <algorithm>
#include <numeric>
#include <vector>

namespace vorodg {

class UnionFind {
 public:
  explicit UnionFind(int n) : parent_(n) { std::iota(parent_.begin(), parent_.end(), 0); }

  int root(int a) {
    while (parent_[a] != a) a = parent_[a] = parent_[parent_[a]];
    return a;
  }
  void join(int a, int b) {
    a = root(a), b = root(b);
    if (a != b) parent_[std::max(a, b)] = std::min(a, b);
  }
  /// Per member, its class numbered 0, 1, ... in order of the classes' smallest members.
  std::vector<int> labels(int* num_classes) {
    std::vector<int> label(parent_.size(), -1), of_root(parent_.size(), -1);
    int n = 0;
    for (int a = 0; a < static_cast<int>(parent_.size()); ++a) {
      const int r = root(a);
      if (of_root[r] < 0) of_root[r] = n++;
      label[a] = of_root[r];
    }
    *num_classes = n;
    return label;
  }

 private:
  std::vector<int> parent_;
};

}  // namespace vorodg
