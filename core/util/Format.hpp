#pragma once
// Numbers in messages: short and exact enough to find the offending value (std::to_string
// prints a fixed six decimals, which hides small and large values alike).
#include <charconv>
#include <iterator>
#include <sstream>
#include <string>

namespace vorodg {

inline std::string fmt(double x, int precision = 6) {
  std::ostringstream os;
  os.precision(precision);
  os << x;
  return os.str();
}

/// The shortest text that reads back to the value (0.7, not 0.69999999999999996).
inline std::string exact_text(double x) {
  char buf[32];
  const auto [end, ec] = std::to_chars(buf, buf + sizeof buf, x);
  return std::string(buf, end);
}

/// "a, b or c": the names of `items` (each item's `name` member) for a message's "expected ...".
template <class Range>
std::string name_list(const Range& items) {
  std::string out;
  const std::size_t n = static_cast<std::size_t>(std::size(items));
  std::size_t i = 0;
  for (const auto& item : items) {
    out += (i == 0 ? "" : i + 1 == n ? " or " : ", ") + item.name;
    ++i;
  }
  return out;
}

}  // namespace vorodg
