#include "core/random/CirculantEmbedding.hpp"

#include <fftw3.h>

#include <algorithm>
#include <cmath>
#include <complex>
#include <memory>
#include <mutex>
#include <numbers>
#include <random>
#include <string>

#include "core/util/Errors.hpp"

namespace vorodg {
namespace {

/// The smallest m >= n whose only prime factors are 2, 3, 5 and 7 (FFTW's fast sizes).
int fast_size(int n) {
  for (int m = std::max(n, 1);; ++m) {
    int r = m;
    for (int p : {2, 3, 5, 7})
      while (r % p == 0) r /= p;
    if (r == 1) return m;
  }
}

std::mutex& planner() {
  static std::mutex m;
  return m;
}

}  // namespace

/// An in-place forward 2D DFT of m1 x m2 complex values (row-major), for arrays of any
/// alignment, planned once and executed by every realization (FFTW's execution is thread-safe,
/// its planner is not, so planning and destruction are serialized). FFTW_ESTIMATE plans without
/// timing, so the same sizes always get the same algorithm and the same bits.
std::shared_ptr<fftw_plan_s> CirculantEmbedding::plan(int m1, int m2) {
  std::vector<std::complex<double>> scratch(static_cast<std::size_t>(m1) * m2);
  auto* x = reinterpret_cast<fftw_complex*>(scratch.data());
  fftw_plan p = nullptr;
  {
    const std::lock_guard<std::mutex> lock(planner());
    p = fftw_plan_dft_2d(m1, m2, x, x, FFTW_FORWARD, FFTW_ESTIMATE | FFTW_UNALIGNED);
  }
  if (!p)
    throw InputError("random field: FFTW could not plan a " + std::to_string(m1) + " x " +
                     std::to_string(m2) + " transform");
  return {p, [](fftw_plan q) {
            const std::lock_guard<std::mutex> lock(planner());
            fftw_destroy_plan(q);
          }};
}

namespace {

void execute(fftw_plan_s* p, std::vector<std::complex<double>>& data) {
  auto* x = reinterpret_cast<fftw_complex*>(data.data());
  fftw_execute_dft(p, x, x);
}

/// Standard normal pairs: 53-bit uniforms of a 64-bit Mersenne twister, Box-Muller.
class NormalPairs {
 public:
  explicit NormalPairs(std::uint64_t seed) : engine_(seed) {}
  std::complex<double> next() {
    constexpr double kUnit = 1.0 / 9007199254740992.0;                       // 2^-53
    const double u1 = (static_cast<double>(engine_() >> 11) + 1.0) * kUnit;  // (0, 1]
    const double u2 = static_cast<double>(engine_() >> 11) * kUnit;          // [0, 1)
    const double radius = std::sqrt(-2.0 * std::log(u1));
    const double angle = 2.0 * std::numbers::pi * u2;
    return {radius * std::cos(angle), radius * std::sin(angle)};
  }

 private:
  std::mt19937_64 engine_;
};

}  // namespace

CirculantEmbedding::CirculantEmbedding(const Rectangle& domain, const FieldCovariance& covariance,
                                       double spacing)
    : domain_(domain), covariance_(covariance) {
  covariance_.check();
  if (!(domain.width() > 0.0 && domain.height() > 0.0))
    throw InputError("random field: the domain " + std::to_string(domain.width()) + " x " +
                     std::to_string(domain.height()) + ": expected a positive width and height");
  spacing_ = spacing > 0.0 ? spacing : covariance_.length / 8.0;
  const double cells_x = std::ceil(domain.width() / spacing_ - 1e-9);
  const double cells_y = std::ceil(domain.height() / spacing_ - 1e-9);
  if (cells_x * cells_y > 1e8)
    throw InputError("random field: a grid of spacing " + std::to_string(spacing_) +
                     " over the domain has " + std::to_string(cells_x * cells_y) +
                     " cells: expected at most 1e8 (a longer correlation or a coarser spacing)");
  nx_ = static_cast<int>(cells_x) + 1;
  ny_ = static_cast<int>(cells_y) + 1;
  // The smallest periodic grid: twice the grid, and at least 4 l along each axis, so that a
  // domain thinner than the correlation (a strip one cell high) still embeds.
  const int reach = static_cast<int>(std::ceil(4.0 * covariance_.length / spacing_));
  const int first_x = std::max(2 * (nx_ - 1), reach), first_y = std::max(2 * (ny_ - 1), reach);
  for (int factor = 1; factor <= 8; factor *= 2) {
    const int m1 = fast_size(first_x * factor), m2 = fast_size(first_y * factor);
    std::vector<double> lambda = eigenvalues(m1, m2);
    const auto [low, high] = std::minmax_element(lambda.begin(), lambda.end());
    if (*low < -1e-10 * *high) continue;
    mx_ = m1, my_ = m2;
    plan_ = plan(m1, m2);
    double negative = 0.0, trace = 0.0;
    for (double& l : lambda) {
      trace += std::abs(l);
      if (l < 0.0) negative -= l, l = 0.0;
    }
    clipped_ = negative / trace;
    amplitude_.resize(lambda.size());
    const double size = static_cast<double>(lambda.size());
    for (std::size_t k = 0; k < lambda.size(); ++k) amplitude_[k] = std::sqrt(lambda[k] / size);
    return;
  }
  throw InputError(
      "random field: no periodic embedding up to 8 times the smallest (twice the grid, at "
      "least 4 l) is non-negative definite (correlation length " +
      std::to_string(covariance_.length) + ", spacing " + std::to_string(spacing_) +
      "): expected a shorter correlation length against the domain");
}

std::vector<double> CirculantEmbedding::eigenvalues(int m1, int m2) const {
  // The first row of the block-circulant matrix: the correlation at the periodic distance.
  std::vector<std::complex<double>> row(static_cast<std::size_t>(m1) * m2);
  for (int i = 0; i < m1; ++i)
    for (int j = 0; j < m2; ++j) {
      const double dx = spacing_ * std::min(i, m1 - i), dy = spacing_ * std::min(j, m2 - j);
      row[static_cast<std::size_t>(i) * m2 + j] = covariance_(std::hypot(dx, dy));
    }
  execute(plan(m1, m2).get(), row);
  std::vector<double> eigenvalues(row.size());
  for (std::size_t k = 0; k < row.size(); ++k) eigenvalues[k] = row[k].real();  // real: even row
  return eigenvalues;
}

std::vector<double> CirculantEmbedding::sample(std::uint64_t seed) const {
  NormalPairs normals(seed);
  std::vector<std::complex<double>> modes(amplitude_.size());
  for (std::size_t k = 0; k < modes.size(); ++k) modes[k] = amplitude_[k] * normals.next();
  execute(plan_.get(), modes);
  std::vector<double> values(static_cast<std::size_t>(nx_) * ny_);
  for (int i = 0; i < nx_; ++i)
    for (int j = 0; j < ny_; ++j)
      values[static_cast<std::size_t>(i) * ny_ + j] =
          modes[static_cast<std::size_t>(i) * my_ + j].real();
  return values;
}

}  // namespace vorodg
