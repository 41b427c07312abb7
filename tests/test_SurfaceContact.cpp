// Contact between surface cells, end to end: the search finds exactly the overlapping pairs of
// surface cells that share no vertex; on two rcp bodies pushed into each other the forces sum to
// zero with zero moment; two squares overlapping by d get k d; a vertex found first deeper than
// a tenth of the cell is left alone until it leaves, one that went in step by step is pushed at
// every depth; the list kept from step to step (with its skin) finds exactly the pairs of a
// brute-force search at every step of a moving configuration, while cells join the surface; a node
// of two surface cells is pushed once; exposed edges are the exits; the result is the same on every
// run.
#include "dynamics/contact/SurfaceContact.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <set>
#include <utility>
#include <vector>

#include "core/util/Errors.hpp"
#include "core/util/Random.hpp"
#include "support/ContactScenes.hpp"

namespace vorodg {
namespace {

double cross(const Point& a, const Point& b) {
  return a.x() * b.y() - a.y() * b.x();
}

PenaltyParameters fixed(double k) {
  PenaltyParameters p;
  p.stiffness = k;
  return p;
}

Box box_of(const PolygonMesh& mesh, const std::vector<Point>& x, int c) {
  Box b;
  for (int p = mesh.offsets()[c]; p < mesh.offsets()[c + 1]; ++p) b.extend(x[p]);
  return b;
}

/// Every cell of both bodies takes part, so that overlaps are many and deep.
SurfaceCells all_cells(const PolygonMesh& mesh) {
  SurfaceCells surface(mesh);
  for (int c = 0; c < mesh.num_cells(); ++c) surface.add(c);
  return surface;
}

TEST(SurfaceContact, FindsTheOverlappingPairsThatShareNoVertex) {
  for (std::uint64_t seed : {1u, 2u}) {
    const auto scene = testing::two_bodies(0.05, seed, Point(0.9, 0.5), 0.4, 0.3);
    const PolygonMesh& mesh = scene.mesh;
    SurfaceCells surface(mesh);
    Random random(seed);
    for (int i = 0; i < mesh.num_cells() / 4; ++i) surface.add(int(random.index(mesh.num_cells())));
    SurfaceContact contact(PenaltyContact(fixed(1.0)), mesh.h_avg());
    std::set<std::pair<int, int>> found;
    for (const IndexPair& p : contact.find_pairs(surface, scene.x)) {
      EXPECT_FALSE(surface.neighbours(p.first, p.second));
      EXPECT_TRUE(found.insert(std::minmax(p.first, p.second)).second);
    }
    std::set<std::pair<int, int>> expected;
    const auto cells = surface.cells();
    for (std::size_t i = 0; i < cells.size(); ++i)
      for (std::size_t j = i + 1; j < cells.size(); ++j) {
        bool share = false;
        for (int v : mesh.cell_vertices(cells[i]))
          for (int w : mesh.cell_vertices(cells[j])) share = share || v == w;
        if (!share && box_of(mesh, scene.x, cells[i]).intersects(box_of(mesh, scene.x, cells[j])))
          expected.insert(std::minmax(cells[i], cells[j]));
      }
    EXPECT_EQ(found, expected) << "seed " << seed;
    EXPECT_GT(expected.size(), 100u);
  }
}

/// The brute-force answer: surface cells sharing no vertex whose current boxes overlap.
std::set<std::pair<int, int>> brute_force_pairs(const PolygonMesh& mesh,
                                                const SurfaceCells& surface,
                                                const std::vector<Point>& x) {
  std::set<std::pair<int, int>> expected;
  const auto cells = surface.cells();
  for (std::size_t i = 0; i < cells.size(); ++i)
    for (std::size_t j = i + 1; j < cells.size(); ++j)
      if (!surface.neighbours(cells[i], cells[j]) &&
          box_of(mesh, x, cells[i]).intersects(box_of(mesh, x, cells[j])))
        expected.insert(std::minmax(cells[i], cells[j]));
  return expected;
}

TEST(SurfaceContact, TheKeptListFindsThePairsOfEveryStep) {
  // Every cell drifts rigidly at its own random velocity, 3 % of h_avg a step, over 80 steps;
  // at step 40 a quarter more cells join the surface.
  const auto scene = testing::two_bodies(0.05, 7, Point(0.9, 0.5), 0.4, 0.3);
  const PolygonMesh& mesh = scene.mesh;
  SurfaceCells surface(mesh);
  Random random(7);
  for (int i = 0; i < mesh.num_cells() / 4; ++i) surface.add(int(random.index(mesh.num_cells())));
  std::vector<Point> drift(mesh.num_cells());
  for (Point& d : drift)
    d = 0.03 * mesh.h_avg() * Point(random.uniform(-1, 1), random.uniform(-1, 1)).normalized();
  SurfaceContact contact(PenaltyContact(fixed(1.0)), mesh.h_avg());
  std::vector<Point> x = scene.x;
  const int steps = 80;
  for (int step = 0; step <= steps; ++step) {
    if (step == steps / 2)
      for (int i = 0; i < mesh.num_cells() / 4; ++i)
        surface.add(int(random.index(mesh.num_cells())));
    for (int c = 0; c < mesh.num_cells(); ++c)
      for (int p = mesh.offsets()[c]; p < mesh.offsets()[c + 1]; ++p)
        x[p] = scene.x[p] + double(step) * drift[c];
    std::set<std::pair<int, int>> found;
    for (const IndexPair& p : contact.find_pairs(surface, x))
      found.insert(std::minmax(p.first, p.second));
    ASSERT_EQ(found, brute_force_pairs(mesh, surface, x)) << "step " << step;
  }
  // Cells move apart at up to 6 % of h_avg a step: the 10 % skin lasts a step or two, and the
  // new cells force one more rebuild.
  EXPECT_LT(contact.candidates().rebuilds(), contact.candidates().calls());
  EXPECT_GT(contact.candidates().rebuilds(), 2);
}

TEST(SurfaceContact, ForcesOfTwoBodiesSumToZeroWithZeroMoment) {
  for (std::uint64_t seed : {3u, 4u, 5u}) {
    const auto scene = testing::two_bodies(0.05, seed, Point(0.8, 0.7), 0.2 * double(seed), 0.3);
    const PolygonMesh& mesh = scene.mesh;
    const SurfaceCells surface = all_cells(mesh);
    const SplitDofMap dofs = SplitDofMap::continuous(mesh);
    Random random(seed);
    Eigen::VectorXd mass(dofs.num_nodes()), velocity(dofs.num_dofs());
    for (Eigen::Index i = 0; i < mass.size(); ++i) mass[i] = random.uniform(0.5, 2.0);
    for (Eigen::Index i = 0; i < velocity.size(); ++i) velocity[i] = random.uniform(-1.0, 1.0);
    const auto m = pair_scalars(mesh, dofs, mass);
    const auto v = pair_vectors(mesh, dofs, velocity);
    const auto nodes = pair_nodes(mesh, dofs);
    PenaltyParameters p;
    p.damping_ratio = 0.3;
    SurfaceContact contact{PenaltyContact(p), mesh.h_avg()};
    PairState state{scene.x, v, m, nodes, 1e-3};
    std::vector<Point> f(scene.x.size(), Point::Zero());
    const auto report = contact.add_forces(surface, state, f);
    EXPECT_GT(report.contacts, 100);
    EXPECT_GT(report.dissipation_power, 0.0);
    Point sum = Point::Zero();
    double scale = 0.0, moment = 0.0, moment_scale = 0.0;
    for (std::size_t i = 0; i < f.size(); ++i) {
      sum += f[i];
      scale += f[i].norm();
      moment += cross(scene.x[i], f[i]);
      moment_scale += scene.x[i].norm() * f[i].norm();
    }
    EXPECT_LE(sum.norm(), 1e-12 * scale) << "seed " << seed;
    EXPECT_LE(std::abs(moment), 1e-12 * moment_scale) << "seed " << seed;
  }
}

TEST(SurfaceContact, ForcesOfEveryCellPairSumToZeroWithZeroMoment) {
  // Each candidate pair on its own, both passes, through the same kernels add_forces uses.
  const auto scene = testing::two_bodies(0.05, 6, Point(0.9, 0.4), 1.1, 0.3);
  const PolygonMesh& mesh = scene.mesh;
  const SurfaceCells surface = all_cells(mesh);
  std::vector<double> m(scene.x.size());
  Random random(6);
  for (double& mi : m) mi = random.uniform(0.5, 2.0);
  const PenaltyContact law{PenaltyParameters{}};
  PairState state;
  state.position = scene.x;
  state.mass = m;
  state.dt = 1e-3;
  SurfaceContact contact(law, mesh.h_avg());
  std::vector<Point> f(scene.x.size());
  std::vector<Penetration> found;
  int balanced = 0;
  for (const IndexPair& cells : contact.find_pairs(surface, scene.x)) {
    std::fill(f.begin(), f.end(), Point::Zero());
    for (auto [a, b] :
         {std::pair(cells.first, cells.second), std::pair(cells.second, cells.first)}) {
      const int base_a = mesh.offsets()[a], base_b = mesh.offsets()[b], nb = mesh.cell_size(b);
      found.clear();
      PolygonPenetration::vertices_inside(
          std::span<const Point>(scene.x).subspan(base_a, mesh.cell_size(a)),
          std::span<const Point>(scene.x).subspan(base_b, nb), {}, found);
      for (const Penetration& pen : found)
        law.apply(pen, base_a + pen.vertex, base_b + pen.edge, base_b + (pen.edge + 1) % nb, state,
                  f);
    }
    Point sum = Point::Zero();
    double scale = 0.0, moment = 0.0, moment_scale = 0.0;
    for (std::size_t i = 0; i < f.size(); ++i) {
      sum += f[i];
      scale += f[i].norm();
      moment += cross(scene.x[i], f[i]);
      moment_scale += scene.x[i].norm() * f[i].norm();
    }
    if (scale == 0.0) continue;
    ++balanced;
    EXPECT_LE(sum.norm(), 1e-12 * scale) << cells.first << ", " << cells.second;
    EXPECT_LE(std::abs(moment), 1e-12 * moment_scale) << cells.first << ", " << cells.second;
  }
  EXPECT_GT(balanced, 50);
}

/// Two unit squares as one mesh (reference: side by side, apart) and their current positions.
struct Squares {
  PolygonMesh mesh{Rectangle(0, 0, 3, 1),
                   {Point(0, 0), Point(1, 0), Point(1, 1), Point(0, 1), Point(2, 0), Point(3, 0),
                    Point(3, 1), Point(2, 1)},
                   {0, 4, 8},
                   {0, 1, 2, 3, 4, 5, 6, 7}};
  std::vector<Point> x;
};

TEST(SurfaceContact, SquaresOverlappingByDGetKD) {
  Squares s;
  const double d = 0.02, k = 300.0;
  s.x = {Point(0, 0), Point(1, 0), Point(1, 1), Point(0, 1)};
  for (const Point& c : {Point(0, 0), Point(1, 0), Point(1, 1), Point(0, 1)})
    s.x.push_back(c + Point(1 - d, 0.25));
  const SurfaceCells surface(s.mesh);
  SurfaceContact contact(PenaltyContact(fixed(k)), 1.0);
  PairState state;
  state.position = s.x;
  std::vector<Point> f(8, Point::Zero());
  const auto report = contact.add_forces(surface, state, f);
  EXPECT_EQ(report.contacts, 2);  // A's (1, 1) in B, B's (1 - d, 0.25) in A
  EXPECT_NEAR(report.max_depth, d, 1e-14);
  EXPECT_NEAR(report.potential, 2 * 0.5 * k * d * d, 1e-12);
  // A's (1, 1): pushed out of B by k d, and a quarter of the reaction to B's corner, which
  // presses A's right edge at t = 1/4 from (1, 0). B's corner likewise.
  EXPECT_NEAR((f[2] - Point(-1.25 * k * d, 0)).norm(), 0.0, 1e-12);
  EXPECT_NEAR((f[4] - Point(1.25 * k * d, 0)).norm(), 0.0, 1e-12);
  const Point body_a = f[0] + f[1] + f[2] + f[3], body_b = f[4] + f[5] + f[6] + f[7];
  EXPECT_NEAR((body_a - Point(-2 * k * d, 0)).norm(), 0.0, 1e-12);
  EXPECT_NEAR((body_a + body_b).norm(), 0.0, 1e-13);
}

TEST(SurfaceContact, AVertexFoundDeepIsLeftAloneUntilItLeaves) {
  // Square B overlaps square A by d in x, a quarter up. The threshold is 0.1 of a unit square.
  Squares s;
  const double k = 300.0;
  const auto place_b = [&](double d) {
    s.x = {Point(0, 0), Point(1, 0), Point(1, 1), Point(0, 1)};
    for (const Point& c : {Point(0, 0), Point(1, 0), Point(1, 1), Point(0, 1)})
      s.x.push_back(c + Point(1 - d, 0.25));
  };
  const SurfaceCells surface(s.mesh);
  SurfaceContact contact(PenaltyContact(fixed(k)), 1.0);
  const auto evaluate = [&](double d, std::vector<Point>& f) {
    place_b(d);
    PairState state;
    state.position = s.x;
    f.assign(8, Point::Zero());
    return contact.add_forces(surface, state, f);
  };
  std::vector<Point> f;
  // Found first at 0.3: both corners got in unseen, and neither is pushed.
  ContactReport r = evaluate(0.3, f);
  EXPECT_EQ(r.contacts, 0);
  EXPECT_EQ(r.tunnelled, 2);
  EXPECT_EQ(r.new_tunnels, 2);
  for (const Point& x : f) EXPECT_EQ(x.norm(), 0.0);
  r = evaluate(0.05, f);  // still inside, now shallow: still left alone
  EXPECT_EQ(r.contacts, 0);
  EXPECT_EQ(r.tunnelled, 2);
  EXPECT_EQ(r.new_tunnels, 0);
  r = evaluate(-0.01, f);  // out: forgotten
  EXPECT_EQ(r.tunnelled, 0);
  // Entering step by step, it is pushed at every depth, past the threshold too.
  for (double d : {0.02, 0.06, 0.1, 0.15, 0.2}) {  // below 0.25, where the exit changes
    r = evaluate(d, f);
    EXPECT_EQ(r.contacts, 2) << d;
    EXPECT_EQ(r.tunnelled, 0) << d;
    EXPECT_NEAR(r.potential, k * d * d, 1e-12 * k) << d;
  }
}

TEST(SurfaceContact, AVertexFoundLateIsPushedOnlyBeyondItsFirstDepth) {
  // As above, with B approaching at w: a step of dt reaches 2 w dt = 0.02 (kReachSlack = 2).
  Squares s;
  const double k = 300.0, w = 1.0, dt = 0.01;
  std::vector<Point> v(4, Point::Zero());
  v.resize(8, Point(-w, 0));
  const SurfaceCells surface(s.mesh);
  SurfaceContact contact(PenaltyContact(fixed(k)), 1.0);
  std::vector<Point> f;
  const auto evaluate = [&](double d) {
    s.x = {Point(0, 0), Point(1, 0), Point(1, 1), Point(0, 1)};
    for (const Point& c : {Point(0, 0), Point(1, 0), Point(1, 1), Point(0, 1)})
      s.x.push_back(c + Point(1 - d, 0.25));
    PairState state;
    state.position = s.x;
    state.velocity = v;
    state.dt = dt;
    f.assign(8, Point::Zero());
    return contact.add_forces(surface, state, f);
  };
  const double tol = 1e-12 * k;
  // Found first at 0.05: the law acts on the 0.02 a step could reach, both corners.
  ContactReport r = evaluate(0.05);
  EXPECT_EQ(r.contacts, 2);
  EXPECT_EQ(r.late, 2);
  EXPECT_EQ(r.new_late, 2);
  EXPECT_EQ(r.tunnelled, 0);
  EXPECT_NEAR(r.potential, k * 0.02 * 0.02, tol);
  EXPECT_NEAR(f[2].x(), -1.25 * k * 0.02, tol);
  r = evaluate(0.08);  // deeper: the offset 0.03 stays
  EXPECT_EQ(r.new_late, 0);
  EXPECT_NEAR(r.potential, k * 0.05 * 0.05, tol);
  r = evaluate(0.04);  // backing out: still 0.03
  EXPECT_NEAR(r.potential, k * 0.01 * 0.01, tol);
  r = evaluate(0.02);  // shallower than the offset: it shrinks to 0.02, and no force
  EXPECT_EQ(r.potential, 0.0);
  for (const Point& x : f) EXPECT_EQ(x.norm(), 0.0);
  r = evaluate(0.05);  // in again from 0.02
  EXPECT_NEAR(r.potential, k * 0.03 * 0.03, tol);
  r = evaluate(-0.01);  // out: forgotten
  EXPECT_EQ(r.contacts, 0);
  EXPECT_EQ(r.late, 0);
  // Found first within a step's reach: the whole depth, as for any contact.
  r = evaluate(0.015);
  EXPECT_EQ(r.late, 0);
  EXPECT_NEAR(r.potential, k * 0.015 * 0.015, tol);
  // Receding, a corner found inside got there some other way: no force until it goes deeper.
  evaluate(-0.01);
  std::fill(v.begin() + 4, v.end(), Point(w, 0));
  r = evaluate(0.015);
  EXPECT_EQ(r.late, 2);
  EXPECT_EQ(r.potential, 0.0);
}

TEST(SurfaceContact, NodeOfTwoSurfaceCellsIsPushedOnce) {
  // Body A: two unit squares sharing the top vertex (1, 1); body B: a square pressing on it.
  const PolygonMesh mesh(Rectangle(0, 0, 4, 1),
                         {Point(0, 0), Point(1, 0), Point(2, 0), Point(2, 1), Point(1, 1),
                          Point(0, 1), Point(3, 0), Point(4, 0), Point(4, 1), Point(3, 1)},
                         {0, 4, 8, 12}, {0, 1, 4, 5, 1, 2, 3, 4, 6, 7, 8, 9});
  const double d = 0.01, k = 50.0;
  std::vector<Point> x;
  for (int c = 0; c < 2; ++c)
    for (int v : mesh.cell_vertices(c)) x.push_back(mesh.vertex(v));
  for (const Point& c :
       {Point(0.5, 1 - d), Point(1.5, 1 - d), Point(1.5, 2 - d), Point(0.5, 2 - d)})
    x.push_back(c);
  const SurfaceCells surface(mesh);
  const SplitDofMap dofs = SplitDofMap::continuous(mesh);
  const auto nodes = pair_nodes(mesh, dofs);
  SurfaceContact contact(PenaltyContact(fixed(k)), 1.0);
  PairState state;
  state.position = x;
  state.node = nodes;
  std::vector<Point> f(x.size(), Point::Zero());
  EXPECT_EQ(contact.add_forces(surface, state, f).contacts, 3);  // (1, 1) once, B's two corners
  Eigen::VectorXd nodal = Eigen::VectorXd::Zero(dofs.num_dofs());
  add_pair_forces(mesh, dofs, f, nodal);
  const int top = dofs.vertex_nodes(4)[0];
  // k d of its own, and half the reaction to each of B's corners (mid-edge on A's top edges).
  EXPECT_NEAR(nodal[2 * top + 1], -2 * k * d, 1e-12);
  state.node = {};  // every pair its own node: the shared vertex is found by both its cells
  std::fill(f.begin(), f.end(), Point::Zero());
  EXPECT_EQ(contact.add_forces(surface, state, f).contacts, 4);
}

TEST(SurfaceContact, ExposedEdgesAreTheExits) {
  // Body B: two bonded unit squares; a slim triangle's tip at (0.95, 0.9) is in B's left
  // square, nearer the bonded edge x = 1 than the free top edge y = 1.
  const PolygonMesh mesh(Rectangle(0, 0, 4, 2),
                         {Point(0, 0), Point(1, 0), Point(2, 0), Point(2, 1), Point(1, 1),
                          Point(0, 1), Point(3, 0), Point(4, 0), Point(3.5, 1)},
                         {0, 4, 8, 11}, {0, 1, 4, 5, 1, 2, 3, 4, 6, 7, 8});
  std::vector<Point> x;
  for (int c = 0; c < 2; ++c)
    for (int v : mesh.cell_vertices(c)) x.push_back(mesh.vertex(v));
  for (const Point& p : {Point(0.95, 0.9), Point(0.97, 1.5), Point(0.85, 1.5)}) x.push_back(p);
  SurfaceCells surface(mesh);
  SurfaceContact contact(PenaltyContact(fixed(1.0)), 1.0);
  PairState state;
  state.position = x;
  std::vector<Point> f(x.size(), Point::Zero());
  auto report = contact.add_forces(surface, state, f);
  ASSERT_EQ(report.contacts, 1);
  EXPECT_NEAR((f[8] - Point(0, 0.1)).norm(), 0.0, 1e-14);  // out through the top, depth 0.1
  // A crack along the bonded edge makes it a free face: now the nearest exit.
  for (int e = 0; e < mesh.num_edges(); ++e)
    if (!mesh.edge(e).on_boundary()) surface.expose(e);
  std::fill(f.begin(), f.end(), Point::Zero());
  report = contact.add_forces(surface, state, f);
  EXPECT_NEAR((f[8] - Point(0.05, 0)).norm(), 0.0, 1e-14);
}

TEST(SurfaceContact, SameForcesOnEveryRun) {
  const auto scene = testing::two_bodies(0.05, 8, Point(1.0, 0.6), 2.0, 0.3);
  const SurfaceCells surface = all_cells(scene.mesh);
  PairState state;
  state.position = scene.x;
  std::vector<Point> f1(scene.x.size(), Point::Zero()), f2 = f1, f3 = f1;
  SurfaceContact one(PenaltyContact(fixed(1.0)), scene.mesh.h_avg());
  SurfaceContact two(PenaltyContact(fixed(1.0)), scene.mesh.h_avg());
  one.add_forces(surface, state, f1);
  one.add_forces(surface, state, f2);
  two.add_forces(surface, state, f3);
  EXPECT_EQ(f1, f2);
  EXPECT_EQ(f1, f3);
}

TEST(SurfaceContact, RefusesBadState) {
  const auto scene = testing::two_bodies(0.1, 9, Point(1.0, 0.6), 0.0, 0.1);
  const SurfaceCells surface(scene.mesh);
  SurfaceContact contact(PenaltyContact(fixed(1.0)), scene.mesh.h_avg());
  std::vector<Point> x = scene.x, f(x.size(), Point::Zero()), short_f(3);
  PairState state;
  state.position = x;
  EXPECT_THROW(contact.add_forces(surface, state, short_f), InputError);
  SurfaceContact mass_scaled(PenaltyContact(), scene.mesh.h_avg());
  EXPECT_THROW(mass_scaled.add_forces(surface, state, f), InputError);  // no masses, no dt
  x[scene.mesh.offsets()[surface.cells()[0]]].x() = std::nan("");
  EXPECT_THROW(contact.add_forces(surface, state, f), NumericalError);
}

}  // namespace
}  // namespace vorodg
