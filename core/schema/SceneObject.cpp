#include "core/schema/SceneObject.hpp"

#include <algorithm>
#include <cstdint>
#include <limits>

#include "core/io/AtomicFile.hpp"
#include "core/util/Errors.hpp"

namespace vorodg {

using nlohmann::json;

std::size_t edit_distance(const std::string& a, const std::string& b) {
  std::vector<std::size_t> row(b.size() + 1);
  for (std::size_t j = 0; j <= b.size(); ++j) row[j] = j;
  for (std::size_t i = 1; i <= a.size(); ++i) {
    std::size_t diagonal = row[0];
    row[0] = i;
    for (std::size_t j = 1; j <= b.size(); ++j) {
      const std::size_t up = row[j];
      row[j] = std::min({row[j] + 1, row[j - 1] + 1, diagonal + (a[i - 1] != b[j - 1])});
      diagonal = up;
    }
  }
  return row[b.size()];
}

SceneObject::SceneObject(const json& value, std::string where, const std::string& source)
    : value_(value), where_(std::move(where)), source_(source) {
  if (!value.is_object()) fail("", "an object", value);
}

void SceneObject::fail(const std::string& key, const std::string& expected,
                       const json& found) const {
  const std::string where = path(key).empty() ? "the top level" : "key '" + path(key) + "'";
  throw InputError("scene " + source_ + ": " + where + ": expected " + expected + ", found " +
                   describe(found));
}

void SceneObject::fail_value(const std::string& key, const std::string& what) const {
  throw InputError("scene " + source_ + ": key '" + path(key) + "': " + what);
}

bool SceneObject::has(const std::string& key) {
  return known(key), value_.contains(key);
}

const json& SceneObject::at(const std::string& key) {
  known(key);
  if (!value_.contains(key)) {
    for (const auto& [present, ignored] : value_.items())
      if (edit_distance(present, key) < 4)
        throw InputError("scene " + source_ + ": unknown key '" + path(present) +
                         "' (did you mean '" + key + "'?)");
    fail_value(key, "missing (required)");
  }
  return value_.at(key);
}

std::string SceneObject::text(const std::string& key, const std::string& fallback) {
  if (!has(key)) return fallback;
  const json& v = value_.at(key);
  if (!v.is_string()) fail(key, "a string", v);
  return v.get<std::string>();
}

double SceneObject::number(const std::string& key, double fallback) {
  if (!has(key)) return fallback;
  const json& v = value_.at(key);
  if (!v.is_number()) fail(key, "a number", v);
  return v.get<double>();
}

int SceneObject::integer(const std::string& key, int fallback) {
  if (!has(key)) return fallback;
  const json& v = value_.at(key);
  if (!v.is_number_integer()) fail(key, "an integer", v);
  // get<int>() would wrap silently (4294967299 -> 3): refuse what an int cannot hold.
  constexpr int lo = std::numeric_limits<int>::min(), hi = std::numeric_limits<int>::max();
  if (v.is_number_unsigned() ? v.get<std::uint64_t>() > static_cast<std::uint64_t>(hi)
                             : v.get<std::int64_t>() < lo || v.get<std::int64_t>() > hi)
    fail(key, "an integer in " + std::to_string(lo) + ".." + std::to_string(hi), v);
  return v.get<int>();
}

bool SceneObject::flag(const std::string& key, bool fallback) {
  if (!has(key)) return fallback;
  const json& v = value_.at(key);
  if (!v.is_boolean()) fail(key, "true or false", v);
  return v.get<bool>();
}

std::vector<double> SceneObject::numbers(const std::string& key, std::vector<double> fallback) {
  if (!has(key)) return fallback;
  const json& v = value_.at(key);
  if (v.is_number()) return {v.get<double>()};
  if (!v.is_array() || v.empty()) fail(key, "a number or a non-empty array of numbers", v);
  std::vector<double> out;
  for (const json& x : v) {
    if (!x.is_number()) fail(key, "an array of numbers", v);
    out.push_back(x.get<double>());
  }
  return out;
}

std::vector<std::string> SceneObject::texts(const std::string& key,
                                            std::vector<std::string> fallback) {
  if (!has(key)) return fallback;
  const json& v = value_.at(key);
  if (v.is_string()) return {v.get<std::string>()};
  if (!v.is_array() || v.empty()) fail(key, "a string or a non-empty array of strings", v);
  std::vector<std::string> out;
  for (const json& x : v) {
    if (!x.is_string()) fail(key, "an array of strings", v);
    out.push_back(x.get<std::string>());
  }
  return out;
}

void SceneObject::finish() const {
  for (const auto& [key, ignored] : value_.items()) {
    if (asked_.count(key)) continue;
    std::string nearest;
    std::size_t best = 4;
    for (const std::string& k : asked_)
      if (const std::size_t d = edit_distance(key, k); d < best) best = d, nearest = k;
    throw InputError("scene " + source_ + ": unknown key '" + path(key) + "'" +
                     (nearest.empty() ? "" : " (did you mean '" + nearest + "'?)"));
  }
}

std::string SceneObject::path(const std::string& key) const {
  return where_.empty() ? key : key.empty() ? where_ : where_ + "." + key;
}

std::string SceneObject::describe(const json& v) {
  std::string text = v.dump();
  if (text.size() > 40) text = text.substr(0, 37) + "...";
  return std::string(v.type_name()) + " " + text;
}

}  // namespace vorodg
