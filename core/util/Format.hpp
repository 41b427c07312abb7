#pragma once
// Numbers in messages: short and exact enough to find the offending value (std::to_string
// prints a fixed six decimals, which hides small and large values alike).
#include <sstream>
#include <string>

namespace vorodg {

inline std::string fmt(double x, int precision = 6) {
  std::ostringstream os;
  os.precision(precision);
  os << x;
  return os.str();
}

}  // namespace vorodg
