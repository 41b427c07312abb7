#include "core/util/Errors.hpp"

#include "core/util/Format.hpp"

namespace vorodg {

void require_parameter(bool ok, const std::string& name, double value, const std::string& range) {
  if (!ok) throw InputError(name + " = " + fmt(value) + ": expected " + range);
}

}  // namespace vorodg
