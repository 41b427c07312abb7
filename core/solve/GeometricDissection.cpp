#include "core/solve/GeometricDissection.hpp"

#include <algorithm>
#include <string>

#include "core/util/Errors.hpp"

namespace vorodg {

Adjacency symmetric_adjacency(const std::vector<int>& lower_col_start,
                              const std::vector<int>& lower_rows) {
  const int n = static_cast<int>(lower_col_start.size()) - 1;
  Adjacency g;
  g.col_start.assign(n + 1, 0);
  for (int j = 0; j < n; ++j)
    for (int q = lower_col_start[j]; q < lower_col_start[j + 1]; ++q)
      if (const int i = lower_rows[q]; i != j) ++g.col_start[i + 1], ++g.col_start[j + 1];
  for (int j = 0; j < n; ++j) g.col_start[j + 1] += g.col_start[j];
  g.rows.resize(g.col_start[n]);
  std::vector<int> next(g.col_start.begin(), g.col_start.end() - 1);
  for (int j = 0; j < n; ++j)
    for (int q = lower_col_start[j]; q < lower_col_start[j + 1]; ++q)
      if (const int i = lower_rows[q]; i != j) g.rows[next[i]++] = j, g.rows[next[j]++] = i;
  return g;
}

namespace {

class Dissection {
 public:
  Dissection(const Adjacency& graph, const Eigen::Matrix2Xd& points, int leaf_size)
      : graph_(graph),
        points_(points),
        leaf_size_(std::max(leaf_size, 1)),
        mark_(points.cols(), -1),
        local_(points.cols(), -1) {
    order_.reserve(points.cols());
  }

  std::vector<int> run() {
    std::vector<int> nodes(points_.cols());
    for (int k = 0; k < static_cast<int>(nodes.size()); ++k) nodes[k] = k;
    dissect(nodes);
    return std::move(order_);
  }

 private:
  /// Orders `nodes` (appended to order_): the two halves first, each dissected, then the separator.
  void dissect(std::vector<int>& nodes) {
    if (static_cast<int>(nodes.size()) <= leaf_size_) {
      append(nodes);
      return;
    }
    Cut cut = cut_at_median(nodes, longer_axis(nodes));
    nodes.clear();
    nodes.shrink_to_fit();
    dissect(cut.first);
    dissect(cut.second);
    append(cut.separator);
  }

  void append(const std::vector<int>& nodes) {
    order_.insert(order_.end(), nodes.begin(), nodes.end());
  }

  struct Cut {
    std::vector<int> first, second, separator;
  };

  /// The nodes split at the median of one coordinate, less the cover of the edges between them.
  Cut cut_at_median(std::vector<int>& nodes, int axis) {
    auto middle = nodes.begin() + static_cast<std::ptrdiff_t>(nodes.size() / 2);
    std::nth_element(nodes.begin(), middle, nodes.end(), [&](int a, int b) {
      const double pa = points_(axis, a), pb = points_(axis, b);
      return pa < pb || (pa == pb && a < b);  // a total order: the same cut on every machine
    });
    // Nodes level with the median stay together (a row of a structured grid is not split), unless
    // that leaves one side empty.
    const double median = points_(axis, *middle);
    const auto level =
        std::partition(nodes.begin(), middle, [&](int k) { return points_(axis, k) < median; });
    if (level != nodes.begin()) middle = level;
    // Each cut marks its two halves with stamps of its own; a node's mark from an earlier cut
    // can never equal them.
    const int stamp = 2 * calls_++;
    for (auto it = nodes.begin(); it != nodes.end(); ++it)
      mark_[*it] = stamp + (it < middle ? 0 : 1);
    Cut cut{{nodes.begin(), middle}, {middle, nodes.end()}, {}};
    cut.separator =
        crossing_cover(border(cut.first, stamp + 1), border(cut.second, stamp), stamp + 1);
    for (const int k : cut.separator) mark_[k] = -1;
    std::erase_if(cut.first, [&](int k) { return mark_[k] != stamp; });
    std::erase_if(cut.second, [&](int k) { return mark_[k] != stamp + 1; });
    return cut;
  }

