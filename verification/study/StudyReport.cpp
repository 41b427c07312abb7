#include "verification/study/StudyReport.hpp"

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <iostream>
#include <map>
#include <sstream>

#include "core/io/AtomicFile.hpp"
#include "core/util/Format.hpp"
#include "verification/cli/JsonOutput.hpp"

namespace vorodg {
namespace {

using nlohmann::json;

/// Two-sided 95% quantile of Student's t with `dof` degrees of freedom.
double t95(int dof) {
  static const double table[] = {12.706, 4.303, 3.182, 2.776, 2.571, 2.447, 2.365, 2.306, 2.262,
                                 2.228, 2.201, 2.179, 2.160, 2.145, 2.131, 2.120, 2.110, 2.101,
                                 2.093, 2.086, 2.080, 2.074, 2.069, 2.064, 2.060, 2.056, 2.052,
                                 2.048, 2.045, 2.042};
  if (dof < 1) return NAN;
  return dof <= 30 ? table[dof - 1] : 1.96 + 2.4 / dof;
}

json stats(std::vector<double> v) {
  if (v.empty()) return json::object();
  const double n = static_cast<double>(v.size());
  double mean = 0.0;
  for (double x : v) mean += x / n;
  double var = 0.0;
  for (double x : v) var += (x - mean) * (x - mean);
  const double sd = v.size() > 1 ? std::sqrt(var / (n - 1)) : 0.0;
  json out = {{"mean", mean}, {"std", sd}, {"min", *std::min_element(v.begin(), v.end())},
              {"max", *std::max_element(v.begin(), v.end())}, {"values", v}};
  return out;
}

std::string group_key(const Scene& scene, const json& r) {
  std::string key = r["mesh"].get<std::string>() + " | " + r["problem"].get<std::string>();
  if (scene.nu.size() > 1) key += " | nu=" + fmt(r["nu"].get<double>(), 12);
  return key + " | " + r["variant"].get<std::string>();
}

bool ok(const json& r) { return r.value("status", "") == "ok"; }

json rate_json(const std::vector<json>& runs, const char* error, int levels) {
  std::vector<double> h, e;
  std::map<int, std::map<int, std::pair<double, double>>> by_realization;  // r -> level -> (h, e)
  for (const json& r : runs) {
    if (!ok(r) || !(r[error].get<double>() > 0)) continue;
    h.push_back(r["h_avg"].get<double>());
    e.push_back(r[error].get<double>());
    by_realization[r["realization"].get<int>()][r["level"].get<int>()] = {h.back(), e.back()};
  }
  if (levels < 2 || h.size() < 2) return json();
  const auto [rate, ci] = fit_rate(h, e);
  std::vector<double> pairs;
  for (const auto& [real, levels_of] : by_realization)
    for (auto it = levels_of.begin(); std::next(it) != levels_of.end(); ++it) {
      const auto& [h0, e0] = it->second;
      const auto& [h1, e1] = std::next(it)->second;
      pairs.push_back(std::log(e0 / e1) / std::log(h0 / h1));
    }
  json out = {{"value", rate}, {"ci95", std::isfinite(ci) ? json(ci) : json()}};
  if (!pairs.empty()) {
    std::sort(pairs.begin(), pairs.end());
    out["pair_min"] = pairs.front();
    out["pair_median"] = pairs[pairs.size() / 2];
    out["pair_max"] = pairs.back();
  }
  return out;
}

bool expected_to_pass(const Scene& scene, const json& r) {
  if (r["formulation"] == "dg-penalty") return false;
  for (const SceneFormulation& f : scene.formulations)
    if (r["variant"].get<std::string>().rfind(f.label, 0) == 0 && !f.settings.element.divergence_correction)
      return r["family"] == "tri" || r["family"] == "quad";
  return true;
}

std::string fixed(double x, int precision = 3) {
  std::ostringstream os;
  os << std::scientific << std::setprecision(precision) << x;
  return os.str();
}

double total_seconds(const json& r) {
  double total = 0.0;
  if (r.contains("seconds"))
    for (const auto& [stage, s] : r["seconds"].items()) total += s.get<double>();
  return total;
}

/// Error against wall time over the scene's knobs: per (variant, level) the mean L2 error and
/// the median total seconds over the realizations; the Pareto front (no other configuration is
/// both cheaper and more accurate); per knob, its cost and accuracy against the first
/// formulation at the same level. Wall times are not deterministic, so all of this goes to
/// tradeoff.json and report.md, never to summary.json.
void write_tradeoff(const Scene& scene, const std::vector<json>& results,
                    const std::filesystem::path& out, std::ostringstream& md) {
  struct Point {
    std::string variant;
    int level;
    double h, error, seconds;
  };
  std::map<std::pair<std::string, int>, std::vector<const json*>> groups;
  std::vector<std::string> variants;
  for (const json& r : results) {
    if (!ok(r)) continue;
    const std::string v = r["variant"];
    if (std::find(variants.begin(), variants.end(), v) == variants.end()) variants.push_back(v);
    groups[{v, r["level"].get<int>()}].push_back(&r);
  }
  std::vector<Point> points;
  for (const auto& [key, runs] : groups) {
    std::vector<double> e, t, h;
    for (const json* r : runs) {
      e.push_back((*r)["l2_error"]);
      t.push_back(total_seconds(*r));
      h.push_back((*r)["h_avg"]);
    }
    std::sort(t.begin(), t.end());
    double mean_e = 0, mean_h = 0;
    for (std::size_t i = 0; i < e.size(); ++i) mean_e += e[i] / e.size(), mean_h += h[i] / h.size();
    points.push_back({key.first, key.second, mean_h, mean_e, t[t.size() / 2]});
  }
  std::sort(points.begin(), points.end(), [](const Point& a, const Point& b) { return a.seconds < b.seconds; });
  std::vector<const Point*> front;  // by increasing time, strictly decreasing error
  for (const Point& p : points)
    if (front.empty() || p.error < front.back()->error) front.push_back(&p);
  json data = {{"points", json::array()}, {"pareto", json::array()}};
  for (const Point& p : points)
    data["points"].push_back({{"variant", p.variant}, {"level", p.level}, {"h_avg", p.h},
                              {"l2_error", p.error}, {"seconds", p.seconds}});
  md << "## Error against wall time\n\nPareto front (median total seconds per run over the "
        "realizations; no other configuration is both cheaper and more accurate). For a target "
        "error e, the cheapest configuration is the first row whose error is at most e:\n\n"
        "| L2 error | seconds | configuration | level | h_avg |\n|---|---|---|---|---|\n";
  std::cout << "\nPareto front (error against median wall time per run):\n";
  for (const Point* p : front) {
    data["pareto"].push_back({{"variant", p->variant}, {"level", p->level}, {"l2_error", p->error},
                              {"seconds", p->seconds}});
    md << "| " << fixed(p->error) << " | " << fmt(p->seconds, 3) << " | " << p->variant << " | "
       << p->level << " | " << fmt(p->h, 4) << " |\n";
    std::cout << "  " << fixed(p->error) << "  " << std::setw(9) << fmt(p->seconds, 3) << " s  "
              << p->variant << ", level " << p->level << "\n";
  }
  md << "\nWhat each knob adds at fixed h, against `" << variants.front()
     << "` (ratios of mean L2 error and of median seconds, per level):\n\n| configuration |";
  int levels = 0;
  for (const auto& [key, runs] : groups) levels = std::max(levels, key.second + 1);
  for (int l = 0; l < levels; ++l) md << " level " << l << " error | level " << l << " time |";
  md << "\n|---|";
  for (int l = 0; l < levels; ++l) md << "---|---|";
  md << "\n";
  auto find = [&](const std::string& v, int l) -> const Point* {
    for (const Point& p : points)
      if (p.variant == v && p.level == l) return &p;
    return nullptr;
  };
  for (const std::string& v : variants) {
    md << "| " << v << " |";
    for (int l = 0; l < levels; ++l) {
      const Point *p = find(v, l), *base = find(variants.front(), l);
      if (p && base) md << " " << fmt(p->error / base->error, 3) << " | " << fmt(p->seconds / base->seconds, 3) << " |";
      else md << " - | - |";
    }
    md << "\n";
  }
  md << "\n![tradeoff.png](tradeoff.png)\n\n";
  write_json(out / "tradeoff.json", data);
  (void)scene;
}

}  // namespace

std::pair<double, double> fit_rate(const std::vector<double>& h, const std::vector<double>& e) {
  const std::size_t n = h.size();
  double mx = 0, my = 0;
  for (std::size_t i = 0; i < n; ++i) mx += std::log(h[i]) / n, my += std::log(e[i]) / n;
  double sxx = 0, sxy = 0;
  for (std::size_t i = 0; i < n; ++i) {
    sxx += (std::log(h[i]) - mx) * (std::log(h[i]) - mx);
    sxy += (std::log(h[i]) - mx) * (std::log(e[i]) - my);
  }
  const double slope = sxy / sxx;
  double ss = 0;
  for (std::size_t i = 0; i < n; ++i) {
    const double fit = my + slope * (std::log(h[i]) - mx);
    ss += (std::log(e[i]) - fit) * (std::log(e[i]) - fit);
  }
  const double se = n > 2 ? std::sqrt(ss / (n - 2) / sxx) : NAN;
  return {slope, t95(static_cast<int>(n) - 2) * se};
}

json summarize_study(const Scene& scene, const std::vector<json>& results, const json& published) {
  std::vector<std::string> order;
  std::map<std::string, std::vector<json>> groups;
  for (const json& r : results) {
    const std::string key = group_key(scene, r);
    if (!groups.count(key)) order.push_back(key);
    groups[key].push_back(r);
  }
  json out = {{"scene", {{"name", scene.name}, {"study", scene.study},
                         {"description", scene.description}, {"problems", scene.problems}}},
              {"groups", json::array()}};
  const json rates = published.is_object() ? published.value("rates", json::object()) : json::object();
  for (const std::string& key : order) {
    const std::vector<json>& runs = groups[key];
    const json& first = runs.front();
    json g = {{"key", key}, {"mesh", first["mesh"]}, {"problem", first["problem"]},
              {"nu", first["nu"]}, {"variant", first["variant"]}, {"formulation", first["formulation"]},
              {"levels", json::array()}};
    if (first["kp"].get<double>() > 0) g["kp"] = first["kp"];
    int max_level = 0;
    for (const json& r : runs) max_level = std::max(max_level, r["level"].get<int>());
    for (int level = 0; level <= max_level; ++level) {
      std::vector<double> l2, energy, h, dofs, iterations;
      int count = 0, failed = 0;
      double size = 0;
      for (const json& r : runs) {
        if (r["level"].get<int>() != level) continue;
        ++count;
        size = r["size"].get<double>();
        if (!ok(r)) { ++failed; continue; }
        l2.push_back(r["l2_error"]);
        energy.push_back(r["energy_error"]);
        h.push_back(r["h_avg"]);
        dofs.push_back(r["dofs"]);
        iterations.push_back(r["iterations"]);
      }
      json lv = {{"level", level}, {"size", size}, {"runs", count}, {"failed", failed}};
      if (!l2.empty()) {
        lv["h_avg"] = stats(h)["mean"];
        lv["dofs"] = stats(dofs)["mean"];
        lv["l2"] = stats(l2);
        if (scene.energy_error) lv["energy"] = stats(energy);
        lv["iterations"] = {{"mean", stats(iterations)["mean"]}};
      }
      g["levels"].push_back(lv);
    }
    g["rate_l2"] = rate_json(runs, "l2_error", max_level + 1);
    if (scene.energy_error) g["rate_energy"] = rate_json(runs, "energy_error", max_level + 1);
    const std::string variant = first["variant"];
    for (const std::string& name : {key, variant})
      if (rates.contains(name) && rates[name].is_number())
        g["published"] = {{"l2_rate", rates[name]}, {"source", published.value("source", "")}};
    out["groups"].push_back(g);
  }
  if (!published.is_null()) out["published"] = published;
  return out;
}

int write_study_report(const Scene& scene, const std::vector<json>& results,
                       const std::filesystem::path& out) {
  // results.csv
  std::ostringstream csv;
  csv << "id,mesh,family,level,size,realization,seed,problem,nu,formulation,variant,kp,status,"
         "cells,dofs,h_avg,l2_error,energy_error,rcond,iterations,stop_reason,relative_gap,"
         "seconds_total,error\n";
  std::map<std::string, std::map<std::string, double>> timings;  // group -> stage -> seconds
  for (const json& r : results) {
    auto v = [&](const char* k) { return r.contains(k) ? (r[k].is_string() ? r[k].get<std::string>() : r[k].dump()) : std::string(); };
    double total = 0;
    if (r.contains("seconds"))
      for (const auto& [stage, s] : r["seconds"].items()) {
        total += s.get<double>();
        timings[group_key(scene, r)][stage] += s.get<double>();
      }
    std::string error = v("error");
    std::replace(error.begin(), error.end(), '"', '\'');
    csv << '"' << v("id") << "\"," << v("mesh") << ',' << v("family") << ',' << v("level") << ','
        << v("size") << ',' << v("realization") << ',' << v("seed") << ',' << v("problem") << ','
        << v("nu") << ',' << v("formulation") << ",\"" << v("variant") << "\"," << v("kp") << ','
        << v("status") << ',' << v("cells") << ',' << v("dofs") << ',' << v("h_avg") << ','
        << v("l2_error") << ',' << v("energy_error") << ',' << v("rcond") << ','
        << v("iterations") << ',' << v("stop_reason") << ',' << v("relative_gap") << ',' << total
        << ",\"" << error << "\"\n";
  }
  write_file_atomically(out / "results.csv", csv.str());
  write_json(out / "timings.json", json(timings));

  json published;
  if (!scene.reference.empty()) {
    const std::filesystem::path file = std::filesystem::path(VORODG_DATA_DIR) / "reference" / "published.json";
    try {
      const json all = json::parse(read_file(file));
      if (all.contains(scene.reference)) published = all[scene.reference];
    } catch (const std::exception&) {
      std::cerr << "note: no published values read from " << file << "\n";
    }
  }
  const json summary = summarize_study(scene, results, published);
  write_json(out / "summary.json", summary);

  // Console tables and report.md.
  std::ostringstream md;
  md << "# " << scene.name << "\n\n" << scene.description << "\n\n"
     << "Study: " << scene.study << "; problems: ";
  for (const auto& p : scene.problems) md << p << " ";
  md << "; E = " << scene.E << ", plane " << (scene.plane == PlaneModel::strain ? "strain" : "stress")
     << "; " << results.size() << " runs.\n\n";
  int unexpected = 0;
  if (scene.study == "patch-suite") {
    md << "| run | L2 error | energy error | verdict | expected |\n|---|---|---|---|---|\n";
    std::cout << "patch suite (tolerance " << scene.patch_tolerance << "):\n";
    for (const json& r : results) {
      const bool pass = ok(r) && r["l2_error"].get<double>() <= scene.patch_tolerance &&
                        r["energy_error"].get<double>() <= scene.patch_tolerance;
      const bool expect = expected_to_pass(scene, r);
      if (pass != expect) ++unexpected;
      const std::string verdict = !ok(r) ? "failed to run" : pass ? "pass" : "fail";
      const std::string l2 = ok(r) ? fixed(r["l2_error"]) : "-", en = ok(r) ? fixed(r["energy_error"]) : "-";
      md << "| " << r["id"].get<std::string>() << " | " << l2 << " | " << en << " | " << verdict << " | "
         << (expect ? "pass" : "fail") << (pass == expect ? "" : " **unexpected**") << " |\n";
      std::cout << "  " << std::left << std::setw(60) << r["id"].get<std::string>() << std::right
                << " L2 " << l2 << "  energy " << en << "  " << verdict
                << (pass == expect ? "" : "  (UNEXPECTED)") << "\n";
    }
    md << "\n" << unexpected << " outcomes differ from the expected ones.\n";
  } else {
    for (const json& g : summary["groups"]) {
      std::cout << "\n" << g["key"].get<std::string>() << "\n"
                << "  level      h_avg      dofs   mean L2 (± std)          rate   mean energy   rate   iter\n";
      md << "## " << g["key"].get<std::string>() << "\n\n"
         << "| level | h_avg | DOFs | runs | L2 error mean ± std | rate | energy error mean | rate | iterations |\n"
         << "|---|---|---|---|---|---|---|---|---|\n";
      json previous;
      for (const json& lv : g["levels"]) {
        if (!lv.contains("l2")) {
          md << "| " << lv["level"] << " | - | - | " << lv["runs"] << " | all failed | | | | |\n";
          continue;
        }
        auto rate = [&](const char* norm) -> std::string {
          if (previous.is_null() || !lv.contains(norm) || !previous.contains(norm)) return "-";
          return fmt(std::log(previous[norm]["mean"].get<double>() / lv[norm]["mean"].get<double>()) /
                         std::log(previous["h_avg"].get<double>() / lv["h_avg"].get<double>()), 3);
        };
        const std::string energy = lv.contains("energy") ? fixed(lv["energy"]["mean"]) : "-";
        std::cout << "  " << std::setw(5) << lv["level"].get<int>() << "  " << std::setw(9)
                  << fmt(lv["h_avg"], 4) << " " << std::setw(9) << fmt(lv["dofs"], 6) << "   "
                  << fixed(lv["l2"]["mean"]) << " ± " << fixed(lv["l2"]["std"], 1) << "  " << std::setw(6)
                  << rate("l2") << "   " << energy << "  " << std::setw(5) << rate("energy") << "  "
                  << fmt(lv["iterations"]["mean"], 3) << "\n";
        md << "| " << lv["level"] << " | " << fmt(lv["h_avg"], 4) << " | " << fmt(lv["dofs"], 6) << " | "
           << lv["runs"] << (lv["failed"].get<int>() ? " (" + lv["failed"].dump() + " failed)" : "")
           << " | " << fixed(lv["l2"]["mean"]) << " ± " << fixed(lv["l2"]["std"], 1) << " | "
           << rate("l2") << " | " << energy << " | " << rate("energy") << " | "
           << fmt(lv["iterations"]["mean"], 3) << " |\n";
        previous = lv;
      }
      auto describe_rate = [](const json& r) -> std::string {
        if (r.is_null()) return "-";
        std::string s = fmt(r["value"], 3);
        if (!r["ci95"].is_null()) s += " ± " + fmt(r["ci95"], 2);
        if (r.contains("pair_min"))
          s += " (per-realization pairs " + fmt(r["pair_min"], 3) + " .. " + fmt(r["pair_max"], 3) + ")";
        return s;
      };
      std::cout << "  least-squares rate: L2 " << describe_rate(g["rate_l2"]);
      md << "\nLeast-squares rates (95% interval): L2 " << describe_rate(g["rate_l2"]);
      if (g.contains("rate_energy")) {
        std::cout << ", energy " << describe_rate(g["rate_energy"]);
        md << ", energy " << describe_rate(g["rate_energy"]);
      }
      if (g.contains("published")) {
        const double ours = g["rate_l2"].is_null() ? NAN : g["rate_l2"]["value"].get<double>();
        const double theirs = g["published"]["l2_rate"].get<double>();
        std::cout << "; published L2 rate " << theirs;
        md << ".\nPublished L2 rate: " << theirs << " (" << g["published"]["source"].get<std::string>()
           << "); ours " << fmt(ours, 3)
           << (std::abs(ours - theirs) > 0.1 ? " — **differs** by more than 0.1 (reported as measured, not adjusted toward it)" : " — agrees");
      }
      std::cout << "\n";
      md << ".\n\n";
    }
  }
  // Rate against k_p, per formulation: the trend the report's Figure 26 claims, stated from our
  // numbers (a rise must exceed the 95% intervals to count).
  std::map<std::string, std::vector<std::pair<double, json>>> by_formulation;
  for (const json& g : summary["groups"])
    if (g.contains("kp") && !g["rate_l2"].is_null()) {
      const std::string variant = g["variant"];
      const std::string base = g["mesh"].get<std::string>() + " | " + g["problem"].get<std::string>() +
                               " | " + variant.substr(0, variant.rfind(" kp="));
      by_formulation[base].emplace_back(g["kp"].get<double>(), g["rate_l2"]);
    }
  for (auto& [base, rates] : by_formulation) {
    if (rates.size() < 2) continue;
    std::sort(rates.begin(), rates.end(), [](const auto& a, const auto& b) { return a.first < b.first; });
    md << "L2 rate against k_p for " << base << ":";
    bool rises = true;
    for (std::size_t i = 0; i < rates.size(); ++i) {
      const json& r = rates[i].second;
      md << (i ? ", " : " ") << "k_p " << fmt(rates[i].first) << " -> " << fmt(r["value"], 3);
      if (i > 0) {
        const json& q = rates[i - 1].second;
        const double margin = (r["ci95"].is_null() ? 0.0 : r["ci95"].get<double>()) +
                              (q["ci95"].is_null() ? 0.0 : q["ci95"].get<double>());
        rises = rises && r["value"].get<double>() > q["value"].get<double>() + margin;
      }
    }
    md << ". " << (rises ? "The rate rises with k_p." : "The rate does **not** rise with k_p beyond the 95% intervals.")
       << "\n\n";
  }
  if (scene.study == "trade-off") write_tradeoff(scene, results, out, md);
  if (published.is_object() && published.contains("trend"))
    md << "Published trend (" << published.value("source", "") << "): "
       << published["trend"].get<std::string>() << "\n\n";
  for (const char* png : {"convergence_l2.png", "convergence_energy.png", "penalty.png", "cdf_l2.png"})
    md << "![" << png << "](" << png << ")\n";
  write_file_atomically(out / "report.md", md.str());
  return unexpected;
}

}  // namespace vorodg
