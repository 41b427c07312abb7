#pragma once
// The one kernel of a point on a crack face, shared by quasi-static fracture (dg/
// CohesiveInterfaces) and explicit dynamics (dynamics/CohesiveForces): from the point's opening
// in the face frame (normal, tangential) to its traction, tangent and energies.
//
//   - the cohesive law (core/material/CohesiveLaw) on the opening d the face has made since it
//     cracked, advancing the point's history (its largest effective opening);
//   - the closure penalty k <g_n>_- against overclosure, on the normal opening g_n of the face
//     (the law puts no normal traction on a closing face): a spring, its energy k <g_n>_-^2 / 2
//     stored, not dissipated.
//
//   - Coulomb friction on a closed face (Camacho and Ortiz's crack faces in compression): the
//     shear the face carries beyond the law's is at most mu p, p = k <g_n>_- the closure's
//     pressure. It is regularized as explicit codes do (a return mapping, as in plasticity): a
//     stick spring of the closure's stiffness k on the tangential opening less the slip so far;
//     where its force passes mu p the face slips, the slip grows until the spring carries mu p.
//     An open face carries no friction, and its slip follows the tangential opening, so that it
//     closes again unstressed. The spring's energy tau^2 / (2 k) is stored.
//     The dissipation is booked as the trapezoid of the shear over the slip increment,
//     (tau_old + tau_new) / 2 * slip increment, not mu p_new |slip increment|: with tau = k (gt -
//     slip) at both ends of an evaluation step, the trapezoid of the shear's work over the step's
//     tangential opening is then exactly the change of tau^2 / (2 k) plus that, so the face's
//     energy closes as tightly as the explicit step's works do however the pressure varies (the
//     end-point form left (mu p_old - mu p_new) / 2 |slip increment| unbooked per step). Where
//     the face opens, the spring's shear does tau_old (gt - slip_old) / 2 over the step and its
//     energy is gone: booked as dissipated too. At constant pressure both forms are Coulomb's
//     mu p |slip|.
//
// A driver supplies k (dg: the interface's eps; dynamics: a fraction of K0) and, for the law,
// its own opening (dg measures it from the jump at insertion; dynamics from zero).
#include <Eigen/Core>

#include "fracture/CohesiveLaw.hpp"

namespace vorodg {

struct FacePointResponse {
  Eigen::Vector2d traction = Eigen::Vector2d::Zero();  // (normal, tangential), resisting opening
  Eigen::Matrix2d tangent = Eigen::Matrix2d::Zero();   // d traction / d opening
};

/// The closure penalty at normal opening gn: adds k gn to the normal traction and k to the
/// normal tangent where gn < 0.
void add_closure(double k, double gn, FacePointResponse& r);
/// Its energy per unit area: k <gn>_-^2 / 2.
double closure_energy(double k, double gn);

/// What friction remembers at a point: how far the face has slid, and the energy that took.
struct FrictionState {
  double slip = 0.0;        // the tangential opening at which the stick spring is unstressed
  double shear = 0.0;       // the friction shear at the last evaluation (0 while open)
  double dissipated = 0.0;  // sum of the shear's trapezoid over the slip increments, per unit area
};

/// Coulomb friction mu on the face at opening (gn, gt), the closure stiffness k also the stick
/// spring's: adds the friction shear to the tangential traction (and, sticking, k to the
/// tangential tangent) and advances `friction`. Nothing where mu = 0.
void add_friction(double mu, double k, double gn, double gt, FrictionState& friction,
                  FacePointResponse& r);
/// The stick spring's energy per unit area: k (gt - slip)^2 / 2 (0 where the face is open or
/// has no friction).
double friction_stored_energy(double mu, double k, double gn, double gt,
                              const FrictionState& friction);

/// An intrinsic law's point: the law at opening d (advancing `history`), plus the closure
/// penalty k on d's normal component.
FacePointResponse face_point_response(const CohesiveLaw& law, const Eigen::Vector2d& d, double k,
                                      CohesiveLaw::State& history);
/// Its recoverable energy per unit area: the law's unloading line plus the closure penalty.
double face_point_stored_energy(const CohesiveLaw& law, const Eigen::Vector2d& d, double k,
                                const CohesiveLaw::State& history);

}  // namespace vorodg
