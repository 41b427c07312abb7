#include "core/random/MaterialField.hpp"

#include "core/util/Random.hpp"

namespace vorodg {

std::uint64_t MaterialField::field_seed(int realization, int which) const {
  return derive_seed(derive_seed(seed, static_cast<std::uint64_t>(realization)),
                     static_cast<std::uint64_t>(which));
}

}  // namespace vorodg
