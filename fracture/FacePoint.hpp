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
// A driver supplies k (dg: the interface's eps; dynamics: a fraction of K0) and, for the law,
// its own opening (dg measures it from the jump at insertion; dynamics from zero).
#include <Eigen/Core>

#include "core/material/CohesiveLaw.hpp"

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

/// An intrinsic law's point: the law at opening d (advancing `history`), plus the closure
/// penalty k on d's normal component.
FacePointResponse face_point_response(const CohesiveLaw& law, const Eigen::Vector2d& d, double k,
                                      CohesiveLaw::State& history);
/// Its recoverable energy per unit area: the law's unloading line plus the closure penalty.
double face_point_stored_energy(const CohesiveLaw& law, const Eigen::Vector2d& d, double k,
                                const CohesiveLaw::State& history);

}  // namespace vorodg
