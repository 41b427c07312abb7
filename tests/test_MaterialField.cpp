// A random material field sampled onto meshes (core/random/MaterialField through
// dynamics/MaterialVariation::from_field; docs/statistics.md), fixed seeds, squared-exponential
// correlation with l = 0.1 on the unit square, uniform +-5 % unless said:
//   - the same realization gives the same factors to the bit; another realization, or the
//     stiffness against the strength, others; the mesh's own seed does not enter;
//   - every factor lies in [1 - a, 1 + a] (a mean of values that do);
//   - nested quads: a coarse cell's factor is the mean of its four children's, to the quadrature
//     error (1e-3 of a);
//   - rcp at h and h/2 (independent meshes): a fine cell's factor differs from the coarse cell's
//     that holds its centroid by less, on average, than the factor varies within a coarse cell;
//   - weibull: the stiffness is uniform, the strength has mean 1 over many cells.
#include <gtest/gtest.h>

#include <cmath>

#include "core/meshgen/MeshFamily.hpp"
#include "core/random/CirculantEmbedding.hpp"
#include "core/random/GaussianRandomField.hpp"
#include "core/random/MaterialVariation.hpp"

namespace vorodg {
namespace {

const Rectangle kSquare(0, 0, 1, 1);

PolygonMesh mesh_of(MeshFamily family, double h, std::uint64_t seed = 5) {
  MeshSpec spec;
  spec.family = family;
  spec.domain = kSquare;
  spec.size = h;
  spec.seed = seed;
  return generate_mesh(spec).mesh;
}

MaterialField field(MarginalKind marginal = MarginalKind::uniform) {
  MaterialField f;
  f.enabled = true;
  f.covariance.kind = CovarianceKind::squared_exponential;
  f.covariance.length = 0.1;
  f.marginal.kind = marginal;
  f.seed = 11;
  return f;
}

/// The cell of `mesh` whose polygon holds x (by the crossing number: cells need not be convex).
int cell_holding(const PolygonMesh& mesh, const Point& x) {
  for (int c = 0; c < mesh.num_cells(); ++c) {
    const std::vector<Point> p = mesh.cell_points(c);
    bool inside = false;
    for (std::size_t k = 0, j = p.size() - 1; k < p.size(); j = k++)
      if ((p[k].y() > x.y()) != (p[j].y() > x.y()) &&
          x.x() < (p[j].x() - p[k].x()) * (x.y() - p[k].y()) / (p[j].y() - p[k].y()) + p[k].x())
        inside = !inside;
    if (inside) return c;
  }
  return -1;
}

TEST(MaterialField, ARealizationIsTheSameMaterialWhateverTheMeshSeed) {
  const PolygonMesh mesh = mesh_of(MeshFamily::quad, 0.05);
  const MaterialVariation a = MaterialVariation::from_field(mesh, field(), 3);
  const MaterialVariation b = MaterialVariation::from_field(mesh, field(), 3);
  const MaterialVariation c = MaterialVariation::from_field(mesh, field(), 4);
  ASSERT_EQ(a.stiffness.size(), static_cast<std::size_t>(mesh.num_cells()));
  EXPECT_EQ(a.stiffness, b.stiffness);
  EXPECT_EQ(a.strength, b.strength);
  EXPECT_NE(a.stiffness, c.stiffness);
  EXPECT_NE(a.stiffness, a.strength);  // two independent fields
  for (const auto* v : {&a.stiffness, &a.strength})
    for (double f : *v) {
      EXPECT_GE(f, 0.95);
      EXPECT_LE(f, 1.05);
    }
  EXPECT_TRUE(MaterialVariation::from_field(mesh, MaterialField{}, 3).empty());
}

TEST(MaterialField, ACoarseCellIsTheMeanOfItsChildren) {
  const PolygonMesh coarse = mesh_of(MeshFamily::quad, 0.1), fine = mesh_of(MeshFamily::quad, 0.05);
  const MaterialVariation vc = MaterialVariation::from_field(coarse, field(), 0);
  const MaterialVariation vf = MaterialVariation::from_field(fine, field(), 0);
  std::vector<double> sum(coarse.num_cells(), 0.0);
  std::vector<int> children(coarse.num_cells(), 0);
  for (int c = 0; c < fine.num_cells(); ++c) {
    const int parent = cell_holding(coarse, fine.cell_centroid(c));
    ASSERT_GE(parent, 0);
    sum[parent] += vf.stiffness[c];
    ++children[parent];
  }
  double worst = 0.0;
  for (int p = 0; p < coarse.num_cells(); ++p) {
    ASSERT_EQ(children[p], 4);
    worst = std::max(worst, std::abs(vc.stiffness[p] - sum[p] / 4.0));
  }
  EXPECT_LT(worst, 1e-3 * 0.05) << "coarse factor against its children's mean";
}

TEST(MaterialField, OneSeedOnTwoRcpLevelsDiffersByLessThanTheFieldWithinACell) {
  const PolygonMesh coarse = mesh_of(MeshFamily::rcp, 0.05, 1);
  const PolygonMesh fine = mesh_of(MeshFamily::rcp, 0.025, 2);  // its own mesh seed
  const MaterialField f = field();
  const MaterialVariation vc = MaterialVariation::from_field(coarse, f, 7);
  const MaterialVariation vf = MaterialVariation::from_field(fine, f, 7);
  // The factor's variation within each coarse cell: its range over the vertices and centroid.
  const CirculantEmbedding embedding(kSquare, f.covariance, f.spacing);
  const GaussianRandomField g(embedding, f.field_seed(7, 0));
  double within = 0.0;
  for (int c = 0; c < coarse.num_cells(); ++c) {
    std::vector<Point> points = coarse.cell_points(c);
    points.push_back(coarse.cell_centroid(c));
    double lo = 2.0, hi = 0.0;
    for (const Point& x : points) {
      const double factor = f.marginal(g.value(x));
      lo = std::min(lo, factor), hi = std::max(hi, factor);
    }
    within += (hi - lo) / coarse.num_cells();
  }
  double apart = 0.0, unrelated = 0.0;
  const MaterialVariation other = MaterialVariation::from_field(coarse, f, 8);
  for (int c = 0; c < fine.num_cells(); ++c) {
    const int parent = cell_holding(coarse, fine.cell_centroid(c));
    ASSERT_GE(parent, 0);
    apart += std::abs(vf.stiffness[c] - vc.stiffness[parent]) / fine.num_cells();
    unrelated += std::abs(vf.stiffness[c] - other.stiffness[parent]) / fine.num_cells();
  }
  EXPECT_LT(apart, within);
  EXPECT_LT(apart, 0.2 * unrelated);  // another realization is far further away
}

TEST(MaterialField, WeibullVariesTheStrengthAlone) {
  const PolygonMesh mesh = mesh_of(MeshFamily::quad, 0.02);
  const MaterialVariation v = MaterialVariation::from_field(mesh, field(MarginalKind::weibull), 1);
  double mean = 0.0;
  for (int c = 0; c < mesh.num_cells(); ++c) {
    EXPECT_EQ(v.stiffness[c], 1.0);
    mean += v.strength[c] / mesh.num_cells();
  }
  // Mean 1 at a point; over the unit square with l = 0.1 the spatial mean of one realization
  // scatters by about the spread (0.1 for k = 12) times l sqrt(2 pi) = 0.25: within 0.1.
  EXPECT_NEAR(mean, 1.0, 0.1);
}

}  // namespace
}  // namespace vorodg