  int longer_axis(const std::vector<int>& nodes) const {
    Eigen::Vector2d low = points_.col(nodes[0]), high = low;
    for (const int k : nodes) {
      low = low.cwiseMin(points_.col(k));
      high = high.cwiseMax(points_.col(k));
    }
    return high.x() - low.x() >= high.y() - low.y() ? 0 : 1;
  }

  /// The nodes of `part` with a neighbour marked `other`.
  std::vector<int> border(const std::vector<int>& part, int other) const {
    std::vector<int> found;
    for (const int k : part)
      for (int q = graph_.col_start[k]; q < graph_.col_start[k + 1]; ++q)
        if (mark_[graph_.rows[q]] == other) {
          found.push_back(k);
          break;
        }
    return found;
  }

  /// A smallest set of nodes that touches every edge between the two borders (left's nodes are
  /// adjacent to right's, marked `right_mark`): a minimum vertex cover of that bipartite graph,
  /// from a maximum matching by Koenig's theorem. It is never larger than the smaller border,
  /// and on polygons, whose nodes are coupled to every node of their cells, often much smaller.
  std::vector<int> crossing_cover(const std::vector<int>& left, const std::vector<int>& right,
                                  int right_mark) {
    for (int i = 0; i < static_cast<int>(left.size()); ++i) local_[left[i]] = i;
    for (int j = 0; j < static_cast<int>(right.size()); ++j) local_[right[j]] = j;
    std::vector<std::vector<int>> across(left.size());
    for (int i = 0; i < static_cast<int>(left.size()); ++i)
      for (int q = graph_.col_start[left[i]]; q < graph_.col_start[left[i] + 1]; ++q)
        if (const int u = graph_.rows[q]; mark_[u] == right_mark) across[i].push_back(local_[u]);
    std::vector<int> match_left(left.size(), -1), match_right(right.size(), -1);
    std::vector<int> seen(right.size(), -1);
    for (int i = 0; i < static_cast<int>(left.size()); ++i)
      augment(i, i, across, match_left, match_right, seen);
    // Koenig: from the unmatched left nodes, alternate free edges right and matched edges back.
    std::vector<char> reached_left(left.size(), 0), reached_right(right.size(), 0);
    std::vector<int> queue;
    for (int i = 0; i < static_cast<int>(left.size()); ++i)
      if (match_left[i] < 0) reached_left[i] = 1, queue.push_back(i);
    for (size_t head = 0; head < queue.size(); ++head)
      for (const int j : across[queue[head]])
        if (!reached_right[j]) {
          reached_right[j] = 1;
          if (const int i = match_right[j]; i >= 0 && !reached_left[i])
            reached_left[i] = 1, queue.push_back(i);
        }
    std::vector<int> cover;
    for (int i = 0; i < static_cast<int>(left.size()); ++i)
      if (!reached_left[i]) cover.push_back(left[i]);
    for (int j = 0; j < static_cast<int>(right.size()); ++j)
      if (reached_right[j]) cover.push_back(right[j]);
    return cover;
  }

  /// Kuhn's augmenting path from left node i (depth-first; `seen` stamped with the search).
  static bool augment(int i, int search, const std::vector<std::vector<int>>& across,
                      std::vector<int>& match_left, std::vector<int>& match_right,
                      std::vector<int>& seen) {
    for (const int j : across[i]) {
      if (seen[j] == search) continue;
      seen[j] = search;
      if (match_right[j] < 0 ||
          augment(match_right[j], search, across, match_left, match_right, seen)) {
        match_left[i] = j;
        match_right[j] = i;
        return true;
      }
    }
    return false;
  }

  const Adjacency& graph_;
  const Eigen::Matrix2Xd& points_;
  const int leaf_size_;
  std::vector<int> mark_, local_, order_;
  int calls_ = 0;
};

}  // namespace

std::vector<int> geometric_dissection(const Adjacency& graph, const Eigen::Matrix2Xd& points,
                                      int leaf_size) {
  const long n = static_cast<long>(graph.col_start.size()) - 1;
  if (n != points.cols())
    throw InputError("geometric dissection: " + std::to_string(points.cols()) +
                     " points for a graph of " + std::to_string(n) + " nodes");
  if (!points.allFinite()) throw InputError("geometric dissection: a node's point is not finite");
  if (n == 0) return {};
  return Dissection(graph, points, leaf_size).run();
}

}  // namespace vorodg
