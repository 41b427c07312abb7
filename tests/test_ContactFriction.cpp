// Coulomb friction on penalty contact (dynamics/contact/ContactFriction), against the closed forms
// of Coulomb's law with a stick spring of the contact's stiffness k, normal force N = k d:
//   - a square pressed into a rigid floor and dragged along it step by step: while its total
//     tangential motion s stays below mu N / k each vertex sticks (shear k s, nothing dissipated);
//     beyond it slips at shear mu N and the slip work is mu N (s - mu N / k); dragged back, the
//     shear turns through the stick range before slipping again. To 1e-12 relative.
//   - the same between two surface cells: the forces on the edge's ends are equal and opposite
//     (no momentum), and the shear and slip work follow the same closed forms.
//   - an evaluation repeated at the same positions (after a remap) adds no motion;
//   - mu outside [0, 10] is refused naming the key.
#include "dynamics/contact/ContactFriction.hpp"

#include <gtest/gtest.h>

#include <vector>

#include "core/util/Errors.hpp"
#include "dynamics/contact/RigidPlane.hpp"
#include "dynamics/contact/SurfaceContact.hpp"

namespace vorodg {
namespace {

constexpr double kStiffness = 2.0e3, kDepth = 1e-3, kMu = 0.4;
constexpr double kNormal = kStiffness * kDepth;        // N per contacting vertex
constexpr double kStick = kMu * kNormal / kStiffness;  // the stick range mu N / k

PenaltyParameters fixed_stiffness() {
  PenaltyParameters p;
  p.stiffness = kStiffness;
  return p;
}

/// A unit square cell sunk kDepth into the floor y = 0.
PolygonMesh square() {
  return PolygonMesh(Rectangle(0, 0, 1, 1), {Point(0, 0), Point(1, 0), Point(1, 1), Point(0, 1)},
                     {0, 4}, {0, 1, 2, 3});
}

/// Drags the square's positions by dx in one step of length dt (velocities dx / dt) and
/// evaluates the floor; returns the report and leaves the forces in f.
struct Drag {
  const PolygonMesh mesh = square();
  const SurfaceCells surface{mesh};
  RigidPlane floor{Point(0, 0), Point(0, 1), PenaltyContact(fixed_stiffness()),
                   ContactFriction(kMu)};
  std::vector<Point> x, v = std::vector<Point>(4, Point::Zero()), f;
  double dissipated = 0.0;
  Drag() {
    x = mesh.vertices();
    for (Point& p : x) p.y() -= kDepth;
  }
  ContactReport step(double dx, double dt = 1e-3) {
    for (std::size_t i = 0; i < x.size(); ++i) {
      x[i].x() += dx;
      v[i] = Point(dx / dt, 0.0);
    }
    PairState state;
    state.position = x;
    state.velocity = v;
    state.dt = dt;
    f.assign(4, Point::Zero());
    const ContactReport r = floor.add_forces(surface, state, f);
    dissipated += r.friction_dissipated;
    return r;
  }
};

TEST(ContactFriction, FloorSticksBelowMuNAndSlipsAtIt) {
  Drag drag;
  // Within the stick range: the shear is the spring's, opposing the motion; nothing slips.
  const double ds = 0.1 * kStick;
  for (int s = 1; s <= 5; ++s) {
    const ContactReport r = drag.step(ds);
    EXPECT_EQ(r.sliding, 0);
    for (int i : {0, 1})
      EXPECT_NEAR(drag.f[i].x(), -kStiffness * s * ds, 1e-12 * kNormal) << "step " << s;
  }
  EXPECT_EQ(drag.dissipated, 0.0);
  // On to s = 3 stick ranges: slipping at mu N, the slip work mu N (s - mu N / k) per vertex.
  const double total = 3.0 * kStick;
  const int steps = 50;
  for (int s = 0; s < steps; ++s) drag.step((total - 0.5 * kStick) / steps);
  for (int i : {0, 1}) EXPECT_NEAR(drag.f[i].x(), -kMu * kNormal, 1e-12 * kNormal);
  const double work = 2 * kMu * kNormal * (total - kStick);
  EXPECT_NEAR(drag.dissipated, work, 1e-12 * work);
  // Back by one stick range: the spring unloads through zero to +mu N / ... still sticking.
  drag.step(-kStick);
  for (int i : {0, 1}) EXPECT_NEAR(drag.f[i].x(), 0.0, 1e-12 * kNormal);
  drag.step(-kStick);
  for (int i : {0, 1}) EXPECT_NEAR(drag.f[i].x(), kMu * kNormal, 1e-12 * kNormal);
  EXPECT_NEAR(drag.dissipated, work, 1e-12 * work);
  // A further stick range back slips all of it.
  drag.step(-kStick);
  EXPECT_NEAR(drag.dissipated, work + 2 * kMu * kNormal * kStick, 1e-12 * work);
  // The stick springs store shear^2 / (2 k) beside the normal springs.
  const ContactReport r = drag.step(0.0);
  const double normal = 2 * 0.5 * kStiffness * kDepth * kDepth;
  const double spring = 2 * 0.5 * (kMu * kNormal) * (kMu * kNormal) / kStiffness;
  EXPECT_NEAR(r.potential, normal + spring, 1e-12 * (normal + spring));
}

TEST(ContactFriction, ARepeatedEvaluationAddsNoMotion) {
  Drag drag;
  drag.step(0.5 * kStick);
  PairState state;
  state.position = drag.x;
  state.velocity = drag.v;  // still the last step's velocities
  state.dt = 1e-3;
  state.repeated = true;
  std::vector<Point> f(4, Point::Zero());
  drag.floor.add_forces(drag.surface, state, f);
  for (int i : {0, 1}) EXPECT_NEAR(f[i].x(), -0.5 * kMu * kNormal, 1e-12 * kNormal);
}

TEST(ContactFriction, BetweenCellsTheShearIsCoulombsAndMovesNoMomentum) {
  // Cell 0: the unit square; cell 1: a square above it whose two lower vertices sink kDepth
  // into cell 0's top edge (cell 0's corners stay outside cell 1).
  const std::vector<Point> vertices{Point(0, 0),
                                    Point(1, 0),
                                    Point(1, 1),
                                    Point(0, 1),
                                    Point(0.2, 1 - kDepth),
                                    Point(0.8, 1 - kDepth),
                                    Point(0.8, 2),
                                    Point(0.2, 2)};
  const PolygonMesh mesh(Rectangle(0, 0, 1, 2), vertices, {0, 4, 8}, {0, 1, 2, 3, 4, 5, 6, 7});
  SurfaceCells surface(mesh);
  SurfaceContact contact(PenaltyContact(fixed_stiffness()), 1.0, ContactFriction(kMu));
  std::vector<Point> x = vertices, v(8, Point::Zero()), f;
  const double dt = 1e-3;
  double dissipated = 0.0;
  auto drag = [&](double dx, double dy = 0.0) {
    for (int i = 4; i < 8; ++i) {
      x[i] += Point(dx, dy);
      v[i] = Point(dx, dy) / dt;
    }
    PairState state;
    state.position = x;
    state.velocity = v;
    state.dt = dt;
    f.assign(8, Point::Zero());
    dissipated += contact.add_forces(surface, state, f).friction_dissipated;
  };
  // It comes down into the contact in one step (a contact found deeper than a step's approach
  // would be a late one, acting only beyond its first depth: SurfaceContact).
  for (int i = 4; i < 8; ++i) x[i].y() += kDepth;
  drag(0.0, -kDepth);
  EXPECT_NEAR(f[4].y(), kNormal, 1e-12 * kNormal);
  drag(0.5 * kStick);
  for (int i : {4, 5}) EXPECT_NEAR(f[i].x(), -0.5 * kMu * kNormal, 1e-12 * kNormal);
  EXPECT_EQ(dissipated, 0.0);
  for (int s = 0; s < 10; ++s) drag(0.25 * kStick);
  for (int i : {4, 5}) EXPECT_NEAR(f[i].x(), -kMu * kNormal, 1e-12 * kNormal);
  const double work = 2 * kMu * kNormal * (3.0 * kStick - kStick);
  EXPECT_NEAR(dissipated, work, 1e-12 * work);
  Point sum = Point::Zero();
  for (const Point& p : f) sum += p;
  EXPECT_LT(sum.norm(), 1e-15 * kNormal);
}

TEST(ContactFriction, RefusesAnOutOfRangeCoefficientNamingIt) {
  EXPECT_THROW(ContactFriction(-0.1, "wall.friction"), InputError);
  EXPECT_THROW(ContactFriction(11.0), InputError);
  try {
    ContactFriction(-1.0, "wall.friction");
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("wall.friction"), std::string::npos) << e.what();
  }
  EXPECT_NO_THROW(ContactFriction(0.0));
}

}  // namespace
}  // namespace vorodg
