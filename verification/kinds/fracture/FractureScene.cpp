#include "verification/kinds/fracture/FractureScene.hpp"

#include <nlohmann/json.hpp>
#include <stdexcept>

#include "core/io/AtomicFile.hpp"
#include "core/schema/SceneKeyReader.hpp"
#include "core/util/Errors.hpp"
#include "core/util/Format.hpp"
#include "fracture/SofteningLaws.hpp"
#include "verification/harness/SceneVariants.hpp"
#include "verification/kinds/fracture/FractureKeys.hpp"
#include "verification/kinds/fracture/FractureRun.hpp"
#include "verification/model/Choices.hpp"
#include "verification/model/MaterialFieldKeys.hpp"

namespace vorodg {
namespace {

using nlohmann::json;

/// Reads one fracture scene (a variant's keys merged already) against its key table.
class FractureSceneReader : public SceneKeyReader {
 public:
  FractureSceneReader(const json& root, const std::string& source)
      : SceneKeyReader(fracture_scene_keys(), root, source) {}

  FractureScene read() {
    s_.name = top_.text("name", std::filesystem::path(source_).stem().string());
    s_.description = top_.text("description", "");
    s_.label = top_.text("label", "");
    word(top_, "study", " fracture ");
    read_geometry();
    read_element();
    read_material();
    read_cohesive();
    read_cracking();
    read_loading();
    try {
      check_fracture_geometry(s_.geometry);
    } catch (const InputError& e) {
      throw InputError("scene " + source_ + ": " + e.what());
    }
    read_meshes();
    SceneObject outputs = object("outputs");
    s_.vtu_every = integer(outputs, "outputs.vtu_every");
    outputs.finish();
    s_.checkpoint = read_checkpoint_policy(*this);
    s_.statistics = read_statistical_settings(*this, fracture_record_numbers(), s_.field.enabled);
    top_.finish();
    s_.settings = settings();
    return s_;
  }

 private:
  void read_geometry() {
    try {
      s_.geometry.problem = fracture_problem(word(top_, "problem", fracture_problem_words()));
    } catch (const InputError& e) {
      top_.fail_value("problem", e.what());
    }
    s_.geometry.domain = rectangle(top_, "domain", Rectangle(0.0, 0.0, 2.0, 0.2));
    s_.geometry.notch_depth = number(top_, "notch_depth");
  }

  /// The element family of every run, as in a study scene's formulations.
  void read_element() {
    std::string allowed = " ";
    for (const NamedChoice& c : element_choices()) allowed += c.name + " ";
    s_.element.family = parse_element(word(top_, "element", allowed));
    s_.element.vem_stabilization = number(top_, "vem_stabilization");
  }

  void read_material() {
    SceneObject m = object("material");
    s_.E = number(m, "material.E");
    s_.nu = number(m, "material.nu");
    s_.plane = parse_plane(word(m, "material.plane", " stress strain "));
    s_.thickness = number(m, "material.thickness");
    try {
      IsotropicElasticity(s_.E, s_.nu, s_.plane);
    } catch (const InputError& e) {
      m.fail_value("E", e.what());
    }
    s_.field = read_material_field(*this, m);
    m.finish();
  }

  void read_cohesive() {
    SceneObject c = object("cohesive");
    s_.law.shape = word(c, "cohesive.law", softening_law_words());
    s_.law.strength = number(c, "cohesive.strength");
    s_.law.fracture_energy = number(c, "cohesive.fracture_energy");
    s_.law.shear_factor = number(c, "cohesive.shear_factor");
    s_.initial_stiffness = number(c, "cohesive.initial_stiffness");
    c.finish();
    SceneObject k = object("criterion");  // its cohesion and cutoff default to the strength
    s_.criterion.tensile_cutoff = number(k, "criterion.tensile_cutoff", s_.law.strength);
    s_.criterion.cohesion = number(k, "criterion.cohesion", s_.law.strength);
    s_.criterion.friction = number(k, "criterion.friction");
    k.finish();
    try {  // the objects check their own parameters and name them
      CohesiveLaw{s_.law};
      MohrCoulomb{s_.criterion};
    } catch (const InputError& e) {
      throw InputError("scene " + source_ + ": cohesive." + e.what());
    }
  }

  void read_cracking() {
    SceneObject c = object("cracking");
    s_.mode = parse_cracking_mode(
        word(c, "cracking.mode", " pre-inserted restricted contiguous arbitrary "));
    const Rectangle& d = s_.geometry.domain;
    s_.geometry.line_x = number(c, "cracking.line", 0.5 * (d.x0() + d.x1()));
    s_.split_all = flag(c, "cracking.split_all");
    c.finish();
  }

  void read_loading() {
    SceneObject l = object("loading");
    s_.loading.control =
        parse_load_control(word(l, "loading.control", " displacement cmod arc-length "));
    s_.loading.max_stroke = number(l, "loading.max_displacement");
    s_.loading.max_cmod = number(l, "loading.max_cmod");
    s_.loading.steps = integer(l, "loading.steps");
    if (l.has("tail")) read_tail(l);
    l.finish();
  }

  /// loading.tail: a second stage of equal steps after the main one, in the control's measure.
  void read_tail(SceneObject& loading) {
    static const json empty = json::object();
    SceneObject t(loading.at("tail"), "loading.tail", source_);
    PathOptions& o = s_.loading;
    const bool by_cmod = o.control == LoadControl::cmod;
    const std::string end_key = by_cmod ? "max_cmod" : "max_displacement";
    if (o.control == LoadControl::arc_length)
      t.fail_value(end_key, "a tail needs displacement or cmod control");
    o.tail_end = number(t, "loading.tail." + end_key, 0.0);
    o.tail_steps = integer(t, "loading.tail.steps");
    const double main_end = by_cmod ? o.max_cmod : o.max_stroke;
    if (!(o.tail_end > main_end))
      t.fail_value(end_key, "expected beyond the main stage's end " + fmt(main_end) + ", found " +
                                fmt(o.tail_end));
    t.finish();
  }

  void read_meshes() {
    const json& meshes = top_.at("meshes");
    if (!meshes.is_array() || meshes.empty())
      top_.fail("meshes", "a non-empty array of mesh objects", meshes);
    for (std::size_t i = 0; i < meshes.size(); ++i) {
      SceneObject m(meshes[i], "meshes[" + std::to_string(i) + "]", source_);
      s_.meshes.push_back(read_mesh(m, s_.geometry.domain));
    }
  }

  FractureScene s_;
};

}  // namespace

FractureScene parse_fracture_scene(const std::string& text, const std::string& source) {
  const json root = parse_scene_json(text, source);
  if (!root.contains("variants")) return FractureSceneReader(root, source).read();
  json base;
  const std::vector<SceneVariant> variants = scene_variants(root, source, base);
  FractureScene top = FractureSceneReader(base, source).read();
  for (const SceneVariant& v : variants) {
    top.variants.push_back(FractureSceneReader(v.root, v.source).read());
    top.variants.back().name = top.name;
  }
  return top;
}

FractureScene read_fracture_scene(const std::filesystem::path& path) {
  FractureScene s = parse_fracture_scene(read_file(path), path.string());
  s.path = path;
  for (FractureScene& v : s.variants) v.path = path;
  return s;
}

}  // namespace vorodg
