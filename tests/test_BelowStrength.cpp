// Below the strength nothing changes: with cracking enabled (every interior edge split and able
// to crack) and loads whose tractions stay under sigma_c, no point is inserted, an affine field
// is reproduced to round-off (the patch test), and a pure-bending field (quadratic, which the
// element cannot reproduce) gives the dg-sipg elastic solution: the same DOFs to round-off, so
// the same error. Both are all-Dirichlet problems, the field prescribed at every boundary vertex.
#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <vector>

#include "core/element/ElasticityIntegrator.hpp"
#include "core/element/ElementTable.hpp"
#include "core/meshgen/MeshFamily.hpp"
#include "core/problem/BoundaryValueProblem.hpp"
#include "dg/CohesiveFracture.hpp"
#include "dg/DgElasticity.hpp"
#include "dg/QuasiStaticPath.hpp"

namespace vorodg {
namespace {

constexpr double kE = 30e9, kNu = 0.2, kStrength = 3.33e6;
using Field = std::function<Eigen::Vector2d(const Point&)>;

/// The field everywhere on the boundary, no body force.
class AllDirichlet : public BoundaryValueProblem {
 public:
  explicit AllDirichlet(Field f) : f_(std::move(f)) {}
  std::string name() const override { return "all-dirichlet"; }
  BoundaryKind boundary(Side) const override { return BoundaryKind::dirichlet; }
  Eigen::Vector2d dirichlet_value(const Point& x) const override { return f_(x); }
  Eigen::Vector2d traction(const Point&, const Eigen::Vector2d&) const override {
    return Eigen::Vector2d::Zero();
  }
  Eigen::Vector2d body_force(const Point&) const override { return Eigen::Vector2d::Zero(); }

