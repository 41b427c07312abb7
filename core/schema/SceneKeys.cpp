#include "core/schema/SceneKeys.hpp"

#include <cmath>
#include <stdexcept>

#include "core/util/Format.hpp"

namespace vorodg {

SceneKey key(std::string name, std::string type, std::string fallback, std::string range,
             std::string doc) {
  return {std::move(name),  std::move(type), std::move(fallback),
          std::move(range), std::move(doc),  Bounds{}};
}

SceneKey bounded(std::string name, std::string type, std::string fallback, std::string range,
                 std::string doc, double lower, bool lower_open, double upper, bool upper_open) {
  SceneKey k =
      key(std::move(name), std::move(type), std::move(fallback), std::move(range), std::move(doc));
  k.bounds = {lower, upper, lower_open, upper_open};
  return k;
}

const SceneKey& KeyTable::at(const std::string& name) const {
  for (const SceneKey& k : keys)
    if (k.name == name) return k;
  throw std::out_of_range("no " + kind + " scene key " + name);
}

double key_default(const SceneKey& key) {
  try {
    std::size_t used = 0;
    const double v = std::stod(key.fallback, &used);
    if (used == key.fallback.size()) return v;
  } catch (const std::exception&) {
  }
  throw std::logic_error("scene key " + key.name + ": the default is not a number");
}

std::optional<std::string> check_key(const SceneKey& key, double value) {
  if (key.bounds.admits(value)) return std::nullopt;
  return "expected " + key.range + ", found " + fmt(value);
}

}  // namespace vorodg
