#pragma once
// What a formulation needs to know about a boundary value problem of linear elasticity on the
// rectangle: which sides carry prescribed displacements and which prescribed tractions, the data
// themselves, and the body force. Exact solutions (verification/) implement it.
#include <Eigen/Core>
#include <string>

#include "core/geometry/Rectangle.hpp"

namespace vorodg {

enum class BoundaryKind { dirichlet, traction };

class BoundaryValueProblem {
 public:
  virtual ~BoundaryValueProblem() = default;
  virtual std::string name() const = 0;
  /// How side s is loaded; traction sides with zero traction are free.
  virtual BoundaryKind boundary(Side s) const = 0;
  /// Prescribed displacement at a point of a Dirichlet side.
  virtual Eigen::Vector2d dirichlet_value(const Point& x) const = 0;
  /// Prescribed traction at a point of a traction side with outward unit normal n.
  virtual Eigen::Vector2d traction(const Point& x, const Eigen::Vector2d& n) const = 0;
  /// Body force per unit area.
  virtual Eigen::Vector2d body_force(const Point& x) const = 0;
  /// False only if the body force is zero everywhere (then a solve needs no psi at the
  /// quadrature points).
  virtual bool has_body_force() const { return true; }

  bool has_dirichlet_side() const {
    for (Side s : {Side::left, Side::right, Side::bottom, Side::top})
      if (boundary(s) == BoundaryKind::dirichlet) return true;
    return false;
  }
};

}  // namespace vorodg
