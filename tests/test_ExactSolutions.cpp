// Exact solutions (docs/design.md, "Verification problems and error norms"):
// - Timoshenko's beam: displacement and stress against the formulas of docs/design.md written
//   out again here, zero body force (plane stress and plane strain), traction-free top and
//   bottom, the end traction integrates to the load P (and carries no axial force or moment);
//   gradients and hessians against central finite differences.
// - The manufactured solution: zero on all four sides, derivatives against finite differences,
//   body force = -div(sigma) by finite differences of the stress.
// - The affine patch field: u = a + G x, constant stress, zero body force, its supports.
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <numbers>
#include <vector>

#include "core/material/IsotropicElasticity.hpp"
#include "core/problem/AffineField.hpp"
#include "core/problem/ManufacturedSolution.hpp"
#include "core/problem/TimoshenkoBeam.hpp"
#include "core/util/Errors.hpp"

namespace vorodg {
namespace {

constexpr double kL = 4.618802153517006;  // L/D = 8/sqrt(3)
constexpr double kD = 1.0;
constexpr double kP = 1.0;

std::vector<Point> sample_points(const Rectangle& r, int nx = 9, int ny = 7) {
  std::vector<Point> points;
  for (int i = 0; i < nx; ++i)
    for (int j = 0; j < ny; ++j)
      points.emplace_back(r.x0() + r.width() * (i + 0.37) / nx,
                          r.y0() + r.height() * (j + 0.21) / ny);
  // Corners and side points too.
  for (double x : {r.x0(), r.x1()})
    for (double y : {r.y0(), 0.5 * (r.y0() + r.y1()), r.y1()}) points.emplace_back(x, y);
  return points;
}

// Central finite differences of the displacement: G(i, j) = d u_i / d x_j.
Eigen::Matrix2d fd_gradient(const ExactSolution& u, const Point& x, double h) {
  Eigen::Matrix2d G;
  for (int j = 0; j < 2; ++j) {
    const Point dx = h * Eigen::Vector2d::Unit(j);
    G.col(j) = (u.displacement(x + dx) - u.displacement(x - dx)) / (2 * h);
  }
  return G;
}

// Central differences of the exact gradient: H[i](j, k) = d/dx_k (d u_i / d x_j).
std::array<Eigen::Matrix2d, 2> fd_hessian(const ExactSolution& u, const Point& x, double h) {
  std::array<Eigen::Matrix2d, 2> H;
  for (int k = 0; k < 2; ++k) {
    const Point dx = h * Eigen::Vector2d::Unit(k);
    const Eigen::Matrix2d dG = (u.gradient(x + dx) - u.gradient(x - dx)) / (2 * h);
    for (int i = 0; i < 2; ++i) H[i].col(k) = dG.row(i).transpose();
  }
  return H;
}

// -div(sigma) from central differences of the exact stress.
Eigen::Vector2d fd_body_force(const ExactSolution& u, const Point& x, double h) {
  const Point dx(h, 0), dy(0, h);
  const Eigen::Vector3d ds_dx = (u.stress(x + dx) - u.stress(x - dx)) / (2 * h);
  const Eigen::Vector3d ds_dy = (u.stress(x + dy) - u.stress(x - dy)) / (2 * h);
  return -Eigen::Vector2d(ds_dx[0] + ds_dy[2], ds_dx[2] + ds_dy[1]);
}

// Gauss-Legendre on [a, b]: composite two-point rule on n panels (exact for cubics).
template <class F>
double integrate(F f, double a, double b, int n) {
  const double g = 0.5 / std::sqrt(3.0);
  double sum = 0.0;
  for (int k = 0; k < n; ++k) {
    const double lo = a + (b - a) * k / n, hi = a + (b - a) * (k + 1) / n, mid = 0.5 * (lo + hi);
    sum += 0.5 * (hi - lo) * (f(mid - g * (hi - lo)) + f(mid + g * (hi - lo)));
  }
  return sum;
}

// ------------------------------------------------------------------------------------------
// Timoshenko beam
// ------------------------------------------------------------------------------------------

class BeamTest : public ::testing::TestWithParam<PlaneModel> {
 protected:
  IsotropicElasticity material() const { return IsotropicElasticity(1.0, 0.3, GetParam()); }
};

TEST_P(BeamTest, DomainAndSupports) {
  const TimoshenkoBeam beam(material(), kL, kD, kP);
  const Rectangle r = beam.domain();
  EXPECT_DOUBLE_EQ(r.x0(), 0.0);
  EXPECT_DOUBLE_EQ(r.x1(), kL);
  EXPECT_DOUBLE_EQ(r.y0(), -kD / 2);
  EXPECT_DOUBLE_EQ(r.y1(), kD / 2);
  EXPECT_EQ(beam.name(), "beam");
  EXPECT_EQ(beam.boundary(Side::left), BoundaryKind::dirichlet);
  EXPECT_EQ(beam.boundary(Side::right), BoundaryKind::traction);
  EXPECT_EQ(beam.boundary(Side::bottom), BoundaryKind::traction);
  EXPECT_EQ(beam.boundary(Side::top), BoundaryKind::traction);
  EXPECT_TRUE(beam.has_dirichlet_side());
  // The Dirichlet data are the exact displacement.
  for (double y : {-0.5, -0.1, 0.3, 0.5})
    EXPECT_EQ(beam.dirichlet_value(Point(0, y)), beam.displacement(Point(0, y)));
}

TEST_P(BeamTest, DisplacementAndStressMatchTheDesignFormulas) {
  const IsotropicElasticity m = material();
  const TimoshenkoBeam beam(m, kL, kD, kP);
  // Effective plane-stress constants.
  const bool strain = GetParam() == PlaneModel::strain;
  const double E = strain ? m.E() / (1 - m.nu() * m.nu()) : m.E();
  const double nu = strain ? m.nu() / (1 - m.nu()) : m.nu();
  const double I = kD * kD * kD / 12, L = kL, D = kD, P = kP;
  for (const Point& p : sample_points(beam.domain())) {
    const double x = p.x(), y = p.y();
    const double ux = -P * y / (6 * E * I) * ((6 * L - 3 * x) * x + (2 + nu) * (y * y - D * D / 4));
    const double uy =
        P / (6 * E * I) *
        (3 * nu * y * y * (L - x) + (4 + 5 * nu) * D * D * x / 4 + (3 * L - x) * x * x);
    const Eigen::Vector2d u = beam.displacement(p);
    const double uscale = P * L * L * L / (E * I);
    EXPECT_NEAR(u.x(), ux, 1e-13 * uscale) << "at " << p.transpose();
    EXPECT_NEAR(u.y(), uy, 1e-13 * uscale) << "at " << p.transpose();
    // The stress (through the material's D, plane strain included) is the same in both models.
    const Eigen::Vector3d s = beam.stress(p);
    const double sscale = P * L * D / I;
    EXPECT_NEAR(s[0], -P * (L - x) * y / I, 1e-12 * sscale) << "at " << p.transpose();
    EXPECT_NEAR(s[1], 0.0, 1e-12 * sscale) << "at " << p.transpose();
    EXPECT_NEAR(s[2], P / (2 * I) * (D * D / 4 - y * y), 1e-12 * sscale) << "at " << p.transpose();
  }
}

TEST_P(BeamTest, BodyForceIsZero) {
  const TimoshenkoBeam beam(material(), kL, kD, kP);
  const double scale = kP * kL / (kD * kD * kD / 12);  // stress gradient scale
  for (const Point& p : sample_points(beam.domain())) {
    const Eigen::Vector2d b = beam.body_force(p);
    EXPECT_LT(b.norm(), 1e-12 * scale) << "at " << p.transpose() << ": b = " << b.transpose();
  }
}

TEST_P(BeamTest, TopAndBottomAreTractionFree) {
  const TimoshenkoBeam beam(material(), kL, kD, kP);
  const double scale = kP / kD;
  for (int i = 0; i <= 20; ++i) {
    const double x = kL * i / 20;
    const Eigen::Vector2d top = beam.traction(Point(x, kD / 2), Eigen::Vector2d(0, 1));
    const Eigen::Vector2d bottom = beam.traction(Point(x, -kD / 2), Eigen::Vector2d(0, -1));
    EXPECT_LT(top.norm(), 1e-12 * scale) << "x = " << x;
    EXPECT_LT(bottom.norm(), 1e-12 * scale) << "x = " << x;
  }
}

TEST_P(BeamTest, EndTractionCarriesTheLoad) {
  const TimoshenkoBeam beam(material(), kL, kD, kP);
  const Eigen::Vector2d n(1, 0);
  const auto t = [&](double y) { return beam.traction(Point(kL, y), n); };
  const double Fx = integrate([&](double y) { return t(y).x(); }, -kD / 2, kD / 2, 400);
  const double Fy = integrate([&](double y) { return t(y).y(); }, -kD / 2, kD / 2, 400);
  const double M = integrate([&](double y) { return y * t(y).x(); }, -kD / 2, kD / 2, 400);
  std::cout << "beam end traction: int t_x = " << Fx << ", int t_y = " << Fy
            << ", int y t_x = " << M << "\n";
  EXPECT_NEAR(std::abs(Fy), kP, 1e-12 * kP);
  EXPECT_NEAR(Fx, 0.0, 1e-12 * kP);
  EXPECT_NEAR(M, 0.0, 1e-12 * kP * kD);
  // The reaction at x = 0 balances it: int t_y over the root (outward normal -x) is -int t_y at
  // the end, and the root moment is P L.
  const Eigen::Vector2d n0(-1, 0);
  const double Fy0 =
      integrate([&](double y) { return beam.traction(Point(0, y), n0).y(); }, -kD / 2, kD / 2, 400);
  const double M0 = integrate([&](double y) { return y * beam.traction(Point(0, y), n0).x(); },
                              -kD / 2, kD / 2, 400);
  EXPECT_NEAR(Fy0, -Fy, 1e-12 * kP);
  EXPECT_NEAR(std::abs(M0), kP * kL, 1e-12 * kP * kL);
}

TEST_P(BeamTest, DerivativesMatchFiniteDifferences) {
  const TimoshenkoBeam beam(material(), kL, kD, kP);
  const double h = 1e-4;
  double gscale = 0, hscale = 0;
  for (const Point& p : sample_points(beam.domain())) {
    gscale = std::max(gscale, beam.gradient(p).cwiseAbs().maxCoeff());
    const auto H = beam.hessian(p);
    hscale = std::max({hscale, H[0].cwiseAbs().maxCoeff(), H[1].cwiseAbs().maxCoeff()});
  }
  for (const Point& p : sample_points(beam.domain())) {
    const Eigen::Matrix2d G = beam.gradient(p), Gfd = fd_gradient(beam, p, h);
    EXPECT_LT((G - Gfd).cwiseAbs().maxCoeff(), 1e-7 * gscale) << "at " << p.transpose() << "\nG =\n"
                                                              << G << "\nfd =\n"
                                                              << Gfd;
    const auto H = beam.hessian(p), Hfd = fd_hessian(beam, p, h);
    for (int i = 0; i < 2; ++i) {
      EXPECT_LT((H[i] - Hfd[i]).cwiseAbs().maxCoeff(), 1e-7 * hscale)
          << "component " << i << " at " << p.transpose() << "\nH =\n"
          << H[i] << "\nfd =\n"
          << Hfd[i];
      EXPECT_LT((H[i] - H[i].transpose()).cwiseAbs().maxCoeff(), 1e-14 * hscale);
    }
  }
}

TEST_P(BeamTest, BodyForceMatchesFiniteDifferencesOfTheStress) {
  const TimoshenkoBeam beam(material(), kL, kD, kP);
  const double scale = kP * kL / (kD * kD * kD / 12);
  for (const Point& p : sample_points(beam.domain())) {
    EXPECT_LT(fd_body_force(beam, p, 1e-4).norm(), 1e-7 * scale) << "at " << p.transpose();
  }
}

INSTANTIATE_TEST_SUITE_P(Planes, BeamTest,
                         ::testing::Values(PlaneModel::stress, PlaneModel::strain),
                         [](const auto& info) {
                           return std::string(info.param == PlaneModel::stress ? "stress"
                                                                               : "strain");
                         });

TEST(Beam, RejectsNonPositiveSizes) {
  const IsotropicElasticity m(1.0, 0.3, PlaneModel::stress);
  EXPECT_THROW(TimoshenkoBeam(m, 0.0, 1.0, 1.0), InputError);
  EXPECT_THROW(TimoshenkoBeam(m, 4.0, -1.0, 1.0), InputError);
}

// ------------------------------------------------------------------------------------------
// Manufactured solution
// ------------------------------------------------------------------------------------------

class MmsTest : public ::testing::TestWithParam<PlaneModel> {};

TEST_P(MmsTest, VanishesOnTheBoundaryAndIsAllDirichlet) {
  const IsotropicElasticity m(2.0, 0.25, GetParam());
  const Rectangle r(0.5, -0.5, 4.5, 1.0);
  const ManufacturedSolution mms(m, r, 1e-3);
  EXPECT_EQ(mms.name(), "mms");
  for (Side s : {Side::left, Side::right, Side::bottom, Side::top})
    EXPECT_EQ(mms.boundary(s), BoundaryKind::dirichlet);
  for (int i = 0; i <= 10; ++i) {
    const double x = r.x0() + r.width() * i / 10, y = r.y0() + r.height() * i / 10;
    for (const Point& p : {Point(x, r.y0()), Point(x, r.y1()), Point(r.x0(), y), Point(r.x1(), y)})
      EXPECT_LT(mms.displacement(p).norm(), 1e-15) << "at " << p.transpose();
  }
  // u = U (s, s/2) with s = 1 at the centre.
  const Eigen::Vector2d centre = mms.displacement(0.5 * (r.lo() + r.hi()));
  EXPECT_NEAR(centre.x(), 1e-3, 1e-15);
  EXPECT_NEAR(centre.y(), 0.5e-3, 1e-15);
}

TEST_P(MmsTest, DerivativesAndBodyForceMatchFiniteDifferences) {
  const IsotropicElasticity m(2.0, 0.25, GetParam());
  const Rectangle r(0.5, -0.5, 4.5, 1.0);
  const ManufacturedSolution mms(m, r, 1e-3);
  const double a = std::numbers::pi / r.width(), b = std::numbers::pi / r.height();
  const double U = 1e-3;
  const double gscale = U * std::max(a, b), hscale = U * std::max(a, b) * std::max(a, b);
  const double bscale = m.E() / (1 - 2 * 0.25) * hscale;  // upper bound on |D| |hessian|
  const double h = 1e-4;
  bool some_nonzero_force = false;
  for (const Point& p : sample_points(r)) {
    const Eigen::Matrix2d G = mms.gradient(p), Gfd = fd_gradient(mms, p, h);
    EXPECT_LT((G - Gfd).cwiseAbs().maxCoeff(), 1e-7 * gscale) << "at " << p.transpose();
    const auto H = mms.hessian(p), Hfd = fd_hessian(mms, p, h);
    for (int i = 0; i < 2; ++i)
      EXPECT_LT((H[i] - Hfd[i]).cwiseAbs().maxCoeff(), 1e-7 * hscale)
          << "component " << i << " at " << p.transpose() << "\nH =\n"
          << H[i] << "\nfd =\n"
          << Hfd[i];
    const Eigen::Vector2d f = mms.body_force(p), ffd = fd_body_force(mms, p, h);
    EXPECT_LT((f - ffd).norm(), 1e-7 * bscale)
        << "at " << p.transpose() << ": body force " << f.transpose() << ", fd " << ffd.transpose();
    some_nonzero_force |= f.norm() > 1e-3 * bscale;
  }
  EXPECT_TRUE(some_nonzero_force);
}

INSTANTIATE_TEST_SUITE_P(Planes, MmsTest, ::testing::Values(PlaneModel::stress, PlaneModel::strain),
                         [](const auto& info) {
                           return std::string(info.param == PlaneModel::stress ? "stress"
                                                                               : "strain");
                         });

// ------------------------------------------------------------------------------------------
// Affine patch field
// ------------------------------------------------------------------------------------------

TEST(AffineField, IsAffineWithConstantStressAndNoBodyForce) {
  const IsotropicElasticity m(1.0, 0.3, PlaneModel::strain);
  const AffineField field(m, AffineField::Supports::mixed);
  const Rectangle r(0, -0.5, 4, 0.5);
  const Point p0(0.3, 0.1);
  const Eigen::Vector3d s0 = field.stress(p0);
  for (const Point& p : sample_points(r)) {
    // u(p) - u(p0) = G (p - p0) for the constant gradient.
    const Eigen::Vector2d du = field.displacement(p) - field.displacement(p0);
    EXPECT_LT((du - field.gradient(p) * (p - p0)).norm(), 1e-16 + 1e-14 * du.norm());
    EXPECT_LT((field.gradient(p) - fd_gradient(field, p, 1e-3)).cwiseAbs().maxCoeff(), 1e-12);
    EXPECT_LT((field.stress(p) - s0).norm(), 1e-15);
    EXPECT_EQ(field.body_force(p), Eigen::Vector2d::Zero());
    const auto H = field.hessian(p);
    EXPECT_TRUE(H[0].isZero() && H[1].isZero());
  }
  // The gradient is not symmetric: the field has a rotation part.
  const Eigen::Matrix2d G = field.gradient(p0);
  EXPECT_GT(std::abs(G(0, 1) - G(1, 0)), 1e-6);
  // Traction = sigma n.
  const Eigen::Vector2d n = Eigen::Vector2d(0.6, 0.8);
  const Eigen::Vector2d t = field.traction(p0, n);
  EXPECT_NEAR(t.x(), s0[0] * n.x() + s0[2] * n.y(), 1e-16);
  EXPECT_NEAR(t.y(), s0[2] * n.x() + s0[1] * n.y(), 1e-16);
}

TEST(AffineField, Supports) {
  const IsotropicElasticity m(1.0, 0.3, PlaneModel::stress);
  constexpr auto D = BoundaryKind::dirichlet, T = BoundaryKind::traction;
  const AffineField all(m, AffineField::Supports::dirichlet);
  const AffineField mixed(m, AffineField::Supports::mixed);
  const AffineField none(m, AffineField::Supports::traction);
  EXPECT_EQ(all.name(), "patch");
  EXPECT_EQ(mixed.name(), "patch-mixed");
  EXPECT_EQ(none.name(), "patch-traction");
  for (Side s : {Side::left, Side::right, Side::bottom, Side::top}) {
    EXPECT_EQ(all.boundary(s), D);
    EXPECT_EQ(none.boundary(s), T);
  }
  EXPECT_EQ(mixed.boundary(Side::left), D);
  EXPECT_EQ(mixed.boundary(Side::bottom), D);
  EXPECT_EQ(mixed.boundary(Side::right), T);
  EXPECT_EQ(mixed.boundary(Side::top), T);
  EXPECT_TRUE(all.has_dirichlet_side());
  EXPECT_TRUE(mixed.has_dirichlet_side());
  EXPECT_FALSE(none.has_dirichlet_side());
}

}  // namespace
}  // namespace vorodg
