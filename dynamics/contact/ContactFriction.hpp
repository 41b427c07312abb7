#pragma once
// Coulomb friction on penalty contact (surface cells against each other, and against a rigid
// plane), in the incremental form explicit codes use: a contact remembers the shear it carried at
// the last step, adds the stick spring's response to the tangential motion of the step, and the
// return mapping (core/material/CoulombFriction) cuts it to mu times the normal force.
//
// Per contact and step: the vertex p moved `increment` = dt (v_p - v_q).tau along the tangent
// tau = J n (n the contact normal, J the quarter turn) relative to the point q it is pushed
// towards (the half-step velocities are what moved the positions, so this is the step's exact
// relative motion). The trial shear is previous - k increment, k the normal penalty's stiffness
// (the stick spring is as stiff as the contact itself, so it never sets the stable step either);
// the limit is mu |F_n|, F_n the whole normal force, displacement and velocity penalty alike, so
// that an impulsive impact meets the friction of its impulse. A new contact starts from zero
// shear; one that ends forgets its shear.
//
// Energy: slipping dissipates mu |F_n| |slip| (ContactReport::friction_dissipated); the stick
// spring stores shear^2 / (2 k) (in ContactReport::potential). The exact account is still the
// work of all contact forces (ContactWork).
#include <string>

#include "core/material/CoulombFriction.hpp"
#include "dynamics/contact/ContactReport.hpp"
#include "dynamics/contact/PairState.hpp"
#include "dynamics/contact/PenaltyContact.hpp"

namespace vorodg {

class ContactFriction {
 public:
  /// Throws InputError naming `what` unless mu is finite and 0 <= mu <= 10 (0: frictionless).
  explicit ContactFriction(double mu = 0.0, const std::string& what = "contact friction");

  double mu() const { return mu_; }
  bool active() const { return mu_ > 0.0; }

  /// The contact's shear (force on the vertex along tau) after a step of tangential motion
  /// `increment`, from the shear it carried before (`previous`, 0 for a new contact), at normal
  /// force `normal_force` >= 0 and stick stiffness `stiffness` > 0.
  CoulombReturn respond(double previous, double increment, double normal_force,
                        double stiffness) const {
    return coulomb_return(previous - stiffness * increment, mu_ * normal_force, stiffness);
  }
  /// One contact's step, as both surface contact and the planes take it: the vertex moving at
  /// `relative_velocity` against its target, pushed along `normal` by `pushed` (the penalty's
  /// response: force and stiffness), with the shear `shear` it carried (updated). Returns the
  /// friction force on the vertex (along tau = J n) and books the slip work, the stick spring's
  /// energy and a slip in `report`. `who` names the caller when the state has no velocities.
  Point force(const Point& normal, const Point& relative_velocity,
              const PenaltyContact::Response& pushed, const PairState& state, double& shear,
              ContactReport& report, const char* who) const;
  /// The stick spring's energy at `shear`: shear^2 / (2 k).
  static double stored_energy(double shear, double stiffness) {
    return stiffness > 0.0 ? 0.5 * shear * shear / stiffness : 0.0;
  }

 private:
  double mu_;
};

}  // namespace vorodg
