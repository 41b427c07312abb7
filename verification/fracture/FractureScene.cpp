#include "verification/fracture/FractureScene.hpp"

#include <nlohmann/json.hpp>
#include <stdexcept>

#include "core/io/AtomicFile.hpp"
#include "core/util/Errors.hpp"
#include "core/util/Format.hpp"
#include "verification/model/Choices.hpp"
#include "verification/study/SceneObject.hpp"

namespace vorodg {
namespace {

using nlohmann::json;

SceneObject object_at(SceneObject& top, const std::string& key) {
  static const json empty = json::object();
  return SceneObject(top.has(key) ? top.at(key) : empty, key, top.source());
}

void read_material(SceneObject& top, FractureScene& s) {
  SceneObject m = object_at(top, "material");
  s.E = m.number("E", s.E);
  s.nu = m.number("nu", s.nu);
  const std::string plane = m.text("plane", "stress");
  if (plane != "stress" && plane != "strain")
    m.fail_value("plane", "'" + plane + "': expected stress or strain");
  s.plane = plane == "stress" ? PlaneModel::stress : PlaneModel::strain;
  s.thickness = m.number("thickness", s.thickness);
  if (!(s.thickness > 0)) m.fail_value("thickness", "expected > 0, found " + fmt(s.thickness));
  try {
    IsotropicElasticity(s.E, s.nu, s.plane);
  } catch (const InputError& e) {
    m.fail_value("E", e.what());
  }
  m.finish();
}

void read_cohesive(SceneObject& top, FractureScene& s) {
  SceneObject c = object_at(top, "cohesive");
  const std::string law = c.text("law", "linear");
  if (law != "linear" && law != "bilinear")
    c.fail_value("law", "'" + law + "': expected linear or bilinear");
  s.law.shape = law == "linear" ? SofteningShape::linear : SofteningShape::bilinear;
  s.law.strength = c.number("strength", 3.33e6);
  s.law.fracture_energy = c.number("fracture_energy", 124.0);
  s.law.shear_factor = c.number("shear_factor", 1.0);
  s.criterion.tensile_cutoff = c.number("tensile_cutoff", s.law.strength);
  s.criterion.cohesion = c.number("cohesion", s.law.strength);
  s.criterion.friction = c.number("friction", 0.75);
  s.initial_stiffness = c.number("initial_stiffness", s.initial_stiffness);
  if (!(s.initial_stiffness > 0))
    c.fail_value("initial_stiffness", "expected > 0, found " + fmt(s.initial_stiffness));
  try {  // the objects check their own parameters and name them
    CohesiveLaw{s.law};
    MohrCoulomb{s.criterion};
  } catch (const InputError& e) {
    throw InputError("scene " + top.source() + ": cohesive." + e.what());
  }
  c.finish();
}

/// loading.tail: a second stage of equal steps after the main one, in the control's measure.
void read_tail(SceneObject& loading, PathOptions& o) {
  SceneObject t = object_at(loading, "tail");
  const bool by_cmod = o.control == LoadControl::cmod;
  const std::string end_key = by_cmod ? "max_cmod" : "max_displacement";
  o.tail_end = t.number(end_key, 0.0);
  o.tail_steps = t.integer("steps", 10);
  const double main_end = by_cmod ? o.max_cmod : o.max_stroke;
  if (o.control == LoadControl::arc_length)
    t.fail_value(end_key, "a tail needs displacement or cmod control");
  if (!(o.tail_end > main_end))
    t.fail_value(end_key, "expected beyond the main stage's end " + fmt(main_end) + ", found " +
                              fmt(o.tail_end));
  if (o.tail_steps < 1) t.fail_value("steps", "expected >= 1");
  t.finish();
}

void read_cracking_and_loading(SceneObject& top, FractureScene& s) {
  SceneObject c = object_at(top, "cracking");
  try {
    s.mode = parse_cracking_mode(c.text("mode", "restricted"));
  } catch (const InputError& e) {
    c.fail_value("mode", e.what());
  }
  s.geometry.line_x = c.number("line", 0.5 * (s.geometry.domain.x0() + s.geometry.domain.x1()));
  s.split_all = c.flag("split_all", false);
  c.finish();
  SceneObject l = object_at(top, "loading");
  try {
    s.loading.control = parse_load_control(l.text("control", "displacement"));
  } catch (const InputError& e) {
    l.fail_value("control", e.what());
  }
  s.loading.max_stroke = l.number("max_displacement", 0.0);
  s.loading.max_cmod = l.number("max_cmod", 0.0);
  s.loading.steps = l.integer("steps", 100);
  if (s.loading.steps < 1) l.fail_value("steps", "expected >= 1");
  if (s.loading.max_stroke < 0) l.fail_value("max_displacement", "expected >= 0");
  if (s.loading.max_cmod < 0) l.fail_value("max_cmod", "expected >= 0");
  if (l.has("tail")) read_tail(l, s.loading);
  l.finish();
}

/// The element family of every run (RK unless `element` names another), as in a study scene's
/// formulations.
void read_element(SceneObject& top, FractureScene& s) {
  const std::string name = top.text("element", element_name(s.element.family));
  try {
    s.element.family = parse_element(name);
  } catch (const std::invalid_argument& e) {  // the choices' own "'x': expected ..." message
    top.fail_value("element", e.what());
  }
  s.element.vem_stabilization = top.number("vem_stabilization", s.element.vem_stabilization);
  if (!(s.element.vem_stabilization > 0.0)) top.fail_value("vem_stabilization", "expected > 0");
}

FractureScene parse_one(const json& root, const std::string& source) {
  SceneObject top(root, "", source);
  FractureScene s;
  s.name = top.text("name", std::filesystem::path(source).stem().string());
  s.description = top.text("description", "");
  s.label = top.text("label", "");
  top.text("study", "fracture");
  try {
    s.geometry.kind = parse_fracture_problem(top.text("problem", "three-point-bend"));
  } catch (const InputError& e) {
    top.fail_value("problem", e.what());
  }
  const std::vector<double> d = top.numbers("domain", {0.0, 0.0, 2.0, 0.2});
  if (d.size() != 4) top.fail_value("domain", "expected four numbers [x0, y0, x1, y1]");
  try {
    s.geometry.domain = Rectangle(d[0], d[1], d[2], d[3]);
  } catch (const InputError& e) {
    top.fail_value("domain", e.what());
  }
  s.geometry.notch_depth = top.number("notch_depth", 0.0);
  read_element(top, s);
  read_material(top, s);
  read_cohesive(top, s);
  read_cracking_and_loading(top, s);
  try {
    check_fracture_geometry(s.geometry);
  } catch (const InputError& e) {
    throw InputError("scene " + source + ": " + e.what());
  }
  const json& meshes = top.at("meshes");
  if (!meshes.is_array() || meshes.empty())
    top.fail("meshes", "a non-empty array of mesh objects", meshes);
  for (std::size_t i = 0; i < meshes.size(); ++i) {
    SceneObject m(meshes[i], "meshes[" + std::to_string(i) + "]", source);
    s.meshes.push_back(read_mesh(m, s.geometry.domain));
  }
  SceneObject outputs = object_at(top, "outputs");
  s.vtu_every = outputs.integer("vtu_every", s.vtu_every);
  if (s.vtu_every < 0) outputs.fail_value("vtu_every", "expected >= 0");
  outputs.finish();
  top.finish();
  return s;
}

}  // namespace

FractureScene parse_fracture_scene(const std::string& text, const std::string& source) {
  json root;
  try {
    root = json::parse(text);
  } catch (const json::exception& e) {
    throw InputError("scene " + source + ": not valid JSON (" + std::string(e.what()) + ")");
  }
  if (!root.is_object()) throw InputError("scene " + source + ": expected a JSON object");
  if (!root.contains("variants")) return parse_one(root, source);
  json base = root;
  base.erase("variants");
  const json& list = root["variants"];
  if (!list.is_array() || list.empty())
    throw InputError("scene " + source + ": variants: expected a non-empty array of objects");
  FractureScene top = parse_one(base, source);
  for (std::size_t i = 0; i < list.size(); ++i) {
    if (!list[i].is_object() || !list[i].contains("label"))
      throw InputError("scene " + source + ": variants[" + std::to_string(i) +
                       "]: expected an object with a label");
    json merged = base;
    merged.merge_patch(list[i]);
    top.variants.push_back(parse_one(merged, source + " variants[" + std::to_string(i) + "]"));
    top.variants.back().name = top.name;
  }
  return top;
}

bool is_fracture_scene(const std::filesystem::path& path) {
  return scene_study_kind(path) == "fracture";
}

FractureScene read_fracture_scene(const std::filesystem::path& path) {
  FractureScene s = parse_fracture_scene(read_file(path), path.string());
  s.path = path;
  for (FractureScene& v : s.variants) v.path = path;
  return s;
}

}  // namespace vorodg
