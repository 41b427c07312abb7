#include "verification/kinds/dynamics/DynamicsKeys.hpp"

#include <cmath>
#include <stdexcept>

#include "core/element/ElementTable.hpp"
#include "core/material/MaterialKeys.hpp"
#include "core/schema/SceneKeyReader.hpp"
#include "core/util/Format.hpp"
#include "dynamics/contact/ContactLaws.hpp"
#include "dynamics/problems/DynamicsProblem.hpp"
#include "fracture/CohesiveKeys.hpp"
#include "verification/harness/CommonKeys.hpp"
#include "verification/harness/StatisticalReport.hpp"
#include "verification/model/Choices.hpp"
#include "verification/model/ElementKeys.hpp"
#include "verification/model/MaterialFieldKeys.hpp"
#include "verification/solve/SettingsSchema.hpp"

namespace vorodg {
namespace {

/// The problems' names: "a, b; c (fragmentation)".
std::string problem_names() {
  std::string both, fragmentation;
  for (const std::unique_ptr<DynamicsProblem>& p : dynamics_problems()) {
    std::string& list = p->needs_fragmentation() ? fragmentation : both;
    list += (list.empty() ? "" : ", ") + p->name();
  }
  return both + (fragmentation.empty() ? "" : "; " + fragmentation + " (fragmentation)");
}

/// The default of a contact or cell-damping key, per problem (DynamicsProblem::default_contact).
std::string contact_default(const std::function<std::string(const ContactDefaults&)>& text) {
  return per_problem_text([&](const DynamicsProblem& p) { return text(p.default_contact()); });
}

/// The keys only one problem reads, each problem's rows in the problems' order.
std::vector<SceneKey> dynamics_problem_keys() {
  std::vector<SceneKey> keys;
  for (const std::unique_ptr<DynamicsProblem>& p : dynamics_problems())
    append_keys(keys, p->keys());
  return keys;
}

/// The study, the problem and the body it is about.
std::vector<SceneKey> dynamics_study_keys() {
  return {
      key("study", "string", "dynamics", "dynamics or fragmentation",
          "the study kind: fragmentation adds crack insertion and the cohesive keys "
          "(docs/fragmentation.md)"),
      key("problem", "string", dynamics_problems().front()->name(), problem_names(),
          "what is thrown, struck or stretched (docs/dynamics.md, \"Problems\")"),
      key("domain", "[x0, y0, x1, y1]",
          per_problem_text([](const DynamicsProblem& p) { return rect_text(p.default_domain()); }),
          kRectangleRange, "the (first) body, in m"),
  };
}

/// How the (first) body is thrown.
std::vector<SceneKey> body_keys() {
  return {
      bounded("initial_velocity", "[vx, vy]", per_problem_text([](const DynamicsProblem& p) {
                return point_text(p.default_velocity());
              }),
              "each |component| <= 1e4", "uniform velocity of the (first) body at t = 0, m/s", -1e4,
              false, 1e4),
      bounded("angular_velocity", "number", per_problem_text([](const DynamicsProblem& p) {
                return exact_text(p.default_angular_velocity());
              }),
              "|omega| <= 1e6",
              "spin of the (first) body about its centre of mass at t = 0, rad/s (small strain: "
              "the spin is the linearized rotation)",
              -1e6, false, 1e6),
  };
}

/// The material beyond its elastic constants, and damping.
std::vector<SceneKey> material_keys() {
  return {
      bounded("material.density", "number", "7800", "0 < density <= 1e5", "mass density, kg/m^3",
              0.0, true, 1e5),
      bounded("material.thickness", "number", "1", "0 < thickness <= 1000 (three-point-bend only)",
              "three-point-bend: out of plane, m: its load in newtons and its energies in joules "
              "include it (every other problem works per unit thickness and refuses it)",
              0.0, true, 1e3),
      key("material.mean_dilation", "bool", "false", "true or false", "B-bar strain operator"),
      bounded("material.variation", "number", "0", "0 <= x < 1",
              "per-cell factors uniform in [1 - x, 1 + x] on E and, independently, on the strength "
              "(an edge takes the mean of its cells'; docs/impact.md)",
              0.0, false, 1.0, true),
      bounded("material.variation_seed", "integer", "1", "0 <= seed <= 2147483647",
              "the seed of the per-cell factors (each cell its own stream)", 0.0, false,
              2147483647.0),
      bounded("damping", "number", "0", "0 <= c <= 1e9",
              "mass-proportional damping c, 1/s (the force -c M v)", 0.0, false, 1e9),
  };
}

/// Bulk viscosity on the cells (dynamics/BulkViscosity, docs/dynamics.md): off unless a
/// coefficient is given; Abaqus and LS-DYNA use b1 = 0.06, b2 = 1.2.
std::vector<SceneKey> bulk_viscosity_keys() {
  return {
      bounded("bulk_viscosity.linear", "number",
              contact_default([](const ContactDefaults& d) { return exact_text(d.bulk_linear); }),
              "0 <= b1 <= 1",
              "cell pressure b1 rho c_d L eps (eps the volumetric strain rate, L = sqrt(area)); "
              "the step is cut by sqrt(1 + b1^2) - b1; 0: off",
              0.0, false, 1.0),
      bounded("bulk_viscosity.quadratic", "number", contact_default([](const ContactDefaults& d) {
                return exact_text(d.bulk_quadratic);
              }),
              "0 <= b2 <= 10",
              "adds rho (b2 L)^2 eps^2 in compression; a run stops where it outgrows the step; "
              "0: off",
              0.0, false, 10.0),
  };
}

/// The kinematics and gravity.
std::vector<SceneKey> impact_keys() {
  return {
      key("interfaces", "string", "insertion", "insertion or dg (dg: with small kinematics)",
          "how cracks appear. insertion: an edge is split when the criterion holds and its "
          "cohesive law starts from zero opening. dg: every edge that may crack is split from "
          "t = 0 and held together by the quasi-static solver's symmetric interior-penalty "
          "terms (coercive penalty, fan tractions); in a fragmentation study the criterion is "
          "checked on the consistent interface traction and an activated face continues with "
          "the law from the traction it carried; the step is the coupled system's "
          "(docs/dynamics.md, \"Interfaces coupled from the start\")"),
      key("kinematics", "string", "small; fragmentation: corotational", "small or corotational",
          "small: linear small strain (a cell turned by theta is drawn and meets contact stretched "
          "by about theta^2 / 2); corotational: small strain in a frame that turns with each cell, "
          "for fragments that spin (docs/impact.md)"),
      bounded("gravity", "[gx, gy]", per_problem_text([](const DynamicsProblem& p) {
                return point_text(p.default_gravity());
              }),
              "each |component| <= 1e6", "body force per unit mass, m/s^2", -1e6, false, 1e6),
  };
}

/// The registered contact laws that are obstacles (a wall can be any of them), or not (between
/// surface cells).
std::vector<ContactLawEntry> laws_of_kind(bool obstacle) {
  std::vector<ContactLawEntry> out;
  for (const ContactLawEntry& e : contact_laws())
    if (e.obstacle == obstacle) out.push_back(e);
  return out;
}

/// The rigid wall and contact.
std::vector<SceneKey> contact_keys() {
  const std::string per_problem = "per problem: ";
  return {
      bounded("wall.point", "[x, y]",
              per_problem + "wall-impact: the body's leading point along its velocity; "
                            "column-impact: the column's bottom-left corner; a `wall` in another "
                            "problem: the middle of the right side; else no wall",
              "each |coordinate| <= 1e6, no point of a body behind the wall at t = 0",
              "a point of a fixed rigid plane (any problem may have one)", -1e6, false, 1e6),
      bounded("wall.normal", "[nx, ny]",
              "wall-impact: against the initial velocity; column-impact: [sin, cos] of the "
              "obliquity; else [-1, 0]",
              "not [0, 0], each |component| <= 1e6",
              "the plane's normal, pointing into free space (normalized)", -1e6, false, 1e6),
      key("wall.law", "string", default_contact_law(true), name_list(laws_of_kind(true)),
          "how the plane acts on the bodies: exact (an impulse per vertex, no parameter) or the "
          "report's penalty (contact.* below) (docs/contact.md, \"Contact laws\")"),
      bounded("wall.friction", "number",
              contact_default([](const ContactDefaults& d) { return exact_text(d.wall_friction); }),
              "0 <= mu <= 10",
              "Coulomb friction between the plane and the bodies (docs/contact.md); 0: "
              "frictionless",
              0.0, false, 10.0),
      key("contact.enabled", "bool", "true", "true or false",
          "contact between the surface cells of every body (the wall acts whatever this says)"),
      key("contact.law", "string", default_contact_law(false), name_list(laws_of_kind(false)),
          "how surface cells act on each other: exact (impulses, no parameter) or the report's "
          "penalty (alpha, damping_ratio, plastic, quiescent_penetration: they act on the "
          "penalty laws only) (docs/contact.md, \"Contact laws\")"),
      bounded("contact.alpha", "number", "0.1", "0 < alpha <= 1",
              "penalty stiffness k = alpha m / dt^2 (docs/contact.md)", 0.0, true, 1.0, false),
      bounded("contact.damping_ratio", "number", "0", "0 <= zeta <= 1",
              "contact damping, a fraction of the critical damping of the penalty spring", 0.0,
              false, 1.0, false),
      bounded("contact.quiescent_penetration", "number",
              contact_default(
                  [](const ContactDefaults& d) { return exact_text(d.quiescent_penetration); }),
              "0 <= x <= 1",
              "> 0: the report's displacement penalty instead of alpha, as small as keeps the "
              "bodies resting under gravity on the wall from sinking more than x h_avg: "
              "k_d = M |g.n| / (x h_avg), M the bodies' mass (the run records k_d)",
              0.0, false, 1.0),
      bounded("contact.friction", "number",
              contact_default([](const ContactDefaults& d) { return exact_text(d.friction); }),
              "0 <= mu <= 10",
              "Coulomb friction between surface cells, fragments included (docs/contact.md); 0: "
              "frictionless",
              0.0, false, 10.0),
      key("contact.plastic", "bool", contact_default([](const ContactDefaults& d) {
            return std::string(d.plastic ? "true" : "false");
          }),
          "true or false (not with damping_ratio > 0)",
          "the report's velocity penalty: k_v = m / dt removes a contacting pair's approach "
          "velocity in one step (a plastic impact of the pair), its work dissipated"),
  };
}

/// The time stepping.
std::vector<SceneKey> time_keys() {
  return {
      bounded(
          "time.end", "number",
          per_problem_text([](const DynamicsProblem& p) { return p.default_length_doc(); }, "; "),
          "0 < end <= 1e6", "the end time, s (not with time.steps)", 0.0, true, 1e6),
      bounded("time.steps", "integer", "none (time.end)", "1 <= steps <= 1e9",
              "the number of steps, instead of an end time (not with time.end)", 1.0, false, 1e9),
      bounded("time.safety", "number", "0.9", "0 < safety < 1 (up to 10 only with --force)",
              "dt = safety x the critical step", 0.0, true, 10.0),
      key("time.estimate", "string", "lanczos; fragmentation: cells", "lanczos or cells",
          "which critical step dt uses: the Lanczos estimate of the assembled system or the "
          "cell-by-cell bound (both are reported); with cracks both hold for every crack pattern: "
          "the estimate is of the cells and the cohesive springs on the map split wherever a face "
          "may form (22-23 % fewer steps on the column, and fewer fragments: docs/impact.md), the "
          "bound the cells' plus the springs'; with interfaces dg only the bound"),
      bounded("time.output_every", "integer", "100", "1 <= output_every <= 1e9",
              "steps between rewrites of the history file and between .vtu frames", 1.0, false,
              1e9),
      bounded("time.history_every", "integer", "1", "1 <= history_every <= 1e9",
              "steps between rows of the history", 1.0, false, 1e9),
      key("time.refinement", "list of numbers", "none",
          "two or more fractions of the step, descending, in (0, 1]",
          "a time-refinement study: every run at each fraction of its step (safety x fraction), "
          "into DIR/dt-<fraction>/ (DIR/<variant>/dt-<fraction>/ with variants); "
          "DIR/time-refinement.md and .csv give each measure's values, their differences, the "
          "observed order and the extrapolated value, and the Kolmogorov-Smirnov distance of "
          "the fragment masses between successive steps (docs/dynamics.md, \"Time refinement\")"),
  };
}

/// What a run writes, the mesh blocks, and the studies of several scenes.
std::vector<SceneKey> output_keys() {
  return {
      key("outputs.vtu", "bool", "true", "true or false",
          "write the .pvd series of the deformed mesh"),
      key("outputs.snapshots", "list of numbers", "none", "ascending times >= 0",
          "extra frames at the first step at or after each time, s: vtu/<run>/snapshot_<i>.vtu, "
          "listed in snapshots/<run>.csv and drawn in plots/<run>_snapshots.png"),
      variants_key(),
      key("perturb.key", "string", "none", "a top-level key or a JSON pointer (/wall/point)",
          "the key a sensitivity study varies (instead of variants[]); its runs go to "
          "DIR/perturb-<i>/, and DIR/perturbation.csv holds each run's Hamming distance to "
          "perturb-0's crack state after every step"),
      key("perturb.values[]", "list", "none", "two or more values of the key",
          "the values, the first the reference"),
  };
}

std::vector<SceneKey> make_dynamics_keys() {
  std::vector<SceneKey> keys = naming_keys();
  append_keys(keys, dynamics_study_keys());
  append_keys(keys, cohesive_keys({"3e8", "100", "10", "0",
                                   "dynamics needs an initially elastic law; its springs share "
                                   "the stable step",
                                   "fragmentation: "}));
  keys.push_back(bounded(
      "cohesive.closure_stiffness", "number or string", "0.1",
      "0 < k <= 1, or \"interface\" (interfaces dg)",
      "fragmentation: the crack faces' penalty against overclosure as a fraction of K0, or "
      "\"interface\": each face keeps its interface's penalty eps, the quasi-static solver's "
      "closure. A tenth lets a face that closes and opens again switch over several steps (at "
      "K0 the switching fed energy in on a stretched strip); the compressed part of a crack line "
      "under a slow load softens the beam with it (docs/dynamics.md)",
      0.0, true, 1.0));
  keys.push_back(bounded(
      "cohesive.face_friction", "number", "criterion.friction", "0 <= mu <= 10",
      "fragmentation: Coulomb friction of closed crack faces (Camacho and Ortiz): a face in "
      "compression slides at mu times the closure's pressure, and that work is dissipated; by "
      "default the material's internal friction, the criterion's, since the faces are its "
      "failure planes (docs/fragmentation.md); 0: frictionless",
      0.0, false, 10.0));
  keys.push_back(
      key("cohesive.turning_frames", "bool", "false", "true or false (true only with corotational)",
          "fragmentation: crack faces read their openings in a frame that turns with them (the "
          "chord of their mean ends) instead of their reference frame; frame-indifferent and the "
          "exact gradient of the faces' energy, but it made column runs unstable "
          "(docs/impact.md, \"The ablation\")"));
  append_keys(keys, body_keys());
  append_keys(keys, dynamics_problem_keys());
  append_keys(keys, elastic_keys("2e11", "0.3"));
  append_keys(keys, material_keys());
  append_keys(keys, material_field_keys());
  append_keys(keys, bulk_viscosity_keys());
  append_keys(keys, element_keys());
  append_keys(keys, impact_keys());
  append_keys(keys, contact_keys());
  append_keys(keys, time_keys());
  append_keys(keys, mesh_keys());
  append_keys(keys, output_keys());
  append_keys(keys, checkpoint_keys());
  append_keys(keys, statistics_keys());
  return keys;
}

}  // namespace

const KeyTable& dynamics_scene_keys() {
  static const KeyTable table{"dynamics", make_dynamics_keys(), {}};
  return table;
}

const SceneKey& dynamics_key(const std::string& name) {
  return dynamics_scene_keys().at(name);
}

}  // namespace vorodg
