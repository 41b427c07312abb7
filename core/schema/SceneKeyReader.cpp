#include "core/schema/SceneKeyReader.hpp"

#include <cmath>
#include <iostream>
#include <sstream>

#include "core/util/Errors.hpp"
#include "core/util/Format.hpp"

namespace vorodg {

std::string vector_text(std::initializer_list<double> v) {
  std::string out = "[";
  for (double x : v) out.append(out.size() > 1 ? ", " : "").append(exact_text(x + 0.0));  // no -0
  return out.append("]");
}

std::string point_text(const Point& p) {
  return vector_text({p.x(), p.y()});
}

std::string rect_text(const Rectangle& r) {
  return vector_text({r.x0(), r.y0(), r.x1(), r.y1()});
}

SceneKeyReader::SceneKeyReader(const KeyTable& table, const nlohmann::json& root,
                               const std::string& source)
    : table_(table), source_(source), top_(root, "", source) {
  for (const auto& [old_name, new_name] : table.renamed) {
    const nlohmann::json* at = &root;
    std::istringstream parts(old_name);
    for (std::string part; at && std::getline(parts, part, '.');)  // walk "a.b" down the objects
      at = at->is_object() && at->contains(part) ? &at->at(part) : nullptr;
    if (at)
      throw InputError("scene " + source + ": " + old_name + ": this key is now spelled " +
                       new_name);
  }
}

double checked_number(SceneObject& o, const std::string& name, const SceneKey& key,
                      double fallback) {
  const double value = o.number(name, fallback);
  if (const auto bad = check_key(key, value)) o.fail_value(name, *bad);
  return value;
}

void echo_settings(const std::vector<std::pair<std::string, std::string>>& settings) {
  for (const auto& [key, value] : settings) std::cout << "#   " << key << " = " << value << "\n";
}

std::vector<std::pair<std::string, std::string>> SceneKeyReader::settings() const {
  std::vector<std::pair<std::string, std::string>> used;
  for (const SceneKey& k : table_.keys)
    if (notes_.count(k.name)) used.emplace_back(k.name, notes_.at(k.name));
  return used;
}

SceneObject SceneKeyReader::object(const std::string& key) {
  static const nlohmann::json empty = nlohmann::json::object();
  return SceneObject(top_.has(key) ? top_.at(key) : empty, key, source_);
}

double SceneKeyReader::number(SceneObject& o, const std::string& full,
                              std::optional<double> fallback) {
  const SceneKey& k = table_.at(full);
  const double v = o.number(leaf(full), fallback ? *fallback : key_default(k));
  if (const auto bad = check_key(k, v)) o.fail_value(leaf(full), *bad);
  note(full, exact_text(v));
  return v;
}

int SceneKeyReader::integer(SceneObject& o, const std::string& full, std::optional<int> fallback) {
  const SceneKey& k = table_.at(full);
  const int v = o.integer(leaf(full), fallback ? *fallback : static_cast<int>(key_default(k)));
  if (const auto bad = check_key(k, v)) o.fail_value(leaf(full), *bad);
  note(full, std::to_string(v));
  return v;
}

bool SceneKeyReader::flag(SceneObject& o, const std::string& full, std::optional<bool> fallback) {
  const bool v = o.flag(leaf(full), fallback ? *fallback : table_.at(full).fallback == "true");
  note(full, v ? "true" : "false");
  return v;
}

std::string SceneKeyReader::word(SceneObject& o, const std::string& full,
                                 const std::string& allowed,
                                 const std::optional<std::string>& fallback) {
  const SceneKey& k = table_.at(full);
  const std::string v = o.text(leaf(full), fallback ? *fallback : k.fallback);
  if (allowed.find(" " + v + " ") == std::string::npos)
    o.fail_value(leaf(full), "'" + v + "': expected " + k.range);
  note(full, v);
  return v;
}

Point SceneKeyReader::point(SceneObject& o, const std::string& full, const Point& fallback) {
  const std::vector<double> v = o.numbers(leaf(full), {fallback.x(), fallback.y()});
  const SceneKey& k = table_.at(full);
  if (v.size() != 2 || !std::isfinite(v[0]) || !std::isfinite(v[1]))
    o.fail_value(leaf(full), "expected two finite numbers " + k.type);
  for (double x : v)  // each component within the key's bounds
    if (const auto bad = check_key(k, x)) o.fail_value(leaf(full), *bad);
  note(full, point_text({v[0], v[1]}));
  return {v[0], v[1]};
}

Rectangle SceneKeyReader::rectangle(SceneObject& o, const std::string& full,
                                    const Rectangle& fallback) {
  const std::vector<double> d =
      o.numbers(leaf(full), {fallback.x0(), fallback.y0(), fallback.x1(), fallback.y1()});
  if (d.size() != 4) o.fail_value(leaf(full), "expected four numbers [x0, y0, x1, y1]");
  for (double x : d)
    if (!(std::abs(x) <= kCoordinateLimit))
      o.fail_value(leaf(full), "expected " + std::string(kRectangleRange) + ", found " + fmt(x));
  try {
    const Rectangle r(d[0], d[1], d[2], d[3]);
    note(full, rect_text(r));
    return r;
  } catch (const InputError& e) {
    o.fail_value(leaf(full), e.what());
  }
}

}  // namespace vorodg
