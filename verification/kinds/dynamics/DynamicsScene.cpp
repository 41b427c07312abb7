#include "verification/kinds/dynamics/DynamicsScene.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <map>
#include <nlohmann/json.hpp>

#include "core/io/AtomicFile.hpp"
#include "core/util/Errors.hpp"
#include "core/util/Format.hpp"
#include "verification/harness/SceneObject.hpp"
#include "verification/harness/SceneVariants.hpp"
#include "verification/kinds/dynamics/DynamicsKeys.hpp"
#include "verification/kinds/dynamics/DynamicsSceneReader.hpp"
#include "verification/model/Choices.hpp"
#include "verification/model/SettingsSchema.hpp"

namespace vorodg {
namespace {

using nlohmann::json;

const std::map<std::string, DynamicsProblem>& problem_names() {
  static const std::map<std::string, DynamicsProblem> names = {
      {"wave-bar", DynamicsProblem::wave_bar},
      {"free-body", DynamicsProblem::free_body},
      {"wall-impact", DynamicsProblem::wall_impact},
      {"two-blocks", DynamicsProblem::two_blocks},
      {"strip-expansion", DynamicsProblem::strip_expansion},
      {"column-impact", DynamicsProblem::column_impact},
      {"projectile-impact", DynamicsProblem::projectile_impact}};
  return names;
}

std::array<Point, 4> corners(const Rectangle& r) {
  return {r.lo(), Point(r.x1(), r.y0()), r.hi(), Point(r.x0(), r.y1())};
}

}  // namespace

void DynamicsSceneReader::read_bodies() {
  const DynamicsProblem p = s_.problem;
  const bool bar = p == DynamicsProblem::wave_bar, free = p == DynamicsProblem::free_body;
  const bool strip = p == DynamicsProblem::strip_expansion;
  const bool column = p == DynamicsProblem::column_impact;
  const bool beam = p == DynamicsProblem::projectile_impact;
  DynamicsBody a;
  a.domain =
      rectangle(top_, "domain",
                bar      ? Rectangle(0, 0, 1, 0.05)
                : free   ? Rectangle(0, 0, 1, 1)
                : strip  ? Rectangle(0, 0, 0.002, 1e-5)
                : column ? Rectangle(0, 0, 0.3, 1.83)
                : beam   ? Rectangle(0, 0, 4.0, 0.3)
                         : Rectangle(0, 0, p == DynamicsProblem::wall_impact ? 0.4 : 0.2, 0.1));
  a.velocity = point(top_, "initial_velocity",
                     bar || strip || beam ? Point(0, 0)
                     : free               ? Point(1, 0.5)
                     : column             ? Point(0, -7.6)
                                          : Point(1, 0));
  a.angular_velocity = number(top_, "angular_velocity", free ? 1.0 : 0.0);
  s_.bodies = {a};
  refuse_unless(p == DynamicsProblem::two_blocks, "second_block");
  if (p != DynamicsProblem::two_blocks) return;
  SceneObject o = object("second_block");
  const double shift = 1.05 * a.domain.width();
  DynamicsBody b;
  b.domain = rectangle(
      o, "second_block.domain",
      Rectangle(a.domain.x0() + shift, a.domain.y0(), a.domain.x1() + shift, a.domain.y1()));
  b.velocity = point(o, "second_block.initial_velocity", -a.velocity);
  b.angular_velocity = number(o, "second_block.angular_velocity");
  const bool apart = b.domain.x0() >= a.domain.x1() || a.domain.x0() >= b.domain.x1() ||
                     b.domain.y0() >= a.domain.y1() || a.domain.y0() >= b.domain.y1();
  if (!apart)
    o.fail_value("domain", rect_text(b.domain) + " overlaps domain " + rect_text(a.domain) +
                               ": expected the blocks apart (touching at most)");
  o.finish();
  s_.bodies.push_back(b);
}

void DynamicsSceneReader::read_material() {
  SceneObject m = object("material");
  s_.E = number(m, "material.E");
  s_.nu = number(m, "material.nu");
  s_.plane = word(m, "material.plane", " stress strain ") == "stress" ? PlaneModel::stress
                                                                      : PlaneModel::strain;
  s_.density = number(m, "material.density");
  s_.mean_dilation = flag(m, "material.mean_dilation");
  s_.variation = number(m, "material.variation");
  s_.variation_seed = static_cast<std::uint64_t>(integer(m, "material.variation_seed"));
  m.finish();
  read_element();
  s_.damping = number(top_, "damping");
  s_.corotational = word(top_, "kinematics", " small corotational ") == "corotational";
}

void DynamicsSceneReader::read_element() {
  std::string allowed = " ";
  for (const NamedChoice& c : element_choices()) allowed += c.name + " ";
  s_.element.family = parse_element(word(top_, "element", allowed));
  s_.element.vem_stabilization = number(top_, "vem_stabilization");
}

void DynamicsSceneReader::read_wave_bar() {
  const bool bar = s_.problem == DynamicsProblem::wave_bar;
  refuse_unless(bar, "sides");
  refuse_unless(bar, "pulse");
  if (!bar) return;
  s_.rollers = word(top_, "sides", " free rollers ") == "rollers";
  SceneObject o = object("pulse");
  s_.pulse_amplitude = number(o, "pulse.amplitude");
  if (s_.pulse_amplitude == 0.0) o.fail_value("amplitude", "expected not 0, found 0");
  s_.pulse_duration =
      number(o, "pulse.duration", 0.9 * s_.bodies[0].domain.width() / s_.wave_speed());
  o.finish();
}

void DynamicsSceneReader::read_wall() {
  const bool impact = s_.hits_wall();
  if (!impact && !top_.has("wall")) {
    note("wall.point", "none");
    note("wall.normal", "none");
    return;
  }
  const DynamicsBody& body = s_.bodies[0];
  if (impact && body.velocity.norm() == 0.0)
    top_.fail_value("initial_velocity", "expected a nonzero velocity towards the wall");
  SceneObject o = object("wall");
  // The default wall touches the body's leading point and faces its velocity.
  const Point ahead = impact ? Point(body.velocity.normalized()) : Point(1, 0);
  const Point centre = 0.5 * (body.domain.lo() + body.domain.hi());
  const double reach = 0.5 * (std::abs(ahead.x()) * body.domain.width() +
                              std::abs(ahead.y()) * body.domain.height());
  const bool column = s_.problem == DynamicsProblem::column_impact;
  DynamicsWall w;
  w.point = point(o, "wall.point", column ? column_wall().point : Point(centre + reach * ahead));
  w.normal = point(o, "wall.normal", column ? column_wall().normal : Point(-ahead));
  if (w.normal.norm() == 0.0) o.fail_value("normal", "expected not [0, 0]");
  w.normal.normalize();
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
  s_.penalty.alpha = number(c, "contact.alpha");
  s_.penalty.damping_ratio = number(c, "contact.damping_ratio");
  c.finish();
}

void DynamicsSceneReader::default_end() {
  const DynamicsBody& a = s_.bodies[0];
  switch (s_.problem) {
    case DynamicsProblem::free_body: s_.steps = 1000; break;
    case DynamicsProblem::wave_bar: s_.end = 2.0 * a.domain.width() / s_.wave_speed(); break;
    case DynamicsProblem::wall_impact: {
      const Point n = s_.wall->normal;
      const double length =
          std::abs(n.x()) * a.domain.width() + std::abs(n.y()) * a.domain.height();
      double gap = 1e300;  // from the leading corner to the wall, at the approach speed
      for (const Point& c : corners(a.domain)) gap = std::min(gap, (c - s_.wall->point).dot(n));
      s_.end = gap / -a.velocity.dot(n) + 3.0 * 2.0 * length / s_.bar_speed();
      break;
    }
    case DynamicsProblem::column_impact: s_.end = 0.3; break;
    case DynamicsProblem::projectile_impact: s_.end = 3e-3; break;
    case DynamicsProblem::strip_expansion:
      s_.end = 20.0 * s_.criterion.tensile_cutoff / (s_.E * s_.strain_rate);
      break;
    case DynamicsProblem::two_blocks: {
      const Rectangle &d = a.domain, &e = s_.bodies[1].domain;
      const double gap = std::hypot(std::max({0.0, e.x0() - d.x1(), d.x0() - e.x1()}),
                                    std::max({0.0, e.y0() - d.y1(), d.y0() - e.y1()}));
      const double speed = (a.velocity - s_.bodies[1].velocity).norm();
      s_.end =
          (speed > 0.0 ? gap / speed : 0.0) + 6.0 * std::max(d.scale(), e.scale()) / s_.bar_speed();
      break;
    }
  }
  note("time.end", s_.end > 0.0 ? exact_text(s_.end) : "none (time.steps)");
  note("time.steps", s_.steps > 0 ? std::to_string(s_.steps) : "none (time.end)");
}

void DynamicsSceneReader::read_time() {
  SceneObject t = object("time");
  const bool end = t.has("end"), steps = t.has("steps");
  if (end && steps) t.fail_value("steps", "give time.end or time.steps, not both");
  if (end) s_.end = number(t, "time.end", 0.0), note("time.steps", "none (time.end)");
  if (steps) s_.steps = integer(t, "time.steps", 1), note("time.end", "none (time.steps)");
  if (!end && !steps) default_end();
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
  if (s_.fragmentation && s_.estimate == StepEstimate::lanczos)
    t.fail_value("estimate",
                 "'lanczos' holds for the uncracked map only: expected cells in a fragmentation "
                 "study (the cell bound holds for every crack pattern)");
  s_.output_every = integer(t, "time.output_every");
  s_.history_every = integer(t, "time.history_every");
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
}

DynamicsScene DynamicsSceneReader::read() {
  s_.name = top_.text("name", std::filesystem::path(source_).stem().string());
  s_.description = top_.text("description", "");
  s_.label = top_.text("label", "");
  s_.fragmentation = word(top_, "study", " dynamics fragmentation ") == "fragmentation";
  const std::string problem = word(top_, "problem",
                                   " wave-bar free-body wall-impact two-blocks strip-expansion "
                                   "column-impact projectile-impact ");
  s_.problem = problem_names().at(problem);
  if (s_.problem == DynamicsProblem::strip_expansion && !s_.fragmentation)
    top_.fail_value("problem", "'strip-expansion': expected study fragmentation");
  read_material();
  try {
    IsotropicElasticity(s_.E, s_.nu, s_.plane);
  } catch (const InputError& e) {
    throw InputError("scene " + source_ + ": material: " + e.what());
  }
  read_bodies();
  read_impact();
  read_wave_bar();
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
  return s_;
}

std::string dynamics_problem_name(DynamicsProblem p) {
  for (const auto& [name, value] : problem_names())
    if (value == p) return name;
  return "?";
}

std::string step_estimate_name(StepEstimate e) {
  return e == StepEstimate::lanczos ? "lanczos" : "cells";
}

double DynamicsScene::bar_speed() const {
  return std::sqrt(E / (density * (plane == PlaneModel::stress ? 1.0 : 1.0 - nu * nu)));
}

double DynamicsScene::dilatational_speed() const {
  if (plane == PlaneModel::stress) return std::sqrt(E / (density * (1.0 - nu * nu)));
  return std::sqrt(E * (1.0 - nu) / (density * (1.0 + nu) * (1.0 - 2.0 * nu)));
}

double DynamicsScene::wave_speed() const {
  return rollers ? dilatational_speed() : bar_speed();
}

bool DynamicsScene::hits_wall() const {
  return problem == DynamicsProblem::wall_impact || problem == DynamicsProblem::column_impact;
}

bool DynamicsScene::external_momentum() const {
  return wall || problem == DynamicsProblem::wave_bar || projectile || damping != 0.0 ||
         gravity != Eigen::Vector2d::Zero();
}

DynamicsScene parse_dynamics_scene(const std::string& text, const std::string& source, bool force) {
  const json root = parse_scene_json(text, source);
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

DynamicsScene read_dynamics_scene(const std::filesystem::path& path, bool force) {
  DynamicsScene s = parse_dynamics_scene(read_file(path), path.string(), force);
  s.path = path;
  for (DynamicsScene& v : s.variants) v.path = path;
  return s;
}

}  // namespace vorodg
