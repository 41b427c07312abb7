#pragma once
// A stationary Gaussian random field with mean 0, variance 1 and a given correlation
// (FieldCovariance), defined in space rather than on a mesh: the same seed gives the same field
// whatever mesh it is later sampled onto, so the levels of a refinement study share their
// material and can be compared realization by realization.
//
// The field is drawn exactly at the nodes of a regular grid over the domain (CirculantEmbedding,
// computed once per domain and covariance and shared by the realizations); between the nodes it
// is their bilinear interpolant. The interpolant's variance dips between the nodes: at a grid
// cell's centre it is (4 + 8 rho(s) + 4 rho(sqrt 2 s)) / 16 of the field's, 0.992 for the squared
// exponential and 0.980 for Matern 3/2 at the default spacing s = l / 8.
#include <cstdint>
#include <functional>
#include <span>
#include <vector>

#include "core/geometry/Rectangle.hpp"
#include "core/random/CirculantEmbedding.hpp"
#include "core/random/FieldCovariance.hpp"

namespace vorodg {

class GaussianRandomField {
 public:
  /// Realization `seed` of the embedding's field.
  GaussianRandomField(const CirculantEmbedding& embedding, std::uint64_t seed);
  /// The same, with an embedding of its own (CirculantEmbedding's arguments and errors).
  GaussianRandomField(const Rectangle& domain, const FieldCovariance& covariance,
                      std::uint64_t seed, double spacing = 0.0);

  /// The field at x (bilinear between the grid's nodes). Throws InputError outside the domain
  /// (by more than round-off of its size).
  double value(const Point& x) const;
  /// The field's mean over a polygon (counter-clockwise vertices): the triangles of a fan from
  /// its vertex mean, split by their edges' midpoints until no piece is wider than two grid
  /// spacings, each piece with the three-point edge-midpoint rule. With `of`, the mean of of(g)
  /// instead (a material factor mapped from the field). Throws InputError for fewer than three
  /// vertices or a zero area.
  double mean_over(std::span<const Point> polygon,
                   const std::function<double(double)>& of = {}) const;

  double spacing() const { return spacing_; }
  int nodes_x() const { return nx_; }
  int nodes_y() const { return ny_; }

 private:
  double node(int i, int j) const { return values_[static_cast<std::size_t>(i) * ny_ + j]; }

  Rectangle domain_;
  double spacing_ = 0.0;
  int nx_ = 0, ny_ = 0;
  std::vector<double> values_;  // nx_ x ny_, row-major (y fastest)
};

}  // namespace vorodg
