#include "verification/dynamics/DynamicsKeys.hpp"

#include <cmath>
#include <stdexcept>

#include "core/element/ElementTable.hpp"
#include "core/util/Format.hpp"
#include "verification/model/Choices.hpp"
#include "verification/model/SettingsSchema.hpp"

namespace vorodg {
namespace {

DynamicsKey key(std::string name, std::string type, std::string fallback, std::string range,
                std::string doc) {
  return {std::move(name),
          std::move(type),
          std::move(fallback),
          std::move(range),
          std::move(doc),
          {},
          {},
          false,
          false};
}

/// A number with bounds: lower (open or closed) and an optional upper.
DynamicsKey bounded(std::string name, std::string type, std::string fallback, std::string range,
                    std::string doc, std::optional<double> lower, bool lower_open,
                    std::optional<double> upper = {}, bool upper_open = false) {
  DynamicsKey k =
      key(std::move(name), std::move(type), std::move(fallback), std::move(range), std::move(doc));
  k.lower = lower, k.lower_open = lower_open, k.upper = upper, k.upper_open = upper_open;
  return k;
}

std::vector<DynamicsKey> make_keys() {
  const std::string per_problem = "per problem: ";
  return {
      key("name", "string", "file stem", "any", "the study's name in reports"),
      key("description", "string", "\"\"", "any", "one sentence for --list and the report"),
      key("study", "string", "dynamics", "dynamics or fragmentation",
          "the study kind: fragmentation adds crack insertion and the cohesive keys "
          "(docs/fragmentation.md)"),
      key("problem", "string", "wave-bar",
          "wave-bar, free-body, wall-impact, two-blocks, column-impact, projectile-impact; "
          "strip-expansion (fragmentation)",
          "what is thrown, struck or stretched (docs/dynamics.md, \"Problems\")"),
      key("domain", "[x0, y0, x1, y1]",
          per_problem + "wave-bar [0, 0, 1, 0.05], free-body [0, 0, 1, 1], wall-impact "
                        "[0, 0, 0.4, 0.1], two-blocks [0, 0, 0.2, 0.1], strip-expansion "
                        "[0, 0, 0.002, 1e-05], column-impact [0, 0, 0.3, 1.83], "
                        "projectile-impact [0, 0, 4, 0.3]",
          "x0 < x1, y0 < y1", "the (first) body, in m"),
      bounded("strain_rate", "number", "1e5", "> 0",
              "strip-expansion: the initial velocity is strain_rate (x - x_mid) along x, 1/s", 0.0,
              true),
      key("cohesive.law", "string", "linear", "linear or bilinear",
          "fragmentation: the softening of the cohesive law (docs/fracture.md)"),
      bounded("cohesive.strength", "number", "3e8", "> 0", "fragmentation: sigma_c, Pa", 0.0, true),
      bounded("cohesive.fracture_energy", "number", "100", "> 0",
              "fragmentation: G, the area under the law, J/m^2", 0.0, true),
      bounded("cohesive.shear_factor", "number", "1", ">= 0",
              "fragmentation: beta, the weight of sliding in the effective opening", 0.0, false),
      bounded("cohesive.initial_stiffness", "number", "10", "> 0",
              "fragmentation: K0 in units of E / h_avg (dynamics needs an initially elastic law; "
              "its springs share the stable step)",
              0.0, true),
      bounded("criterion.cohesion", "number", "cohesive.strength", "> 0",
              "fragmentation: Mohr-Coulomb cohesion c, Pa", 0.0, true),
      bounded("criterion.friction", "number", "0", ">= 0",
              "fragmentation: Mohr-Coulomb friction coefficient mu", 0.0, false),
      bounded("criterion.tensile_cutoff", "number", "cohesive.strength", "> 0",
              "fragmentation: the tensile cutoff sigma_o, Pa", 0.0, true),
      key("initial_velocity", "[vx, vy]",
          per_problem + "wave-bar, strip-expansion and projectile-impact [0, 0], free-body "
                        "[1, 0.5], wall-impact and two-blocks [1, 0], column-impact [0, -7.6]",
          "finite", "uniform velocity of the (first) body at t = 0, m/s"),
      bounded("angular_velocity", "number", per_problem + "free-body 1, else 0", "finite",
              "spin of the (first) body about its centre of mass at t = 0, rad/s (small "
              "strain: the spin is the linearized rotation)",
              {}, false),
      key("second_block.domain", "[x0, y0, x1, y1]", "domain moved right by 1.05 times its width",
          "x0 < x1, y0 < y1, apart from domain",
          "two-blocks: the second body (family file: the same size as domain)"),
      key("second_block.initial_velocity", "[vx, vy]", "minus initial_velocity", "finite",
          "two-blocks: the second body's velocity, m/s"),
      bounded("second_block.angular_velocity", "number", "0", "finite",
              "two-blocks: the second body's spin, rad/s", {}, false),
      key("sides", "string", "free", "free or rollers",
          "wave-bar: the long sides free (uniaxial stress, bar speed) or on rollers (uniaxial "
          "strain, dilatational speed)"),
      bounded("pulse.amplitude", "number", "1", "finite, not 0",
              "wave-bar: the peak of the velocity prescribed on the left end, m/s", {}, false),
      bounded("pulse.duration", "number", "0.9 L / c", "> 0",
              "wave-bar: (1 - cos) rise, hold and (1 + cos) fall, a third each, s (c the "
              "expected speed, L the bar's length)",
              0.0, true),
      bounded("material.E", "number", "2e11", "> 0", "Young's modulus, Pa", 0.0, true),
      bounded("material.nu", "number", "0.3", "-1 < nu < 0.5", "Poisson's ratio", -1.0, true, 0.5,
              true),
      key("material.plane", "string", "stress", "stress or strain", "plane stress or strain"),
      bounded("material.density", "number", "7800", "> 0", "mass density, kg/m^3", 0.0, true),
      key("material.mean_dilation", "bool", "false", "true or false", "B-bar strain operator"),
      bounded("material.variation", "number", "0", "0 <= x < 1",
              "per-cell factors uniform in [1 - x, 1 + x] on E and, independently, on the strength "
              "(an edge takes the mean of its cells'; docs/impact.md)",
              0.0, false, 1.0, true),
      bounded("material.variation_seed", "integer", "1", ">= 0",
              "the seed of the per-cell factors (each cell its own stream)", 0.0, false),
      bounded("damping", "number", "0", ">= 0",
              "mass-proportional damping c, 1/s (the force -c M v)", 0.0, false),
      key("element", "string", element_name(ElementOptions{}.family),
          choice_list(element_choices()),
          "the element: its shape functions (docs/element.md, \"Which element for what\")"),
      bounded("vem_stabilization", "number", exact_text(ElementOptions{}.vem_stabilization), "> 0",
              "vem: the stabilization's scale tau, times trace(K_consistency) / (2n)", 0.0, true),
      key("kinematics", "string", "small", "small or corotational",
          "small: linear small strain (a cell turned by theta is drawn and meets contact stretched "
          "by about theta^2 / 2); corotational: small strain in a frame that turns with each "
          "cell, for fragments that spin (docs/impact.md)"),
      key("gravity", "[gx, gy]", per_problem + "column-impact [0, -9.81], else [0, 0]", "finite",
          "body force per unit mass, m/s^2"),
      bounded("obliquity", "number", "45", "0 <= obliquity < 90",
              "column-impact: the tilt of the plane the column falls on, degrees (the plane "
              "passes through the column's bottom-left corner, its normal [sin, cos] of the tilt)",
              0.0, false, 90.0, true),
      bounded("projectile.speed", "number", "20", "> 0",
              "projectile-impact: the rigid projectile's constant downward speed, m/s", 0.0, true),
      bounded("projectile.width", "number", "0.1", "> 0",
              "projectile-impact: the width of its flat nose, m (the top vertices under it move "
              "down at its speed from t = 0, free to slide)",
              0.0, true),
      bounded("projectile.position", "number", "the middle of the top side", "nose within the top",
              "projectile-impact: x of the nose's centre, m", {}, false),
      key("wall.point", "[x, y]",
          per_problem + "wall-impact: the body's leading point along its velocity; "
                        "column-impact: the column's bottom-left corner; a `wall` in another "
                        "problem: the middle of the right side; else no wall",
          "no point of a body behind the wall at t = 0",
          "a point of a fixed rigid plane (any problem may have one)"),
      key("wall.normal", "[nx, ny]",
          "wall-impact: against the initial velocity; column-impact: [sin, cos] of the "
          "obliquity; else [-1, 0]",
          "not [0, 0]", "the plane's normal, pointing into free space (normalized)"),
      key("contact.enabled", "bool", "true", "true or false",
          "contact between the surface cells of every body (the wall acts whatever this says)"),
      bounded("contact.alpha", "number", "0.1", "0 < alpha <= 1",
              "penalty stiffness k = alpha m / dt^2 (docs/contact.md)", 0.0, true, 1.0, false),
      bounded("contact.damping_ratio", "number", "0", "0 <= zeta <= 1",
              "contact damping, a fraction of the critical damping of the penalty spring", 0.0,
              false, 1.0, false),
      bounded("time.end", "number",
              per_problem + "wave-bar 2 L / c; wall-impact and two-blocks the flight to contact "
                            "plus 3 x 2 L / c_bar (L: the extent along the wall's normal; the "
                            "longer side of either block); free-body 1000 steps; "
                            "strip-expansion 20 x the time to reach the cutoff, "
                            "sigma_o / (E strain_rate); column-impact 0.3; projectile-impact "
                            "3e-3",
              "> 0", "the end time, s (not with time.steps)", 0.0, true),
      bounded("time.steps", "integer", "none (time.end)", ">= 1",
              "the number of steps, instead of an end time (not with time.end)", 1.0, false),
      bounded("time.safety", "number", "0.9", "0 < safety < 1 (>= 1 only with --force)",
              "dt = safety x the critical step", 0.0, true),
      key("time.estimate", "string", "lanczos; fragmentation: cells", "lanczos or cells",
          "which critical step dt uses: the Lanczos estimate of the assembled system or the "
          "cell-by-cell bound (both are reported); fragmentation needs the cell bound, which "
          "holds for every crack pattern, plus the cohesive springs' bound"),
      bounded("time.output_every", "integer", "100", ">= 1",
              "steps between rewrites of the history file and between .vtu frames", 1.0, false),
      bounded("time.history_every", "integer", "1", ">= 1", "steps between rows of the history",
              1.0, false),
      key("outputs.vtu", "bool", "true", "true or false",
          "write the .pvd series of the deformed mesh"),
      key("outputs.snapshots", "list of numbers", "none", "ascending times >= 0",
          "extra frames at the first step at or after each time, s: vtu/<run>/snapshot_<i>.vtu, "
          "listed in snapshots/<run>.csv and drawn in plots/<run>_snapshots.png"),
      key("meshes[]", "list (required)", "", "as in every study (docs/scenes.md)",
          "mesh families with sizes, realizations, seed"),
      key("variants[]", "objects with a label", "none", "",
          "each merged over the top-level keys; each runs into DIR/<label>/"),
      key("perturb.key", "string", "none", "a top-level key or a JSON pointer (/wall/point)",
          "the key a sensitivity study varies (instead of variants[]); its runs go to "
          "DIR/perturb-<i>/, and DIR/perturbation.csv holds each run's Hamming distance to "
          "perturb-0's crack state after every step"),
      key("perturb.values[]", "list", "none", "two or more values of the key",
          "the values, the first the reference"),
  };
}

}  // namespace

const std::vector<DynamicsKey>& dynamics_scene_keys() {
  static const std::vector<DynamicsKey> keys = make_keys();
  return keys;
}

const DynamicsKey& dynamics_key(const std::string& name) {
  for (const DynamicsKey& k : dynamics_scene_keys())
    if (k.name == name) return k;
  throw std::out_of_range("no dynamics scene key " + name);
}

double key_default(const DynamicsKey& key) {
  try {
    std::size_t used = 0;
    const double v = std::stod(key.fallback, &used);
    if (used == key.fallback.size()) return v;
  } catch (const std::exception&) {
  }
  throw std::logic_error("dynamics scene key " + key.name + ": the default is not a number");
}

std::optional<std::string> check_key(const DynamicsKey& key, double value) {
  const bool low = key.lower && (key.lower_open ? !(value > *key.lower) : !(value >= *key.lower));
  const bool high = key.upper && (key.upper_open ? !(value < *key.upper) : !(value <= *key.upper));
  if (std::isfinite(value) && !low && !high) return std::nullopt;
  return "expected " + key.range + ", found " + fmt(value);
}

}  // namespace vorodg
