#include "dynamics/contact/ContactLaws.hpp"

#include "core/util/NamedRegistry.hpp"
#include "dynamics/contact/RigidPlane.hpp"
#include "dynamics/contact/SurfaceContact.hpp"

namespace vorodg {

namespace {

NamedRegistry<ContactLawEntry>& registry() {
  static NamedRegistry<ContactLawEntry> entries{
      "contact law",
      {
          {"rigid-plane", "a fixed rigid half-plane, the penalty law on each vertex behind it",
           true,
           [](const ContactLawSettings& s) {
             return std::make_unique<RigidPlane>(s.point, s.normal, s.penalty, s.friction);
           }},
          {"cell-pairs", "surface cells against surface cells, the penalty law per vertex inside",
           false,
           [](const ContactLawSettings& s) {
             return std::make_unique<SurfaceContact>(s.penalty, s.grid_spacing, s.friction);
           }},
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

std::unique_ptr<ContactLaw> make_contact_law(const std::string& name,
                                             const ContactLawSettings& settings) {
  return registry().at(name).make(settings);
}

}  // namespace vorodg
