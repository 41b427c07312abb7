#include "dynamics/contact/ContactLaws.hpp"

#include "core/io/StateArchive.hpp"
#include "core/util/Errors.hpp"
#include "core/util/NamedRegistry.hpp"
#include "dynamics/contact/ExactPlane.hpp"
#include "dynamics/contact/ExactSurfaceContact.hpp"
#include "dynamics/contact/RigidPlane.hpp"
#include "dynamics/contact/SurfaceContact.hpp"

namespace vorodg {

namespace {

NamedRegistry<ContactLawEntry>& registry() {
  static NamedRegistry<ContactLawEntry> entries{
      "contact law",
      {
          // The first obstacle is a wall's default.
          {"exact-plane",
           "a fixed rigid half-plane enforced exactly: each vertex that would cross it is put "
           "on it by an impulse, its approach velocity removed (plastic), Coulomb friction "
           "capped by mu times that impulse",
           true,
           [](const ContactLawSettings& s) {
             return std::make_unique<ExactPlane>(s.point, s.normal, s.friction);
           }},
          {"penalty-plane",
           "a fixed rigid half-plane, the penalty law on each vertex behind it (the report's)",
           true,
           [](const ContactLawSettings& s) {
             return std::make_unique<RigidPlane>(s.point, s.normal, s.penalty, s.friction);
           },
           true},
          // The first law between surface cells is the default of `contact.law`.
          {"exact-cell-pairs",
           "surface cells against surface cells enforced exactly: impulses that put each vertex "
           "that would enter a cell on its edge (plastic, momentum-conserving), Coulomb friction "
           "capped by mu times them",
           false,
           [](const ContactLawSettings& s) {
             return std::make_unique<ExactSurfaceContact>(s.grid_spacing, s.friction);
           }},
          {"penalty-cell-pairs",
           "surface cells against surface cells, the penalty law per vertex inside (the report's)",
           false,
           [](const ContactLawSettings& s) {
             return std::make_unique<SurfaceContact>(s.penalty, s.grid_spacing, s.friction);
           },
           true},
      }};
  return entries;
}

}  // namespace

const std::vector<ContactLawEntry>& contact_laws() {
  return registry().entries();
}

bool register_contact_law(ContactLawEntry entry) {
  return registry().add(std::move(entry));
}

const ContactLawEntry& contact_law(const std::string& name) {
  return registry().at(name);
}

std::string default_contact_law(bool obstacle) {
  for (const ContactLawEntry& e : contact_laws())
    if (e.obstacle == obstacle) return e.name;
  throw InputError(std::string("contact law: none registered ") +
                   (obstacle ? "for a wall" : "between surface cells"));
}

double contact_step_factor(const std::vector<std::string>& names, const PenaltyContact& penalty) {
  for (const std::string& name : names)
    if (contact_law(name).penalty) return penalty.step_factor();
  return 1.0;
}

std::unique_ptr<ContactLaw> make_contact_law(const std::string& name,
                                             const ContactLawSettings& settings) {
  return registry().at(name).make(settings);
}

void KinematicContactLaw::archive(StateArchive& a) {
  a.vector("law.touched", touched_);
}

}  // namespace vorodg
