#pragma once
// Sums over many items, in parallel, with the same bits for any thread count. The items are cut
// into chunks of a fixed size (independent of the threads); each chunk is summed in item order
// by whichever thread takes it, into the chunk's own slot, and the chunk sums are then added in
// chunk order. An OpenMP reduction would add in an order that depends on the thread count.
#include <algorithm>
#include <array>
#include <vector>

namespace vorodg {

class OrderedSum {
 public:
  static constexpr int kChunk = 1024;

  /// Sums K quantities over items [0, n): term(i, acc) adds item i's contributions to acc[0..K).
  /// The term may also update per-item state (each item is visited exactly once).
  template <int K, class Term>
  std::array<double, K> sum(int n, int threads, Term&& term) {
    const int chunks = (n + kChunk - 1) / kChunk;
    partial_.assign(static_cast<std::size_t>(chunks) * K, 0.0);  // no reallocation once grown
#pragma omp parallel for schedule(static) num_threads(std::max(threads, 1))
    for (int b = 0; b < chunks; ++b) {
      // A local accumulator: no store the term makes (to its own double arrays) can alias it, so
      // it stays in registers; one into partial_ had to be reloaded after every such store.
      std::array<double, K> acc{};
      const int end = std::min(n, (b + 1) * kChunk);
      for (int i = b * kChunk; i < end; ++i) term(i, acc.data());
      std::copy(acc.begin(), acc.end(), partial_.begin() + static_cast<std::ptrdiff_t>(b) * K);
    }
    std::array<double, K> total{};
    for (int b = 0; b < chunks; ++b)
      for (int k = 0; k < K; ++k) total[k] += partial_[static_cast<std::size_t>(b) * K + k];
    return total;
  }

 private:
  std::vector<double> partial_;
};

}  // namespace vorodg
