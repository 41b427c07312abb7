#pragma once
// The contact laws known by name (ContactLaw): the shipped ones, and any a program or a test
// registers. Each entry makes its law from the settings every law may read; a law reads only
// what it needs (a plane its point and normal, surface contact the grid spacing).
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "dynamics/contact/ContactFriction.hpp"
#include "dynamics/contact/ContactLaw.hpp"
#include "dynamics/contact/PenaltyContact.hpp"

namespace vorodg {

struct ContactLawSettings {
  PenaltyContact penalty;       // the normal law of the penalty laws
  ContactFriction friction;     // Coulomb's, on this law's contacts
  Point point = Point::Zero();  // an obstacle's plane: a point of it,
  Point normal = Point(0, 1);   // and its normal into free space
  double grid_spacing = 1.0;    // surface contact: the search grid's smallest spacing (h_avg)
};

struct ContactLawEntry {
  std::string name;       // as scenes name it
  std::string doc;        // one line
  bool obstacle = false;  // an obstacle outside the mesh (ContactLaw::external)
  std::function<std::unique_ptr<ContactLaw>(const ContactLawSettings&)> make;
  bool penalty = false;  // reads the penalty law (ContactLawSettings::penalty), its step factor
};

/// Every contact law known, in registration order: the shipped ones first.
const std::vector<ContactLawEntry>& contact_laws();
/// Adds one (a name already known is refused with InputError). Returns true, so that a file can
/// register at static initialization: `const bool registered = register_contact_law(...)`.
bool register_contact_law(ContactLawEntry entry);
/// The entry named `name`; throws InputError for an unknown name.
const ContactLawEntry& contact_law(const std::string& name);
/// The default law of a wall (obstacle) or between surface cells: the first registered of its
/// kind.
std::string default_contact_law(bool obstacle);
/// What the named laws leave of the critical step: `penalty`'s step factor if one of them reads
/// the penalty law (PenaltyContact::step_factor), else 1.
double contact_step_factor(const std::vector<std::string>& names, const PenaltyContact& penalty);
/// The law named `name`, made from `settings`; throws InputError for an unknown name.
std::unique_ptr<ContactLaw> make_contact_law(const std::string& name,
                                             const ContactLawSettings& settings);

}  // namespace vorodg
