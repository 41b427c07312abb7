// Fragments (fracture/Fragments) with lumped masses (dynamics/LumpedMass), rho = 7800:
//   - a quad strip [0,4] x [0,1] (h = 0.25) with every edge of k vertical cross-sections cracked
//     falls into k + 1 fragments whose masses are the column areas x rho, to 1e-12 relative,
//     with lumped masses and with density x area;
//   - the total mass is LumpedMass::total() bit for bit, one fragment's mass too, and the sum
//     of the fragments' masses agrees to 1e-14 relative (the figure is printed);
//   - lumped centres of mass are the geometric centroids to 1e-12 (first moments are exact);
//   - a rigid translation gives every fragment that velocity, and v = r (x - x_mid) gives
//     r (x_c - x_mid) at the fragment centroids, both to 1e-12, on the quad strip and on an rcp
//     mesh (seed 17), for the continuous, the cracked and the fully split DOF maps;
//   - the sorted mass fractions, the largest one and their empirical CDF on unequal columns.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <memory>
#include <vector>

#include "core/element/ElementTable.hpp"
#include "core/meshgen/MeshFamily.hpp"
#include "core/util/Errors.hpp"
#include "dynamics/LumpedMass.hpp"
#include "fracture/Fragments.hpp"

namespace vorodg {
namespace {

constexpr double kDensity = 7800.0;

struct Body {
  PolygonMesh mesh;
  std::unique_ptr<ElementTable> table;
  std::unique_ptr<LumpedMass> mass;
};

std::unique_ptr<Body> make_body(MeshFamily family, const Rectangle& domain, double size) {
  MeshSpec spec;
  spec.family = family;
  spec.domain = domain;
  spec.size = size;
  spec.seed = 17;
  auto body = std::make_unique<Body>();
  body->mesh = generate_mesh(spec).mesh;
  body->table = std::make_unique<ElementTable>(body->mesh, ElementOptions{});
  body->mass = std::make_unique<LumpedMass>(*body->table, kDensity);
  return body;
}

const Body& strip() {
  static const auto body = make_body(MeshFamily::quad, Rectangle(0.0, 0.0, 4.0, 1.0), 0.25);
  return *body;
}

const Body& rcp() {
  static const auto body = make_body(MeshFamily::rcp, Rectangle(0.0, 0.0, 2.0, 1.0), 0.1);
  return *body;
}

/// Every interior edge of the quad strip lying on one of the lines x = xs[i].
std::vector<char> cross_sections(const PolygonMesh& mesh, const std::vector<double>& xs) {
  std::vector<char> cut(mesh.num_edges(), 0);
  for (int e = 0; e < mesh.num_edges(); ++e) {
    const MeshEdge& edge = mesh.edge(e);
    if (edge.on_boundary()) continue;
    for (double x : xs)
      if (std::abs(mesh.vertex(edge.v0).x() - x) < 1e-12 &&
          std::abs(mesh.vertex(edge.v1).x() - x) < 1e-12)
        cut[e] = 1;
  }
  return cut;
}

/// Interior edges whose cells' centroids lie on either side of one of the lines x = xs[i].
std::vector<char> centroid_cuts(const PolygonMesh& mesh, const std::vector<double>& xs) {
  std::vector<char> cut(mesh.num_edges(), 0);
  for (int e = 0; e < mesh.num_edges(); ++e) {
    const MeshEdge& edge = mesh.edge(e);
    if (edge.on_boundary()) continue;
    for (double x : xs)
      if ((mesh.cell_centroid(edge.cell0).x() < x) != (mesh.cell_centroid(edge.cell1).x() < x))
        cut[e] = 1;
  }
  return cut;
}

std::vector<char> negated(const std::vector<char>& flags) {
  std::vector<char> out(flags.size());
  for (std::size_t e = 0; e < flags.size(); ++e) out[e] = !flags[e];
  return out;
}

/// Node velocities sampling v(X) at each node's vertex.
template <class Field>
Eigen::VectorXd sample(const PolygonMesh& mesh, const SplitDofMap& dofs, Field v) {
  Eigen::VectorXd out(dofs.num_dofs());
  for (int c = 0; c < mesh.num_cells(); ++c) {
    const auto loop = mesh.cell_vertices(c);
    for (std::size_t k = 0; k < loop.size(); ++k)
      out.segment<2>(2 * dofs.node(c, int(k))) = v(mesh.vertex(loop[k]));
  }
  return out;
}

/// Geometric centroid of each fragment: area-weighted cell centroids.
Eigen::Matrix2Xd centroids(const PolygonMesh& mesh, const Fragments& f) {
  Eigen::Matrix2Xd first = Eigen::Matrix2Xd::Zero(2, f.num_fragments());
  Eigen::VectorXd area = Eigen::VectorXd::Zero(f.num_fragments());
  for (int c = 0; c < mesh.num_cells(); ++c) {
    first.col(f.fragment(c)) += mesh.cell_area(c) * mesh.cell_centroid(c);
    area[f.fragment(c)] += mesh.cell_area(c);
  }
  for (int i = 0; i < f.num_fragments(); ++i) first.col(i) /= area[i];
  return first;
}

TEST(Fragments, CrossSectionsMakeColumns) {
  const Body& b = strip();
  for (int k : {0, 1, 3, 7}) {  // cuts on the grid lines of the 16 columns
    std::vector<double> xs;
    for (int i = 1; i <= k; ++i) xs.push_back(4.0 * i / (k + 1));
    const CrackState cracks(b.mesh, cross_sections(b.mesh, xs));
    const double column = kDensity * 4.0 / (k + 1);
    for (const Fragments& f :
         {Fragments(cracks, b.mass->pair_masses()), Fragments(cracks, kDensity)}) {
      ASSERT_EQ(f.num_fragments(), k + 1);
      for (int i = 0; i < f.num_fragments(); ++i) {
        EXPECT_NEAR(f.mass(i), column, 1e-12 * column) << "k " << k << " fragment " << i;
        EXPECT_EQ(f.num_cells(i), b.mesh.num_cells() / (k + 1));
        EXPECT_NEAR(f.centres()(0, i), 4.0 * (i + 0.5) / (k + 1), 1e-12);
        EXPECT_NEAR(f.centres()(1, i), 0.5, 1e-12);
      }
    }
  }
}

TEST(Fragments, TotalMassIsConserved) {
  for (const Body* b : {&strip(), &rcp()}) {
    const Fragments one(CrackState(b->mesh, std::vector<char>(b->mesh.num_edges(), 0)),
                        b->mass->pair_masses());
    ASSERT_EQ(one.num_fragments(), 1);
    EXPECT_EQ(one.total_mass(), b->mass->total());
    EXPECT_EQ(one.mass(0), b->mass->total());
    for (const auto& cut :
         {centroid_cuts(b->mesh, {0.5, 1.0, 1.5}), std::vector<char>(b->mesh.num_edges(), 1)}) {
      const Fragments f(CrackState(b->mesh, cut), b->mass->pair_masses());
      EXPECT_EQ(f.total_mass(), b->mass->total());
      const double error = std::abs(f.masses().sum() - f.total_mass()) / f.total_mass();
      std::printf("%5d fragments of %5d cells: |sum of masses - total| / total = %.2e\n",
                  f.num_fragments(), b->mesh.num_cells(), error);
      EXPECT_LT(error, 1e-14);
    }
  }
}

TEST(Fragments, LumpedCentresAreCentroids) {
  for (const Body* b : {&strip(), &rcp()}) {
    const CrackState cracks(b->mesh, centroid_cuts(b->mesh, {0.7, 1.4}));
    const Fragments lumped(cracks, b->mass->pair_masses()), areas(cracks, kDensity);
    ASSERT_EQ(lumped.num_fragments(), 3);
    const Eigen::Matrix2Xd exact = centroids(b->mesh, lumped);
    const double error = (lumped.centres() - exact).cwiseAbs().maxCoeff();
    std::printf("%5d cells: lumped centre - centroid = %.2e\n", b->mesh.num_cells(), error);
    EXPECT_LT(error, 1e-12);
    EXPECT_LT((areas.centres() - exact).cwiseAbs().maxCoeff(), 1e-12);
    for (int i = 0; i < 3; ++i) EXPECT_NEAR(lumped.mass(i), areas.mass(i), 1e-12 * areas.mass(i));
  }
}

TEST(Fragments, RigidAndLinearVelocities) {
  const Eigen::Vector2d rigid(0.3, -0.7);
  const double r = 2.5;
  for (const Body* b : {&strip(), &rcp()}) {
    const PolygonMesh& mesh = b->mesh;
    const Point mid = 0.5 * (mesh.domain().lo() + mesh.domain().hi());
    const std::vector<char> cut = centroid_cuts(mesh, {0.7, 1.4});
    const Fragments f(CrackState(mesh, cut), b->mass->pair_masses());
    const Eigen::Matrix2Xd exact = centroids(mesh, f);
    for (const SplitDofMap& dofs : {SplitDofMap::continuous(mesh), SplitDofMap(mesh, negated(cut)),
                                    SplitDofMap::discontinuous(mesh)}) {
      const Eigen::Matrix2Xd vr =
          f.velocities(dofs, sample(mesh, dofs, [&](const Point&) { return rigid; }));
      const Eigen::Matrix2Xd vl = f.velocities(
          dofs,
          sample(mesh, dofs, [&](const Point& x) -> Eigen::Vector2d { return r * (x - mid); }));
      double rigid_error = 0.0, linear_error = 0.0;
      for (int i = 0; i < f.num_fragments(); ++i) {
        rigid_error = std::max(rigid_error, (vr.col(i) - rigid).cwiseAbs().maxCoeff());
        linear_error =
            std::max(linear_error, (vl.col(i) - r * (exact.col(i) - mid)).cwiseAbs().maxCoeff());
      }
      std::printf("%5d cells, %5d nodes: rigid %.2e, linear %.2e\n", mesh.num_cells(),
                  dofs.num_nodes(), rigid_error, linear_error);
      EXPECT_LT(rigid_error, 1e-12);
      EXPECT_LT(linear_error, 1e-12);
    }
  }
}

TEST(Fragments, MassFractionsAndTheirCdf) {
  const Body& b = strip();
  const Fragments f(CrackState(b.mesh, cross_sections(b.mesh, {1.0, 1.5, 3.0})),
                    b.mass->pair_masses());
  ASSERT_EQ(f.num_fragments(), 4);
  const Eigen::Vector4d expected(0.125, 0.25, 0.25, 0.375);
  const Eigen::VectorXd sorted = f.sorted_mass_fractions();
  ASSERT_EQ(sorted.size(), 4);
  EXPECT_LT((sorted - expected).cwiseAbs().maxCoeff(), 1e-14);
  EXPECT_NEAR(f.largest_mass_fraction(), 0.375, 1e-14);
  const Fragments::Cdf cdf = f.mass_fraction_cdf();
  EXPECT_EQ(cdf.fractions, sorted);
  EXPECT_EQ(cdf.cumulative, Eigen::Vector4d(0.25, 0.5, 0.75, 1.0));
}

TEST(Fragments, RefusesBadInput) {
  const Body& b = strip();
  const CrackState none(b.mesh, std::vector<char>(b.mesh.num_edges(), 0));
  const SplitDofMap dofs = SplitDofMap::continuous(b.mesh);
  EXPECT_THROW(Fragments(none, 0.0), InputError);
  EXPECT_THROW(Fragments(none, kDensity).velocities(dofs, Eigen::VectorXd::Zero(dofs.num_dofs())),
               InputError);
  EXPECT_THROW(Fragments(none, b.mass->pair_masses()).velocities(dofs, Eigen::VectorXd::Zero(3)),
               InputError);
  EXPECT_THROW(Fragments(CrackState(rcp().mesh, std::vector<char>(rcp().mesh.num_edges(), 0)),
                         b.mass->pair_masses()),
               InputError);
}

}  // namespace
}  // namespace vorodg
