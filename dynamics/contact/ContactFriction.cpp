#include "dynamics/contact/ContactFriction.hpp"

#include <cmath>

#include "core/util/Errors.hpp"

namespace vorodg {

ContactFriction::ContactFriction(double mu, const std::string& what) : mu_(mu) {
  require_parameter(std::isfinite(mu) && mu >= 0.0 && mu <= 10.0, what, mu,
                    "in [0, 10] (0: frictionless)");
}

}  // namespace vorodg
