// The crack-face kernel (fracture/FacePoint), which dg and dynamics share:
//   - the closure penalty acts on overclosure only: k g_n on the normal traction and k on the
//     normal tangent where g_n < 0, nothing where the face is open; its energy k g_n^2 / 2 has
//     the traction as its derivative (central differences, 1e-7 relative);
//   - an intrinsic law's point is the law plus the closure: on the elastic branch the stored
//     energy's gradient is the traction (1e-7 relative), the tangent is K0 diag(1, beta^2) plus
//     k on the normal in closure, and loading past the peak advances the history while the
//     energy stays the unloading line's;
//   - Coulomb friction at a point: sticking, the shear is k (g_t - slip) with tangent k; past mu p
//     it slips at mu p exactly, dissipating mu p times the slip, and on reversal it sticks again
//     until the shear reaches -mu p; an open face carries none and its slip follows g_t, so it
//     closes unstressed; mu = 0 adds nothing at all;
//   - the insertion check (fracture/FaceInsertion): a uniaxial stress sigma along x on a face
//     turned by theta carries sigma cos^2 theta normal and sigma sin theta cos theta shear (1e-15
//     relative), and a face of strength factor f fails where t / f fails (cutoff and cohesion
//     scale with f).
#include <gtest/gtest.h>

#include <cmath>

#include "fracture/FaceInsertion.hpp"
#include "fracture/FacePoint.hpp"

