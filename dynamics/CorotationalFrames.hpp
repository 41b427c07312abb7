#pragma once
// Corotational cell kinematics: each cell deforms by small strain in a frame that turns with it,
// so fragments may spin through any angle (docs/impact.md, "Finite rotations").
//
// The cell's rotation theta is the polar angle of its mean deformation gradient
//     F = I + sum_k u_k (x) b_k     (MeanGradient: the boundary integral of u (x) n over the
// area, exact for the displacements, linear along each edge), theta = atan2(F21 - F12, F11 + F22).
// The local displacements are u^_k = R^T q_k - p_k, with p_k = X_k - X_0 and q_k = p_k + u_k - u_0
// (K annihilates translations). The cell's energy is E = 1/2 u^.K u^, and its force the exact
// gradient:
//     f_k = R (K u^)_k + g dtheta/du_k,   g = dE/dtheta = -sum_k (K u^)_k . J (u^_k + p_k),
//     dtheta/du_k = (s (-b_ky, b_kx) - d (b_kx, b_ky)) / (s^2 + d^2),  s = F11 + F22,
//     d = F21 - F12, J the quarter turn.
// The same mean gradient gives the small-strain model's measure of how far a cell has turned,
// omega_c = (G21 - G12) / 2 with G = F - I (mean_rotation): a rigid rotation u = theta (-y, x)
// gives theta exactly. A small-strain cell turned by theta is drawn, and meets contact,
// stretched by sqrt(1 + theta^2) - 1, about theta^2 / 2 (docs/impact.md).
//
// E does not change when the whole cell turns rigidly, so a spinning cell feels no force and keeps
// its shape; for small rotations f = K u to first order. The force is not linear in u, so the
// integrator's energy identity closes to O(dt^2), not to round-off.
#include <Eigen/Core>
#include <cmath>
#include <vector>

#include "core/dofs/SplitDofMap.hpp"
#include "core/mesh/PolygonMesh.hpp"
#include "dynamics/MeanGradient.hpp"

namespace vorodg {

class CorotationalFrames {
 public:
  explicit CorotationalFrames(const PolygonMesh& mesh);
  int cell_size(int c) const { return gradient_.cell_size(c); }

  /// Cell c's turn: R = [[cos, -sin], [sin, cos]], and the parts of F its derivative needs.
  struct Turn {
    double cos = 1.0, sin = 0.0;
    double trace = 2.0, skew = 0.0;  // s = F11 + F22, d = F21 - F12
    double angle() const;
  };
  /// Cell c's turn from its vertices' displacements relative to vertex 0 (w[2k], w[2k+1];
  /// w_0 = 0), and its local displacements u^ (2n, written to `local`).
  Turn local_displacements(int c, const double* w, double* local) const {
    return local_displacements(c, cell_size(c), w, local);
  }
  /// The same for a caller that knows n (inline: the force's fixed-size loops unroll it).
  Turn local_displacements(int c, int n, const double* w, double* local) const {
    const double* p = p_.data() + 2 * std::size_t(offsets_[c]);
    const Eigen::Matrix2d g = gradient_.gradient(c, n, w);
    Turn t;
    t.trace = 2.0 + g(0, 0) + g(1, 1);
    t.skew = g(1, 0) - g(0, 1);
    // sqrt, not hypot: the trace is near 2, so nothing over- or underflows, and libm's hypot
    // (careful scaling) was 4 % of a column run.
    const double inverse = 1.0 / std::sqrt(t.trace * t.trace + t.skew * t.skew);
    t.cos = t.trace * inverse, t.sin = t.skew * inverse;
    // u^_k = R^T q_k - p_k, written so that no rotation leaves u^ = w exactly.
    for (int k = 0; k < n; ++k) {
      const double qx = p[2 * k] + w[2 * k], qy = p[2 * k + 1] + w[2 * k + 1];
      local[2 * k] = w[2 * k] + ((t.cos - 1.0) * qx + t.sin * qy);
      local[2 * k + 1] = w[2 * k + 1] + (-t.sin * qx + (t.cos - 1.0) * qy);
    }
    return t;
  }
  /// G = F - I = sum_k w_k (x) b_k of cell c from displacements relative to vertex 0 (w_0 = 0;
  /// absolute displacements give the same, since sum_k b_k = 0).
  Eigen::Matrix2d displacement_gradient(int c, const double* w) const {
    return gradient_.gradient(c, w);
  }
  /// G of cell c at node displacements u of `dofs`.
  Eigen::Matrix2d displacement_gradient(int c, const SplitDofMap& dofs,
                                        const Eigen::VectorXd& u) const {
    return displacement_gradient(c, relative(c, dofs, u));
  }
  /// The small-strain rotation of cell c, (G21 - G12) / 2, at node displacements u of `dofs`.
  double mean_rotation(int c, const SplitDofMap& dofs, const Eigen::VectorXd& u) const;
  /// The largest |mean_rotation| over the cells.
  double largest_mean_rotation(const SplitDofMap& dofs, const Eigen::VectorXd& u) const;
  /// The same from node displacements u of `dofs` (`local` resized to 2n).
  Turn local_displacements(int c, const SplitDofMap& dofs, const Eigen::VectorXd& u,
                           Eigen::VectorXd& local) const;
  /// The same into `local`, which has room for 2n: for loops over cells of varying size, where
  /// resizing one vector per cell allocated at every change of size.
  Turn local_displacements(int c, const SplitDofMap& dofs, const Eigen::VectorXd& u,
                           double* local) const {
    return local_displacements(c, relative(c, dofs, u), local);
  }
  /// A Voigt stress (xx, yy, xy) of a cell's turned frame in the global one: R s R^T.
  static Eigen::Vector3d global_stress(const Turn& turn, const Eigen::Vector3d& s);
  /// Cell c's global force (2n, written to `global`) from its turn, its local displacements and
  /// the local force f_loc = K u^; n is the cell's size (inline, as local_displacements: the
  /// force's fixed-size loops unroll it).
  void global_force(int c, int n, const Turn& t, const double* local, const double* f_loc,
                    double* global) const {
    const double* p = p_.data() + 2 * std::size_t(offsets_[c]);
    const double* b = gradient_.weights(c);
    // g = dE/dtheta = -sum_k f_k . J (u^_k + p_k), J (x, y) = (-y, x).
    double g = 0.0;
    for (int k = 0; k < n; ++k) {
      const double x = local[2 * k] + p[2 * k], y = local[2 * k + 1] + p[2 * k + 1];
      g -= f_loc[2 * k] * -y + f_loc[2 * k + 1] * x;
    }
    const double r2 = t.trace * t.trace + t.skew * t.skew;
    for (int k = 0; k < n; ++k) {
      const double bx = b[2 * k], by = b[2 * k + 1];
      const double dx = (t.trace * -by - t.skew * bx) / r2;
      const double dy = (t.trace * bx - t.skew * by) / r2;
      const double fx = f_loc[2 * k], fy = f_loc[2 * k + 1];
      global[2 * k] = t.cos * fx - t.sin * fy + g * dx;
      global[2 * k + 1] = t.sin * fx + t.cos * fy + g * dy;
    }
  }

 private:
  /// Cell c's node displacements relative to its vertex 0, in a per-thread buffer.
  const double* relative(int c, const SplitDofMap& dofs, const Eigen::VectorXd& u) const;

  MeanGradient gradient_;
  std::vector<int> offsets_;
  std::vector<double> p_;  // per pair: X_k - X_0 (x, y)
};

}  // namespace vorodg
