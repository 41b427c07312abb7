#include "verification/static/StudySummary.hpp"

#include <algorithm>
#include <cmath>
#include <iostream>
#include <map>

#include "core/io/AtomicFile.hpp"
#include "core/util/Format.hpp"
#include "verification/harness/StudyFiles.hpp"

namespace vorodg {
namespace {

using nlohmann::json;

std::optional<RateSummary> rate_summary(const std::vector<const RunRecord*>& records,
                                        double RunMetrics::*error, int levels) {
  std::vector<double> h, e;
  std::map<int, std::map<int, std::pair<double, double>>> by_realization;  // r -> level -> (h, e)
  for (const RunRecord* r : records) {
    if (!r->ok() || !((*r->metrics).*error > 0)) continue;
    h.push_back(r->metrics->h_avg);
    e.push_back((*r->metrics).*error);
    by_realization[r->run.realization][r->run.level] = {h.back(), e.back()};
  }
  if (levels < 2 || h.size() < 2) return std::nullopt;
  RateSummary out{fit_rate(h, e), {}, {}, {}};
  std::vector<double> pairs;
  for (const auto& [realization, by_level] : by_realization)
    for (auto it = by_level.begin(); std::next(it) != by_level.end(); ++it) {
      const auto& [h0, e0] = it->second;
      const auto& [h1, e1] = std::next(it)->second;
      pairs.push_back(pair_rate(h0, e0, h1, e1));
    }
  if (!pairs.empty()) {
    std::sort(pairs.begin(), pairs.end());
    out.pair_min = pairs.front();
    out.pair_median = pairs[pairs.size() / 2];
    out.pair_max = pairs.back();
  }
  return out;
}

LevelSummary level_summary(const Scene& scene, const std::vector<const RunRecord*>& records,
                           int level) {
  LevelSummary lv;
  lv.level = level;
  std::vector<double> l2, energy, h, dofs, iterations;
  for (const RunRecord* r : records) {
    if (r->run.level != level) continue;
    ++lv.runs;
    lv.size = r->run.size;
    if (!r->ok()) {
      ++lv.failed;
      continue;
    }
    const RunMetrics& m = *r->metrics;
    if (m.stop_reason() == "diverged") ++lv.diverged;
    l2.push_back(m.l2_error);
    energy.push_back(m.energy_error);
    h.push_back(m.h_avg);
    dofs.push_back(m.dofs);
    iterations.push_back(m.iterations());
  }
  if (l2.empty()) return lv;
  lv.h_avg = sample_statistics(h).mean;
  lv.dofs = sample_statistics(dofs).mean;
  lv.iterations = sample_statistics(iterations).mean;
  lv.l2 = sample_statistics(l2);
  if (scene.energy_error) lv.energy = sample_statistics(energy);
  return lv;
}

json statistics_json(const SampleStatistics& s) {
  json out = {{"mean", s.mean}, {"min", s.min}, {"max", s.max}, {"values", s.values}};
  if (s.std_dev) out["std"] = *s.std_dev;  // only with two or more realizations
  return out;
}

json rate_json(const std::optional<RateSummary>& rate) {
  if (!rate) return json();
  json out = {{"value", rate->fit.rate},
              {"intercept", rate->fit.intercept},
              {"points", rate->fit.points},
              {"ci95", rate->fit.ci95 ? json(*rate->fit.ci95) : json()}};
  if (rate->pair_min) {
    out["pair_min"] = *rate->pair_min;
    out["pair_median"] = *rate->pair_median;
    out["pair_max"] = *rate->pair_max;
  }
  return out;
}

json level_json(const LevelSummary& lv) {
  json out = {{"level", lv.level}, {"size", lv.size}, {"runs", lv.runs}, {"failed", lv.failed}};
  if (lv.diverged) out["diverged"] = lv.diverged;  // absent when none, as in older summaries
  if (!lv.l2) return out;
  out["h_avg"] = *lv.h_avg;
  out["dofs"] = *lv.dofs;
  out["l2"] = statistics_json(*lv.l2);
  if (lv.energy) out["energy"] = statistics_json(*lv.energy);
  out["iterations"] = {{"mean", *lv.iterations}};
  return out;
}

}  // namespace

std::string group_key(const Scene& scene, const StudyRun& r) {
  std::string key = r.mesh_label + " | " + r.problem;
  if (scene.nu.size() > 1) key += " | nu=" + fmt(r.nu, 12);
  return key + " | " + r.variant;
}

StudySummary summarize_study(const Scene& scene, const std::vector<RunRecord>& records,
                             const json& published) {
  std::vector<std::string> order;
  std::map<std::string, std::vector<const RunRecord*>> groups;
  for (const RunRecord& r : records) {
    const std::string key = group_key(scene, r.run);
    if (!groups.count(key)) order.push_back(key);
    groups[key].push_back(&r);
  }
  const json rates =
      published.is_object() ? published.value("rates", json::object()) : json::object();
  StudySummary summary{{}, published};
  for (const std::string& key : order) {
    const std::vector<const RunRecord*>& runs = groups[key];
    const StudyRun& first = runs.front()->run;
    GroupSummary g{key,
                   first.mesh_label,
                   first.problem,
                   first.formulation_name,
                   first.formulation_label,
                   first.variant,
                   first.nu,
                   first.kp,
                   {},
                   {},
                   {},
                   {}};
    int max_level = 0;
    for (const RunRecord* r : runs) max_level = std::max(max_level, r->run.level);
    for (int level = 0; level <= max_level; ++level)
      g.levels.push_back(level_summary(scene, runs, level));
    g.rate_l2 = rate_summary(runs, &RunMetrics::l2_error, max_level + 1);
    if (scene.energy_error)
      g.rate_energy = rate_summary(runs, &RunMetrics::energy_error, max_level + 1);
    for (const std::string& name : {key, g.variant})
      if (rates.contains(name) && rates[name].is_number())
        g.published_l2_rate = rates[name].get<double>();
    summary.groups.push_back(std::move(g));
  }
  return summary;
}

json published_reference(const Scene& scene) {
  if (scene.reference.empty()) return json();
  const std::filesystem::path file =
      std::filesystem::path(VORODG_DATA_DIR) / "reference" / "published.json";
  try {
    const json all = json::parse(read_file(file));
    if (all.contains(scene.reference)) return all[scene.reference];
  } catch (const std::exception&) {
    std::cerr << "note: no published values read from " << file << "\n";
  }
  return json();
}

json to_json(const Scene& scene, const StudySummary& summary) {
  json out = summary_head(scene.name, scene.study);
  out.update({{"description", scene.description},
              {"problems", scene.problems},
              {"groups", json::array()}});
  for (const GroupSummary& g : summary.groups) {
    json j = {{"key", g.key},     {"mesh", g.mesh},         {"problem", g.problem},
              {"nu", g.nu},       {"variant", g.variant},   {"formulation", g.formulation},
              {"label", g.label}, {"levels", json::array()}};
    if (g.kp) j["kp"] = *g.kp;
    for (const LevelSummary& lv : g.levels) j["levels"].push_back(level_json(lv));
    j["rate_l2"] = rate_json(g.rate_l2);
    if (scene.energy_error) j["rate_energy"] = rate_json(g.rate_energy);
    if (g.published_l2_rate)
      j["published"] = {{"l2_rate", *g.published_l2_rate},
                        {"source", summary.published.value("source", "")}};
    out["groups"].push_back(j);
  }
  if (!summary.published.is_null()) out["published"] = summary.published;
  return out;
}

}  // namespace vorodg
