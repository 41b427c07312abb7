#include "verification/solve/SettingsSchema.hpp"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <stdexcept>

#include "core/element/WeightFunctions.hpp"
#include "core/quadrature/TriangleRule.hpp"

namespace vorodg {
namespace {

using S = SolveSettings;

/// A setting's numeric range as its builders state it: bounds, or the only values allowed.
struct SettingRange {
  Bounds bounds;
  std::vector<int> allowed;
};

/// The type a scene key of this kind has in the docs.
std::string type_name(SettingKind kind) {
  switch (kind) {
    case SettingKind::number: return "number";
    case SettingKind::integer: return "integer";
    case SettingKind::flag: return "bool";
    case SettingKind::choice: return "string";
  }
  return "?";
}

SettingSpec base(std::string key, std::string flag, std::string symbol, std::string doc,
                 SettingKind kind, SettingScope scope, SettingRange range) {
  SettingSpec spec;
  spec.name = std::move(key);
  spec.type = type_name(kind);
  spec.flag = std::move(flag);
  spec.symbol = std::move(symbol);
  spec.doc = std::move(doc);
  spec.kind = kind;
  spec.scope = scope;
  spec.bounds = range.bounds;
  spec.allowed = std::move(range.allowed);
  if (!spec.allowed.empty()) {  // a list of values: bounded by its least and greatest
    const auto [lo, hi] = std::minmax_element(spec.allowed.begin(), spec.allowed.end());
    spec.bounds = {double(*lo), double(*hi), false, false};
  }
  return spec;
}

SettingSpec number(std::string key, std::string flag, std::string symbol, std::string doc,
                   SettingScope scope, SettingRange range, double& (*field)(S&)) {
  SettingSpec spec = base(key, flag, symbol, doc, SettingKind::number, scope, range);
  spec.get = [field](const S& s) { return field(const_cast<S&>(s)); };
  spec.set = [field](S& s, double v) { field(s) = v; };
  return spec;
}

SettingSpec integer(std::string key, std::string flag, std::string symbol, std::string doc,
                    SettingScope scope, SettingRange range, int& (*field)(S&)) {
  SettingSpec spec = base(key, flag, symbol, doc, SettingKind::integer, scope, range);
  spec.get = [field](const S& s) { return field(const_cast<S&>(s)); };
  spec.set = [field](S& s, double v) { field(s) = static_cast<int>(v); };
  return spec;
}

SettingSpec flag(std::string key, std::string flag, std::string doc, SettingScope scope,
                 bool& (*field)(S&), bool negates = false) {
  SettingSpec spec = base(key, flag, key, doc, SettingKind::flag, scope, SettingRange{});
  spec.flag_negates = negates;
  spec.get = [field](const S& s) { return field(const_cast<S&>(s)) ? 1.0 : 0.0; };
  spec.set = [field](S& s, double v) { field(s) = v != 0.0; };
  return spec;
}

SettingSpec choice(std::string key, std::string flag, std::string doc, SettingScope scope,
                   const Choices& choices, std::function<std::string(const S&)> get,
                   std::function<void(S&, const std::string&)> set) {
  SettingSpec spec = base(key, flag, key, doc, SettingKind::choice, scope, SettingRange{});
  spec.choices = &choices;
  spec.get_text = std::move(get);
  spec.set_text = std::move(set);
  return spec;
}

// Every number has a finite upper bound too: a generous limit of what the physics allows, so
// that a value that would overflow a run is refused as bad input (docs/robustness.md).
SettingRange above(double lower, double upper) {
  return {{lower, upper, true, false}, {}};
}
SettingRange at_least(double lower, double upper) {
  return {{lower, upper, false, false}, {}};
}
SettingRange one_of(std::vector<int> allowed) {
  return {{}, allowed};
}

/// The DG penalty's scaling: unset means the formulation's default (dg/DgElasticity.hpp).
SettingSpec penalty_choice() {
  SettingSpec spec = choice(
      "penalty", "--penalty", "DG: how the penalty eps is scaled on each interface",
      SettingScope::formulation, penalty_choices(),
      [](const S& s) { return penalty_name(penalty_scaling(dg_options(s))); },
      [](S& s, const std::string& v) { s.dg.penalty = parse_penalty(v); });
  spec.fallback = "auto for dg-sipg, else h-avg";
  spec.default_depends = true;
  return spec;
}

/// Which stress of each cell the interface terms take: unset means the formulation's default.
SettingSpec traction_choice() {
  SettingSpec spec = choice(
      "traction", "--traction", "DG: each cell's stress on an interface", SettingScope::formulation,
      traction_choices(),
      [](const S& s) { return traction_name(interface_traction(dg_options(s))); },
      [](S& s, const std::string& v) { s.dg.traction = parse_traction(v); });
  spec.fallback = "fan for dg-sipg, else mean";
  spec.default_depends = true;
  return spec;
}

/// k_p multiplies the scaling: E / h (h-avg, local-h, fixed-h) or the coercive bound (auto).
SettingSpec kp_number() {
  SettingSpec spec = base("kp", "--kp", "k_p",
                          "DG penalty multiplier: eps = k_p E / h, or k_p times the proven "
                          "coercive bound with penalty auto",
                          SettingKind::number, SettingScope::formulation, above(0, 1e16));
  spec.get = [](const S& s) { return penalty_multiplier(dg_options(s)); };
  spec.set = [](S& s, double v) { s.dg.kp = v; };
  spec.fallback = "1 with penalty auto, else 1000";
  spec.default_depends = true;
  return spec;
}

/// The problem, the formulation and the material.
std::vector<SettingSpec> problem_specs() {
  using Scope = SettingScope;
  return {
      choice(
          "problem", "--problem", "the boundary value problem", Scope::top, problem_choices(),
          [](const S& s) { return s.problem; }, [](S& s, const std::string& v) { s.problem = v; }),
      choice(
          "name", "--formulation", "the formulation", Scope::formulation, formulation_choices(),
          [](const S& s) { return s.formulation; },
          [](S& s, const std::string& v) { s.formulation = v; }),
      choice(
          "plane", "--plane", "plane stress or plane strain", Scope::material, plane_choices(),
          [](const S& s) { return plane_name(s.plane); },
          [](S& s, const std::string& v) { s.plane = parse_plane(v); }),
      number("E", "--E", "E", "Young's modulus", Scope::material, above(0, 1e13),
             [](S& s) -> double& { return s.E; }),
      number("nu", "--nu", "nu", "Poisson's ratio", Scope::material, {-1.0, 0.5, true, true, {}},
             [](S& s) -> double& { return s.nu; }),
      number("load", "--load", "P", "beam: end load P", Scope::material,
             {-1e15, 1e15, false, false, {}}, [](S& s) -> double& { return s.load; }),
  };
}

/// The element: strain operator, shape functions, quadrature, weight functions.
std::vector<SettingSpec> element_specs() {
  using Scope = SettingScope;
  const std::vector<int> rules(kFanRulePoints.begin(), kFanRulePoints.end());
  const std::vector<int> degrees(kWeightDegrees.begin(), kWeightDegrees.end());
  return {
      flag("mean_dilation", "--mean-dilation", "mean-dilation (B-bar) strain operator",
           Scope::formulation, [](S& s) -> bool& { return s.mean_dilation; }),
      choice(
          "element", "--element", "the element: its shape functions", Scope::formulation,
          element_choices(), [](const S& s) { return element_name(s.element.family); },
          [](S& s, const std::string& v) { s.element.family = parse_element(v); }),
      number("vem_stabilization", "--vem-stabilization", "vem_stabilization",
             "vem: the stabilization's scale tau, times trace(K_consistency) / (2n)",
             Scope::formulation, above(0, 1e6),
             [](S& s) -> double& { return s.element.vem_stabilization; }),
      flag(
          "correction", "--no-correction", "divergence-consistency correction (the flag skips it)",
          Scope::formulation, [](S& s) -> bool& { return s.element.divergence_correction; }, true),
      integer("rule", "--rule", "rule", "quadrature points per fan triangle", Scope::formulation,
              one_of(rules), [](S& s) -> int& { return s.element.rule_points; }),
      integer("refinement", "--refinement", "refinement",
              "weight functions: fan triangles cut into 4^refinement", Scope::formulation,
              {0.0, static_cast<double>(kMaxWeightRefinement), false, false, {}},
              [](S& s) -> int& { return s.element.weights.refinement; }),
      integer("degree", "--degree", "degree", "weight functions: P1 or P2 on the sub-triangles",
              Scope::formulation, one_of(degrees),
              [](S& s) -> int& { return s.element.weights.degree; }),
  };
}

/// The DG formulations' penalty, iterations and interface tractions.
std::vector<SettingSpec> dg_specs() {
  using Scope = SettingScope;
  return {
      penalty_choice(),
      kp_number(),
      flag("weighted_average", "--weighted-average",
           "DG, penalty auto: interface average weighted by the cells' trace constants",
           Scope::formulation, [](S& s) -> bool& { return s.dg.weighted_average; }),
      number("tolerance", "--tol", "tolerance", "DG iterations: relative change to stop at",
             Scope::formulation, {0.0, 1.0, true, false, {}},
             [](S& s) -> double& { return s.dg.tolerance; }),
      integer("max_iterations", "--max-iter", "max_iterations", "DG iterations: at most this many",
              Scope::formulation, at_least(1, 1e7),
              [](S& s) -> int& { return s.dg.max_iterations; }),
      flag("al_update_kp", "--al-update-kp",
           "dg-al: update lambda with k_p E [u] (the report's Eq. 26) instead of eps [u]",
           Scope::formulation, [](S& s) -> bool& { return s.dg.al_update_kp; }),
      traction_choice(),
      integer("sipg_sign", "--sipg-sign", "sipg_sign", "dg-sipg: -1 symmetric, +1 non-symmetric",
              Scope::formulation, one_of({-1, 1}), [](S& s) -> int& { return s.dg.sipg_sign; }),
  };
}

/// What a run computes and how it solves.
std::vector<SettingSpec> run_specs() {
  using Scope = SettingScope;
  return {
      flag(
          "errors", "--no-errors",
          "integrate the error against the exact solution (the flag skips it: no error points, "
          "no weight functions rebuilt after the factorization; a study always measures errors)",
          Scope::command_line, [](S& s) -> bool& { return s.errors; }, true),
      flag("energy_error", "", "compute the energy norm of the error too", Scope::outputs,
           [](S& s) -> bool& { return s.energy_error; }),
      integer("threads", "--threads", "threads", "threads for setup, assembly and errors",
              Scope::command_line, at_least(1, 4096),
              [](S& s) -> int& { return s.element.threads; }),
      choice(
          "ordering", "--ordering", "fill-reducing ordering of the sparse factor",
          Scope::command_line, ordering_choices(),
          [](const S& s) { return ordering_name(s.solver.ordering); },
          [](S& s, const std::string& v) { s.solver.ordering = parse_ordering(v); }),
      choice(
          "solver", "--solver", "CG: the linear solver", Scope::formulation, solver_choices(),
          [](const S& s) { return solver_name(s.solver.kind); },
          [](S& s, const std::string& v) { s.solver.kind = parse_solver(v); }),
      number("amg_tolerance", "--amg-tol", "amg_tolerance",
             "amg-cg: relative tolerance of CG in the AMG-preconditioned norm; 0 ties it to the "
             "mesh: 0.01 (h_avg/L)^2 within [1e-12, 1e-6]",
             Scope::formulation, {0.0, 1.0, false, true, {}},
             [](S& s) -> double& { return s.solver.amg_tolerance; }),
  };
}

std::string bound_text(double x) {
  return exact_text(x);
}

/// What the range requires, for messages and docs: "-1 < nu < 0.5", "1, 3 or 6", "stress or
/// strain".
std::string requirement_text(const SettingSpec& spec) {
  if (spec.kind == SettingKind::choice) return choice_list(*spec.choices);
  if (spec.kind == SettingKind::flag) return "true or false";
  const std::vector<int>& allowed = spec.allowed;
  const Bounds& r = spec.bounds;
  if (!allowed.empty()) {
    std::string out;
    for (std::size_t i = 0; i < allowed.size(); ++i)
      out += (i == 0 ? "" : i + 1 == allowed.size() ? " or " : ", ") + std::to_string(allowed[i]);
    return out;
  }
  const std::string lo = r.lower ? bound_text(*r.lower) + (r.lower_open ? " < " : " <= ") : "";
  const std::string hi = r.upper ? (r.upper_open ? " < " : " <= ") + bound_text(*r.upper) : "";
  if (r.lower && !r.upper)
    return spec.symbol + (r.lower_open ? " > " : " >= ") + bound_text(*r.lower);
  if (!r.lower && !r.upper) return "a finite " + spec.symbol;
  return lo + spec.symbol + hi;
}

/// Every setting with its row complete: the range in words, and the default read from a
/// default-constructed SolveSettings where it does not depend on the formulation.
std::vector<SettingSpec> make_specs() {
  std::vector<SettingSpec> specs;
  for (auto group : {problem_specs, element_specs, dg_specs, run_specs}) {
    std::vector<SettingSpec> more = group();
    specs.insert(specs.end(), more.begin(), more.end());
  }
  for (SettingSpec& spec : specs) {
    spec.range = requirement_text(spec);
    if (!spec.default_depends) spec.fallback = value_text(spec, SolveSettings{});
  }
  return specs;
}

}  // namespace

const std::vector<SettingSpec>& setting_specs() {
  static const std::vector<SettingSpec> specs = make_specs();
  return specs;
}

const SettingSpec& setting_spec(const std::string& key) {
  for (const SettingSpec& spec : setting_specs())
    if (spec.name == key) return spec;
  throw std::out_of_range("no setting '" + key + "'");
}

std::string value_text(const SettingSpec& spec, const SolveSettings& settings) {
  switch (spec.kind) {
    case SettingKind::choice: return spec.get_text(settings);
    case SettingKind::flag: return spec.get(settings) != 0.0 ? "true" : "false";
    default: return exact_text(spec.get(settings));
  }
}

std::optional<std::string> check_value(const SettingSpec& spec, double value) {
  const std::vector<int>& a = spec.allowed;
  const bool listed = a.empty() || std::find(a.begin(), a.end(), value) != a.end();
  if (listed && spec.bounds.admits(value)) return std::nullopt;
  return exact_text(value) + ": expected " + spec.range + " (" + spec.doc + ")";
}

std::optional<std::string> check_text(const SettingSpec& spec, const std::string& text) {
  if (is_choice(*spec.choices, text)) return std::nullopt;
  return "'" + text + "': expected " + spec.range;
}

std::optional<SettingError> check_settings(const SolveSettings& settings) {
  for (const SettingSpec& spec : setting_specs()) {
    const auto message = spec.kind == SettingKind::choice
                             ? check_text(spec, spec.get_text(settings))
                         : spec.kind == SettingKind::flag ? std::nullopt
                                                          : check_value(spec, spec.get(settings));
    if (message) return SettingError{&spec, *message};
  }
  return std::nullopt;
}

}  // namespace vorodg
