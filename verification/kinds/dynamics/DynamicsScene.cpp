#include "verification/kinds/dynamics/DynamicsScene.hpp"

#include <algorithm>
#include <cmath>
#include <nlohmann/json.hpp>
#include <stdexcept>

#include "core/io/AtomicFile.hpp"
#include "core/schema/SceneObject.hpp"
#include "core/util/Errors.hpp"
#include "core/util/Format.hpp"
#include "dynamics/contact/ContactLaws.hpp"
#include "verification/harness/SceneVariants.hpp"
#include "verification/kinds/dynamics/DynamicsKeys.hpp"
#include "verification/kinds/dynamics/DynamicsMeasureFields.hpp"
#include "verification/kinds/dynamics/DynamicsSceneReader.hpp"
#include "verification/model/Choices.hpp"
#include "verification/model/MaterialFieldKeys.hpp"
#include "verification/solve/SettingsSchema.hpp"

namespace vorodg {
namespace {

using nlohmann::json;

/// The problems' names as the reader's list of accepted words: " a b c ".
std::string problem_words() {
  std::string words = " ";
  for (const std::unique_ptr<DynamicsProblem>& p : dynamics_problems()) words += p->name() + " ";
  return words;
}

/// " exact-plane penalty-plane ... ": the contact laws a wall (obstacle) or the surface cells
/// can have, for word().
std::string contact_law_words(bool obstacle) {
  std::string words = " ";
  for (const ContactLawEntry& e : contact_laws())
    if (e.obstacle == obstacle) words += e.name + " ";
  return words;
}

}  // namespace

void DynamicsSceneReader::read_problem() {
  const std::string name = word(top_, "problem", problem_words());
  problem_ = make_dynamics_problem(name);
  if (problem_->needs_fragmentation() && !s_.fragmentation)
    top_.fail_value("problem", "'" + name + "': expected study fragmentation");
  const std::vector<std::string> own = problem_->own_keys();
  for (const std::unique_ptr<DynamicsProblem>& other : dynamics_problems())
    for (const std::string& key : other->own_keys())
      if (top_.has(key) && std::find(own.begin(), own.end(), key) == own.end())
        top_.fail_value(key, "not used by problem " + name);
}

void DynamicsSceneReader::read_body() {
  DynamicsBody a;
  a.domain = rectangle(top_, "domain", problem_->default_domain());
  a.velocity = point(top_, "initial_velocity", problem_->default_velocity());
  a.angular_velocity = number(top_, "angular_velocity", problem_->default_angular_velocity());
  s_.bodies = {a};
  s_.gravity = point(top_, "gravity", problem_->default_gravity());
}

void DynamicsSceneReader::read_material() {
  SceneObject m = object("material");
  s_.E = number(m, "material.E");
  s_.nu = number(m, "material.nu");
  s_.plane = word(m, "material.plane", " stress strain ") == "stress" ? PlaneModel::stress
                                                                      : PlaneModel::strain;
  s_.density = number(m, "material.density");
  if (m.has("thickness") && !problem_->uses_thickness())
    m.fail_value("thickness", "not used by problem " + problem_->name() +
                                  " (its forces and energies are per unit thickness)");
  s_.thickness = number(m, "material.thickness");
  s_.mean_dilation = flag(m, "material.mean_dilation");
  s_.variation = number(m, "material.variation");
  s_.variation_seed = static_cast<std::uint64_t>(integer(m, "material.variation_seed"));
  s_.field = read_material_field(*this, m);
  if (s_.field.enabled && s_.variation > 0.0)
    m.fail_value("field", "beside material.variation " + exact_text(s_.variation) +
                              ": expected one way of varying the material");
  m.finish();
  read_element();
  s_.damping = number(top_, "damping");
  SceneObject bulk = object("bulk_viscosity");
  const ContactDefaults defaults = problem_->default_contact();
  s_.bulk_viscosity.linear = number(bulk, "bulk_viscosity.linear", defaults.bulk_linear);
  s_.bulk_viscosity.quadratic = number(bulk, "bulk_viscosity.quadratic", defaults.bulk_quadratic);
  bulk.finish();
  // The report's second approach: interfaces in the equations from the start, activated by the
  // criterion in a fragmentation study; only for linear cells of one material (the blocks use
  // the integrator's, unvaried, in the reference configuration).
  s_.dg_interfaces = word(top_, "interfaces", " insertion dg ") == "dg";
  if (s_.dg_interfaces && (s_.variation > 0.0 || s_.field.enabled))
    top_.fail_value("interfaces",
                    std::string("'dg' beside ") +
                        (s_.field.enabled ? "material.field"
                                          : "material.variation " + exact_text(s_.variation)) +
                        ": expected a uniform material");
  // Fragments spin: a fragmentation study turns its cells' frames by default.
  s_.corotational = word(top_, "kinematics", " small corotational ",
                         s_.fragmentation ? "corotational" : "small") == "corotational";
  if (s_.dg_interfaces && s_.corotational)
    top_.fail_value("interfaces",
                    "'dg' with kinematics corotational: expected small (the "
                    "interface terms are linear)");
}

void DynamicsSceneReader::read_element() {
  std::string allowed = " ";
  for (const NamedChoice& c : element_choices()) allowed += c.name + " ";
  s_.element.family = parse_element(word(top_, "element", allowed));
  s_.element.vem_stabilization = number(top_, "vem_stabilization");
}

void DynamicsSceneReader::read_wall() {
  const bool impact = problem_->hits_wall();
  if (!impact && !top_.has("wall")) {
    note("wall.point", "none");
    note("wall.normal", "none");
    note("wall.law", "none");
    note("wall.friction", "none");
    return;
  }
  const DynamicsBody& body = s_.bodies[0];
  if (impact && body.velocity.norm() == 0.0)
    top_.fail_value("initial_velocity", "expected a nonzero velocity towards the wall");
  SceneObject o = object("wall");
  const DynamicsWall fallback = problem_->default_wall(s_);
  DynamicsWall w;
  w.point = point(o, "wall.point", fallback.point);
  w.normal = point(o, "wall.normal", fallback.normal);
  if (w.normal.norm() == 0.0) o.fail_value("normal", "expected not [0, 0]");
  w.normal.normalize();
  w.law = word(o, "wall.law", contact_law_words(true));
  w.friction = number(o, "wall.friction", problem_->default_contact().wall_friction);
  o.finish();
  const double tolerance = 1e-12 * body.domain.scale();
  for (const DynamicsBody& b : s_.bodies)
    for (const Point& c : corners(b.domain))
      if (const double gap = (c - w.point).dot(w.normal); gap < -tolerance)
        top_.fail_value("wall", "the plane through " + point_text(w.point) + " with normal " +
                                    point_text(w.normal) + " cuts the body at t = 0: corner " +
                                    point_text(c) + " lies " + fmt(-gap) +
                                    " behind it (expected every body on its free side)");
  if (impact && !(body.velocity.dot(w.normal) < 0.0))
    top_.fail_value("initial_velocity", point_text(body.velocity) +
                                            ": expected a velocity towards the wall (against "
                                            "its normal " +
                                            point_text(w.normal) + ")");
  s_.wall = w;
}

void DynamicsSceneReader::read_contact() {
  SceneObject c = object("contact");
  s_.contact = flag(c, "contact.enabled");
  s_.contact_law = word(c, "contact.law", contact_law_words(false));
  s_.penalty.alpha = number(c, "contact.alpha");
  s_.penalty.damping_ratio = number(c, "contact.damping_ratio");
  const ContactDefaults defaults = problem_->default_contact();
  // The problem's velocity penalty unless the scene damps contact; its displacement penalty
  // where there is a resting weight to hold.
  s_.penalty.plastic =
      flag(c, "contact.plastic", defaults.plastic && s_.penalty.damping_ratio == 0.0);
  s_.contact_friction = number(c, "contact.friction", defaults.friction);
  const bool resting = s_.wall && std::abs(s_.gravity.dot(s_.wall->normal)) > 0.0;
  s_.quiescent_penetration =
      number(c, "contact.quiescent_penetration", resting ? defaults.quiescent_penetration : 0.0);
  if (s_.quiescent_penetration > 0.0 &&
      !(s_.wall && std::abs(s_.gravity.dot(s_.wall->normal)) > 0.0))
    c.fail_value("quiescent_penetration",
                 exact_text(s_.quiescent_penetration) +
                     ": expected a wall and gravity towards it (the resting weight sets the "
                     "stiffness)");
  if (s_.penalty.plastic && s_.penalty.damping_ratio > 0.0)
    c.fail_value("plastic", "true beside damping_ratio " + exact_text(s_.penalty.damping_ratio) +
                                ": expected one velocity penalty, not both");
  c.finish();
}

void DynamicsSceneReader::read_time() {
  SceneObject t = object("time");
  const bool end = t.has("end"), steps = t.has("steps");
  if (end && steps) t.fail_value("steps", "give time.end or time.steps, not both");
  if (end) s_.end = number(t, "time.end", 0.0), note("time.steps", "none (time.end)");
  if (steps) s_.steps = integer(t, "time.steps", 1), note("time.end", "none (time.steps)");
  if (!end && !steps) {  // the problem's rough length
    problem_->default_length(s_);
    note("time.end", s_.end > 0.0 ? exact_text(s_.end) : "none (time.steps)");
    note("time.steps", s_.steps > 0 ? std::to_string(s_.steps) : "none (time.end)");
  }
  const SceneKey& safety = table_.at("time.safety");
  s_.safety = t.number("safety", key_default(safety));
  if (const auto bad = check_key(safety, s_.safety)) t.fail_value("safety", *bad);
  if (s_.safety >= 1.0 && !force_)
    t.fail_value("safety", "expected < 1, found " + fmt(s_.safety) +
                               " (the run may blow up; --force allows it)");
  note("time.safety", exact_text(s_.safety));
  s_.estimate =
      word(t, "time.estimate", " lanczos cells ", s_.fragmentation ? "cells" : "lanczos") == "cells"
          ? StepEstimate::cells
          : StepEstimate::lanczos;
  if (s_.fragmentation && s_.dg_interfaces && s_.estimate == StepEstimate::lanczos)
    t.fail_value("estimate",
                 "'lanczos' holds for the uncracked map only with interfaces: dg: expected cells "
                 "(the cell bound holds for every crack pattern)");
  s_.output_every = integer(t, "time.output_every");
  s_.history_every = integer(t, "time.history_every");
  read_refinement(t);
  t.finish();
  SceneObject o = object("outputs");
  s_.vtu = flag(o, "outputs.vtu");
  s_.snapshots = o.numbers("snapshots", {});
  std::string listed;
  for (std::size_t i = 0; i < s_.snapshots.size(); ++i) {
    const double t = s_.snapshots[i];
    if (!std::isfinite(t) || t < 0.0 || (i > 0 && !(t > s_.snapshots[i - 1])))
      o.fail_value("snapshots", "expected ascending times >= 0, found " + fmt(t) + " at [" +
                                    std::to_string(i) + "]");
    listed += (listed.empty() ? "" : ", ") + exact_text(t);
  }
  note("outputs.snapshots", listed.empty() ? "none" : "[" + listed + "]");
  o.finish();
  s_.checkpoint = read_checkpoint_policy(*this);
  std::vector<std::string> measures;
  for (const auto& [name, member] : dynamics_measure_fields()) measures.push_back(name);
  s_.statistics = read_statistical_settings(*this, measures, s_.field.enabled);
}

void DynamicsSceneReader::read_refinement(SceneObject& t) {
  s_.refinement = t.numbers("refinement", {});
  std::string listed;
  for (std::size_t i = 0; i < s_.refinement.size(); ++i) {
    const double f = s_.refinement[i];
    if (!(f > 0.0 && f <= 1.0) || (i > 0 && !(f < s_.refinement[i - 1])))
      t.fail_value("refinement", "expected descending fractions in (0, 1], found " + fmt(f) +
                                     " at [" + std::to_string(i) + "]");
    listed += (listed.empty() ? "" : ", ") + exact_text(f);
  }
  if (s_.refinement.size() == 1)
    t.fail_value("refinement", "expected two or more fractions of the step, found one");
  note("time.refinement", listed.empty() ? "none" : "[" + listed + "]");
}

DynamicsScene DynamicsSceneReader::read() {
  s_.name = top_.text("name", std::filesystem::path(source_).stem().string());
  s_.description = top_.text("description", "");
  s_.label = top_.text("label", "");
  s_.fragmentation = word(top_, "study", " dynamics fragmentation ") == "fragmentation";
  read_problem();
  read_material();
  try {
    IsotropicElasticity(s_.E, s_.nu, s_.plane);
  } catch (const InputError& e) {
    throw InputError("scene " + source_ + ": material: " + e.what());
  }
  read_body();
  problem_->read(*this, s_);
  read_wall();
  read_contact();
  read_fracture();
  read_time();
  const json& meshes = top_.at("meshes");
  if (!meshes.is_array() || meshes.empty())
    top_.fail("meshes", "a non-empty array of mesh objects", meshes);
  for (std::size_t i = 0; i < meshes.size(); ++i) {
    SceneObject m(meshes[i], "meshes[" + std::to_string(i) + "]", source_);
    s_.meshes.push_back(read_mesh(m, s_.bodies[0].domain));
  }
  top_.finish();
  s_.settings = settings();
  s_.problem = std::move(problem_);
  return s_;
}

const std::string& DynamicsScene::setting(const std::string& key) const {
  for (const auto& [name, value] : settings)
    if (name == key) return value;
  throw std::out_of_range("dynamics scene: no setting " + key);
}

namespace {

DynamicsScene parse_parts(const json& root, const std::string& source, bool force) {
  if (root.contains("perturb")) return perturbed_scene(root, source, force);
  if (!root.contains("variants")) return DynamicsSceneReader(root, source, force).read();
  json base;
  const std::vector<SceneVariant> variants = scene_variants(root, source, base);
  DynamicsScene top = DynamicsSceneReader(base, source, force).read();
  for (const SceneVariant& v : variants) {
    top.variants.push_back(DynamicsSceneReader(v.root, v.source, force).read());
    top.variants.back().name = top.name;
  }
  return top;
}

}  // namespace

DynamicsScene parse_dynamics_scene(const std::string& text, const std::string& source, bool force) {
  DynamicsScene top = parse_parts(parse_scene_json(text, source), source, force);
  return top.refinement.empty() &&
                 std::none_of(top.variants.begin(), top.variants.end(),
                              [](const DynamicsScene& v) { return !v.refinement.empty(); })
             ? top
             : refined_scene(std::move(top), source);
}

DynamicsScene read_dynamics_scene(const std::filesystem::path& path, bool force) {
  DynamicsScene s = parse_dynamics_scene(read_file(path), path.string(), force);
  s.path = path;
  for (DynamicsScene& v : s.variants) v.path = path;
  return s;
}

}  // namespace vorodg
