#pragma once
// The insertion check of a crack face, shared by quasi-static fracture (dg/CohesiveInterfaces)
// and explicit dynamics (dynamics/CrackInsertion): the traction a stress puts on the face, in the
// face frame (normal: tension positive; shear along the face's tangent), and the Mohr-Coulomb
// utilization of that traction (>= 1: the face cracks). A face whose strength is scaled by f
// (a material varying from cell to cell) fails where t / f fails the scene's criterion: its
// cohesion and tensile cutoff scale with f, its friction angle does not.
#include <Eigen/Core>

#include "fracture/MohrCoulomb.hpp"

namespace vorodg {

/// (n . sigma n, t . sigma n) of the Voigt stress sigma (xx, yy, xy).
Eigen::Vector2d face_traction(const Eigen::Vector3d& sigma, const Eigen::Vector2d& n,
                              const Eigen::Vector2d& t);
/// The criterion's utilization of traction t on a face of strength factor f.
double face_utilization(const MohrCoulomb& criterion, const Eigen::Vector2d& t,
                        double strength_factor = 1.0);

}  // namespace vorodg