 private:
  Field f_;
};

struct Fixture {
  GeneratedMesh mesh;
  ElementTable table;
  IsotropicElasticity material{kE, kNu, PlaneModel::stress};
  ElasticityIntegrator integrator;
  explicit Fixture(std::uint64_t seed)
      : mesh(generate_mesh([&] {
          MeshSpec s;
          s.family = MeshFamily::rcp;
          s.domain = Rectangle(0.0, 0.0, 2.0, 1.0);
          s.size = 0.15;
          s.seed = seed;
          return s;
        }())),
        table(mesh.mesh, ElementOptions{}),
        integrator(table, material, false) {}
};

/// Follows the path to lambda = 1 with `field` prescribed on the boundary; returns u at the end
/// and how many points left the intact state.
std::pair<Eigen::VectorXd, int> crack_enabled_solve(const Fixture& f, const Field& field,
                                                    CrackingMode mode,
                                                    const CohesiveFracture** model_out,
                                                    std::unique_ptr<CohesiveFracture>& holder) {
  const PolygonMesh& mesh = f.mesh.mesh;
  FractureSetup setup;
  setup.mode = mode;
  setup.line.assign(mesh.num_edges(), 0);
  setup.notch.assign(mesh.num_edges(), 0);
  const double tol = 1e-9 * mesh.domain().scale();
  for (int v = 0; v < mesh.num_vertices(); ++v) {
    const auto near = mesh.domain().sides_near(mesh.vertex(v), tol);
    if (!(near[0] || near[1] || near[2] || near[3])) continue;
    const Eigen::Vector2d u = field(mesh.vertex(v));
    setup.constraints.push_back({v, 0, u.x()});
    setup.constraints.push_back({v, 1, u.y()});
  }
  const CohesiveParameters law{kStrength, 124.0, 1.0, "linear"};
  holder = std::make_unique<CohesiveFracture>(f.table, f.integrator, setup, law,
                                              MohrCoulombParameters{kStrength, 0.75, kStrength},
                                              DgOptions{});
  holder->setup_system();
  *model_out = holder.get();
  PathOptions options;
  options.control = LoadControl::displacement;
  options.max_stroke = holder->stroke(1.0);
  options.steps = 2;
  QuasiStaticPath path(*holder, options);
  Eigen::VectorXd last;
  int broken = 0;
  EXPECT_TRUE(path.run([&](const PathPoint&, const Eigen::VectorXd& u,
                           const std::vector<InterfacePoint>& points) {
    last = u;
    broken = 0;
    for (const InterfacePoint& p : points) broken += p.state != PointState::intact;
  })) << path.failure();
  return {last, broken};
}

/// A field whose largest stress is a fraction of the strength: affine, or pure bending
/// (sigma_xx = E kappa (y - 1/2), the rest zero; plane stress, no body force).
Field affine_field() {
  const double s = 0.3 * kStrength / kE;
  return [s](const Point& x) {
    return Eigen::Vector2d(s * (0.4 * x.x() + 0.2 * x.y() + 0.1), s * (-0.3 * x.x() + 0.5 * x.y()));
  };
}
Field bending_field() {
  const double k = 0.5 * kStrength / kE / 0.5;  // |sigma_xx| <= sigma_c / 2 at y = 0, 1
  return [k](const Point& p) {
    const double x = p.x(), y = p.y() - 0.5;
    return Eigen::Vector2d(k * x * y, -0.5 * k * (x * x + kNu * y * y));
  };
}

TEST(BelowStrength, ThePatchTestPassesWithCrackingEnabled) {
  for (CrackingMode mode : {CrackingMode::arbitrary, CrackingMode::contiguous}) {
    for (std::uint64_t seed : {3u, 11u}) {
      const Fixture f(seed);
      const Field field = affine_field();
      std::unique_ptr<CohesiveFracture> holder;
      const CohesiveFracture* model = nullptr;
      const auto [u, broken] = crack_enabled_solve(f, field, mode, &model, holder);
      EXPECT_EQ(broken, 0) << cracking_mode_name(mode) << " seed " << seed;
      const PolygonMesh& mesh = f.mesh.mesh;
      double worst = 0.0, scale = 0.0;
      for (int c = 0; c < mesh.num_cells(); ++c) {
        const auto loop = mesh.cell_vertices(c);
        for (int k = 0; k < static_cast<int>(loop.size()); ++k) {
          const Eigen::Vector2d exact = field(mesh.vertex(loop[k]));
          const int d = model->space().dof(c, k);
          worst = std::max(worst, (Eigen::Vector2d(u[d], u[d + 1]) - exact).norm());
          scale = std::max(scale, exact.norm());
        }
      }
      EXPECT_LE(worst, 1e-10 * scale) << cracking_mode_name(mode) << " seed " << seed;
    }
  }
}

TEST(BelowStrength, BendingGivesTheElasticDgSolution) {
  const Fixture f(5);
  const Field field = bending_field();
  std::unique_ptr<CohesiveFracture> holder;
  const CohesiveFracture* model = nullptr;
  const auto [u, broken] = crack_enabled_solve(f, field, CrackingMode::arbitrary, &model, holder);
  EXPECT_EQ(broken, 0);
  const AllDirichlet problem(field);
  DgOptions sipg;
  sipg.formulation = "dg-sipg";
  DgElasticity elastic(f.table, f.integrator, problem, sipg);
  elastic.run();
  const PolygonMesh& mesh = f.mesh.mesh;
  double worst = 0.0, scale = 0.0, error = 0.0;
  for (int c = 0; c < mesh.num_cells(); ++c) {
    const Eigen::VectorXd mine = elastic.cell_dofs(c);
    const auto loop = mesh.cell_vertices(c);
    for (int k = 0; k < static_cast<int>(loop.size()); ++k) {
      const int d = model->space().dof(c, k);
      const Eigen::Vector2d theirs = mine.segment<2>(2 * k);
      worst = std::max(worst, (Eigen::Vector2d(u[d], u[d + 1]) - theirs).norm());
      scale = std::max(scale, theirs.norm());
      error = std::max(error, (theirs - field(mesh.vertex(loop[k]))).norm());
    }
  }
  EXPECT_GT(error, 1e-6 * scale) << "bending must not be reproduced, or the test says nothing";
  EXPECT_LE(worst, 1e-9 * scale) << "the crack-enabled solution differs from dg-sipg's";
}

}  // namespace
}  // namespace vorodg
