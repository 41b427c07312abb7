#include "verification/dynamics/DynamicsSceneReader.hpp"

#include <cmath>

#include "core/util/Errors.hpp"
#include "core/util/Format.hpp"
#include "verification/dynamics/DynamicsKeys.hpp"
#include "verification/model/SettingsSchema.hpp"

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
double DynamicsSceneReader::number(SceneObject& o, const std::string& full,
                                   std::optional<double> fallback) {
  const DynamicsKey& k = dynamics_key(full);
  const double v = o.number(leaf(full), fallback ? *fallback : key_default(k));
  if (const auto bad = check_key(k, v)) o.fail_value(leaf(full), *bad);
  note(full, exact_text(v));
  return v;
}

int DynamicsSceneReader::integer(SceneObject& o, const std::string& full,
                                 std::optional<int> fallback) {
  const DynamicsKey& k = dynamics_key(full);
  const int v = o.integer(leaf(full), fallback ? *fallback : static_cast<int>(key_default(k)));
  if (const auto bad = check_key(k, v)) o.fail_value(leaf(full), *bad);
  note(full, std::to_string(v));
  return v;
}

bool DynamicsSceneReader::flag(SceneObject& o, const std::string& full) {
  const bool v = o.flag(leaf(full), dynamics_key(full).fallback == "true");
  note(full, v ? "true" : "false");
  return v;
}

std::string DynamicsSceneReader::word(SceneObject& o, const std::string& full,
                                      const std::string& allowed,
                                      const std::optional<std::string>& fallback) {
  const DynamicsKey& k = dynamics_key(full);
  const std::string v = o.text(leaf(full), fallback ? *fallback : k.fallback);
  if (allowed.find(" " + v + " ") == std::string::npos)
    o.fail_value(leaf(full), "'" + v + "': expected " + k.range);
  note(full, v);
  return v;
}

Point DynamicsSceneReader::point(SceneObject& o, const std::string& full, const Point& fallback) {
  const std::vector<double> v = o.numbers(leaf(full), {fallback.x(), fallback.y()});
  if (v.size() != 2 || !std::isfinite(v[0]) || !std::isfinite(v[1]))
    o.fail_value(leaf(full), "expected two finite numbers " + dynamics_key(full).type);
  note(full, point_text({v[0], v[1]}));
  return {v[0], v[1]};
}

Rectangle DynamicsSceneReader::rectangle(SceneObject& o, const std::string& full,
                                         const Rectangle& fallback) {
  const std::vector<double> d =
      o.numbers(leaf(full), {fallback.x0(), fallback.y0(), fallback.x1(), fallback.y1()});
  if (d.size() != 4) o.fail_value(leaf(full), "expected four numbers [x0, y0, x1, y1]");
  try {
    const Rectangle r(d[0], d[1], d[2], d[3]);
    note(full, rect_text(r));
    return r;
  } catch (const InputError& e) {
    o.fail_value(leaf(full), e.what());
  }
}

void DynamicsSceneReader::refuse_unless(bool applies, const std::string& key) {
  if (!applies && top_.has(key))
    top_.fail_value(key, "not used by problem " + dynamics_problem_name(s_.problem));
}

}  // namespace vorodg
