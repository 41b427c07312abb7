#include "core/material/MaterialKeys.hpp"

namespace vorodg {

std::vector<SceneKey> elastic_keys(const std::string& E, const std::string& nu) {
  return {bounded("material.E", "number", E, "0 < E <= 1e13",
                  "Young's modulus, Pa (no solid is stiffer than about 1.2e12)", 0.0, true, 1e13),
          bounded("material.nu", "number", nu, "-1 < nu < 0.5", "Poisson's ratio", -1.0, true, 0.5,
                  true),
          key("material.plane", "string", "stress", "stress or strain", "plane stress or strain")};
}

}  // namespace vorodg