namespace vorodg {
namespace {

CohesiveLaw intrinsic_law() {
  CohesiveParameters p;
  p.strength = 3e6;
  p.fracture_energy = 100.0;
  p.initial_stiffness = 1e12;
  p.shear_factor = 0.5;
  return CohesiveLaw(p);
}

TEST(FacePoint, ClosureActsOnOverclosureOnly) {
  const double k = 2e11;
  FacePointResponse open, closed;
  add_closure(k, 1e-6, open);
  EXPECT_EQ(open.traction, Eigen::Vector2d::Zero());
  EXPECT_EQ(open.tangent, Eigen::Matrix2d::Zero());
  add_closure(k, -1e-6, closed);
  EXPECT_EQ(closed.traction[0], -k * 1e-6);
  EXPECT_EQ(closed.tangent(0, 0), k);
  EXPECT_EQ(closed.traction[1], 0.0);
  EXPECT_EQ(closure_energy(k, 1e-6), 0.0);
  const double g = -3e-6, h = 1e-10;
  const double slope = (closure_energy(k, g + h) - closure_energy(k, g - h)) / (2 * h);
  EXPECT_NEAR(slope, k * g, 1e-7 * std::abs(k * g));
}

TEST(FacePoint, AnIntrinsicPointIsTheLawPlusTheClosure) {
  const CohesiveLaw law = intrinsic_law();
  const double k = 0.1 * law.parameters().initial_stiffness;
  const Eigen::Vector2d d(-1e-7, 2e-7);  // closing and sliding, below the peak
  CohesiveLaw::State history, alone;
  const FacePointResponse r = face_point_response(law, d, k, history);
  const CohesiveLaw::Response l = law.respond(d, alone);
  EXPECT_EQ(r.traction[0], l.traction[0] + k * d[0]);
  EXPECT_EQ(r.traction[1], l.traction[1]);
  EXPECT_EQ(r.tangent(0, 0), l.tangent(0, 0) + k);
  for (int i = 0; i < 2; ++i) {  // the stored energy's gradient is the traction
    const double h = 1e-12;
    Eigen::Vector2d up = d, down = d;
    up[i] += h, down[i] -= h;
    const double slope = (face_point_stored_energy(law, up, k, history) -
                          face_point_stored_energy(law, down, k, history)) /
                         (2 * h);
    EXPECT_NEAR(slope, r.traction[i], 1e-6 * r.traction.norm()) << i;
  }
}

TEST(FacePoint, LoadingPastThePeakAdvancesTheHistory) {
  const CohesiveLaw law = intrinsic_law();
  CohesiveLaw::State history;
  const double peak = law.parameters().strength / law.parameters().initial_stiffness;
  const Eigen::Vector2d d(3 * peak, 0.0);
  const FacePointResponse r = face_point_response(law, d, 1e11, history);
  EXPECT_NEAR(history.max_opening, d[0], 1e-15);
  EXPECT_LT(r.traction[0], law.parameters().strength);
  EXPECT_GT(r.traction[0], 0.0);
  // On the unloading line: the secant's triangle, no closure energy for an open face.
  const double secant = r.traction[0] / d[0];
  EXPECT_NEAR(face_point_stored_energy(law, d, 1e11, history), 0.5 * secant * d[0] * d[0],
              1e-9 * secant * d[0] * d[0]);
}

TEST(FaceInsertion, TractionOfAUniaxialStressAndScaledStrength) {
  const double sigma = 5e6, theta = 0.3;
  const Eigen::Vector2d n(std::cos(theta), std::sin(theta)), t(-n.y(), n.x());
  const Eigen::Vector2d tr = face_traction(Eigen::Vector3d(sigma, 0.0, 0.0), n, t);
  EXPECT_NEAR(tr[0], sigma * std::cos(theta) * std::cos(theta), 1e-15 * sigma);
  EXPECT_NEAR(tr[1], -sigma * std::sin(theta) * std::cos(theta), 1e-15 * sigma);
  const MohrCoulomb criterion({3e6, 0.5, 2e6});
  const Eigen::Vector2d at_cutoff(2e6, 0.0);
  EXPECT_DOUBLE_EQ(face_utilization(criterion, at_cutoff), 1.0);
  EXPECT_DOUBLE_EQ(face_utilization(criterion, at_cutoff, 2.0), 0.5);  // twice as strong
  EXPECT_DOUBLE_EQ(face_utilization(criterion, Eigen::Vector2d(0.0, 1.5e6), 0.5), 1.0);
}

TEST(FacePoint, CoulombFrictionSticksSlipsAndReverses) {
  const double mu = 0.5, k = 1e11, gn = -2e-7, p = k * -gn, limit = mu * p;
  FrictionState state;
  FacePointResponse stick;
  add_friction(mu, k, gn, 0.5 * limit / k, state, stick);
  EXPECT_EQ(stick.traction[1], 0.5 * limit);
  EXPECT_EQ(stick.tangent(1, 1), k);
  EXPECT_EQ(state.dissipated, 0.0);
  FacePointResponse slip;
  const double gt = 3 * limit / k;  // past the limit by 2 limit / k
  add_friction(mu, k, gn, gt, state, slip);
  EXPECT_NEAR(slip.traction[1], limit, 1e-15 * limit);
  EXPECT_NEAR(state.slip, gt - limit / k, 1e-15 * gt);
  // The trapezoid of the shear (0.5 limit at the start of the step, limit at its end) over the
  // slip 2 limit / k: what the trapezoid of the shear's work leaves beyond the spring's energy.
  EXPECT_NEAR(state.dissipated, 0.5 * (0.5 * limit + limit) * 2 * limit / k,
              1e-12 * limit * limit / k);
  EXPECT_NEAR(friction_stored_energy(mu, k, gn, gt, state), 0.5 * limit * limit / k,
              1e-12 * limit * limit / k);
  FacePointResponse back;  // reversed by limit / k: sticks, the spring unloaded to zero
  add_friction(mu, k, gn, gt - limit / k, state, back);
  EXPECT_NEAR(back.traction[1], 0.0, 1e-12 * limit);
  FacePointResponse open;
  add_friction(mu, k, 1e-9, 5 * limit / k, state, open);
  EXPECT_EQ(open.traction[1], 0.0);
  EXPECT_EQ(state.slip, 5 * limit / k);
  EXPECT_EQ(friction_stored_energy(mu, k, 1e-9, 5 * limit / k, state), 0.0);
  FacePointResponse none;
  FrictionState untouched;
  add_friction(0.0, k, gn, gt, untouched, none);
  EXPECT_EQ(none.traction, Eigen::Vector2d::Zero());
  EXPECT_EQ(untouched.slip, 0.0);
  EXPECT_EQ(friction_stored_energy(0.0, k, gn, gt, untouched), 0.0);
}

}  // namespace
}  // namespace vorodg
