#pragma once
// Circulant embedding (Dietrich and Newsam 1997): what a stationary Gaussian field with mean 0,
// variance 1 and correlation `covariance` needs to be drawn exactly at the nodes of a regular
// grid of spacing `spacing` over a rectangle, computed once and shared by every realization.
//
// The grid's covariance matrix is block Toeplitz; it is embedded in a block-circulant one on a
// periodic grid of m1 x m2 nodes, whose eigenvalues are the 2D DFT of its first row (FFTW). When
// they are all >= 0, F(sqrt(Lambda / M) xi) with xi complex standard normal, F the DFT and
// M = m1 m2, has exactly the wanted covariance at the grid's nodes (its real part is used; the
// imaginary part would be a second, independent field). The periodic grid starts at twice the
// grid (and at least 4 l per axis, for a domain thinner than the correlation) and is doubled until
// the smallest eigenvalue is no lower than -1e-10 of the largest; for a smooth covariance (the
// squared exponential) the slightly negative eigenvalues left are round-off of a matrix whose
// condition is huge, and are set to zero; `clipped()` says what share of the trace that was (it is
// the relative error of the variance).
//
// Normal deviates: a 64-bit Mersenne twister seeded with the realization's seed, 53-bit
// uniforms, Box-Muller. All three are fixed by their definitions, so a seed gives the same field
// with any standard library; FFTW plans without timing (FFTW_ESTIMATE), so the same sizes take the
// same algorithm and give the same bits.
#include <cstdint>
#include <memory>
#include <vector>

#include "core/geometry/Rectangle.hpp"
#include "core/random/FieldCovariance.hpp"

struct fftw_plan_s;  // FFTW's plan; fftw3.h stays in the .cpp

namespace vorodg {

class CirculantEmbedding {
 public:
  /// `spacing` <= 0 takes l / 8. Throws InputError for a bad covariance or domain, a grid of more
  /// than 1e8 cells, or when no embedding up to 8 times the smallest (twice the grid, and at
  /// least 4 l per axis) is non-negative to the
  /// tolerance.
  CirculantEmbedding(const Rectangle& domain, const FieldCovariance& covariance,
                     double spacing = 0.0);

  /// One realization's values at the grid's nodes, nodes_x() x nodes_y(), row-major (y fastest).
  std::vector<double> sample(std::uint64_t seed) const;

  const Rectangle& domain() const { return domain_; }
  const FieldCovariance& covariance() const { return covariance_; }
  double spacing() const { return spacing_; }
  int nodes_x() const { return nx_; }
  int nodes_y() const { return ny_; }
  /// The periodic grid's size.
  int embedding_x() const { return mx_; }
  int embedding_y() const { return my_; }
  /// The share of the embedding's trace in negative eigenvalues set to zero (0 when none).
  double clipped() const { return clipped_; }

 private:
  /// The eigenvalues of an m1 x m2 periodic embedding (row-major, m2 fastest).
  std::vector<double> eigenvalues(int m1, int m2) const;
  /// A forward 2D DFT plan for m1 x m2 in-place transforms of any alignment.
  static std::shared_ptr<fftw_plan_s> plan(int m1, int m2);

  Rectangle domain_;
  FieldCovariance covariance_;
  double spacing_ = 0.0;
  int nx_ = 0, ny_ = 0, mx_ = 0, my_ = 0;
  double clipped_ = 0.0;
  std::vector<double> amplitude_;      // sqrt(lambda / M) per mode
  std::shared_ptr<fftw_plan_s> plan_;  // the m1 x m2 transform, shared by the copies
};

}  // namespace vorodg
