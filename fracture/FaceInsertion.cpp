#include "fracture/FaceInsertion.hpp"

namespace vorodg {

Eigen::Vector2d face_traction(const Eigen::Vector3d& sigma, const Eigen::Vector2d& n,
                              const Eigen::Vector2d& t) {
  const Eigen::Vector2d sn(sigma[0] * n.x() + sigma[2] * n.y(),
                           sigma[2] * n.x() + sigma[1] * n.y());
  return {sn.dot(n), sn.dot(t)};
}

double face_utilization(const MohrCoulomb& criterion, const Eigen::Vector2d& t,
                        double strength_factor) {
  return criterion.utilization(t[0] / strength_factor, t[1] / strength_factor);
}

}  // namespace vorodg
