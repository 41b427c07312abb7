#include "fracture/SofteningLaws.hpp"

#include "core/util/NamedRegistry.hpp"

namespace vorodg {

namespace {

NamedRegistry<SofteningLawEntry>& registry() {
  static NamedRegistry<SofteningLawEntry> entries{
      "cohesive softening",
      {
          {"linear", "T = sigma_c (1 - delta / delta_c), delta_c = 2 G / sigma_c",
           [](double sc, double g, double) {
             return std::vector<Eigen::Vector2d>{{2.0 * g / sc, 0.0}};
           }},
          // The usual concrete law: the kink at sigma_c / 3 keeps the area G, at 0.8 G / sigma_c
          // extrinsic and moved by delta_0 / 3 for an intrinsic law.
          {"bilinear", "kink at sigma_c / 3 at 0.8 G / sigma_c, zero at 3.6 G / sigma_c",
           [](double sc, double g, double d0) {
             return std::vector<Eigen::Vector2d>{{0.8 * g / sc + d0 / 3.0, sc / 3.0},
                                                 {3.6 * g / sc, 0.0}};
           }},
      }};
  return entries;
}

}  // namespace

const std::vector<SofteningLawEntry>& softening_laws() {
  return registry().entries();
}

bool register_softening_law(SofteningLawEntry entry) {
  return registry().add(std::move(entry));
}

const SofteningLawEntry& softening_law(const std::string& name) {
  return registry().at(name);
}

std::string softening_law_list() {
  return name_list(registry().entries());
}

std::string softening_law_words() {
  return registry().words();
}

}  // namespace vorodg
