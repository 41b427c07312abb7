#include "verification/harness/StatisticalReport.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <tuple>

#include "core/io/AtomicFile.hpp"
#include "core/schema/SceneObject.hpp"
#include "core/util/Format.hpp"
#include "verification/harness/RecordFields.hpp"
#include "verification/report/StatisticalConvergenceReport.hpp"

namespace vorodg {

std::vector<SceneKey> statistics_keys() {
  const StatisticalOptions d;
  return {
      key("statistics.quantities", "list of names", "none", "fields of the kind's records",
          "the quantities of interest whose convergence over the mesh levels is judged in "
          "distribution, of the mean and (levels sharing a random field) in mean and in "
          "probability: statistical-convergence.md and .csv (docs/statistics.md)"),
      bounded("statistics.confidence", "number", fmt(d.confidence), "0.5 <= confidence < 1",
              "the confidence of every interval and test of the report", 0.5, false, 1.0, true),
      bounded("statistics.tolerance", "number", fmt(d.tolerance), "0 < tolerance <= 1",
              "the resolution asked of a quantity, as a share of its scale (the finest level's "
              "|mean| or spread): epsilon of Pr(|D| > epsilon) and the bound on E|D| and on the "
              "change of the mean",
              0.0, true, 1.0),
      bounded("statistics.ks_resolution", "number", fmt(d.ks_resolution), "0 < ks_resolution < 1",
              "two levels' laws count as the same when the KS test sees no difference and could "
              "have seen one this large; the planner sizes the ensemble for it",
              0.0, true, 1.0, true),
      bounded("statistics.probability", "number", fmt(d.probability), "0 < probability < 1",
              "Pr(|D| > epsilon) below this counts as converged in probability", 0.0, true, 1.0,
              true),
      bounded("statistics.resamples", "integer", std::to_string(d.bootstrap.resamples),
              "100 <= resamples <= 1e6", "bootstrap resamples of each interval of a distance",
              100.0, false, 1e6),
  };
}

StatisticalSettings read_statistical_settings(SceneKeyReader& reader,
                                              const std::vector<std::string>& fields,
                                              bool coupled) {
  SceneObject o = reader.object("statistics");
  StatisticalSettings s;
  s.quantities = o.texts("quantities", {});
  for (const std::string& q : s.quantities)
    if (std::find(fields.begin(), fields.end(), q) == fields.end()) {
      const auto nearest = std::min_element(fields.begin(), fields.end(), [&](auto& a, auto& b) {
        return edit_distance(a, q) < edit_distance(b, q);
      });
      o.fail_value("quantities",
                   "'" + q + "' is not a number of this kind's records" +
                       (nearest != fields.end() ? " (nearest: " + *nearest + ")" : ""));
    }
  std::string listed;
  for (const std::string& q : s.quantities) listed += (listed.empty() ? "" : ", ") + q;
  reader.note("statistics.quantities", listed.empty() ? "none" : "[" + listed + "]");
  s.options.confidence = reader.number(o, "statistics.confidence");
  s.options.tolerance = reader.number(o, "statistics.tolerance");
  s.options.ks_resolution = reader.number(o, "statistics.ks_resolution");
  s.options.probability = reader.number(o, "statistics.probability");
  s.options.bootstrap.resamples = reader.integer(o, "statistics.resamples");
  s.options.bootstrap.confidence = s.options.confidence;
  s.options.coupled = coupled;
  o.finish();
  return s;
}

std::vector<QuantityConvergence> statistical_convergence_of(
    const std::vector<nlohmann::json>& records, const StatisticalSettings& settings) {
  std::vector<QuantityConvergence> out;
  for (const std::string& quantity : settings.quantities) {
    // (mesh block, level) -> the level's sample; h_avg the mean over its complete runs, so that
    // every quantity of a level has the same h.
    std::map<std::pair<std::string, int>, LevelSample> levels;
    for (const nlohmann::json& r : records) {
      if (!r.value("complete", true)) continue;
      LevelSample& l = levels[{r.at("mesh").get<std::string>(), r.at("level").get<int>()}];
      // Every complete run counts for the level's cost and for how many runs a value takes.
      l.complete.push_back(r.at("realization").get<int>());
      l.h_avg += read_number(r.at("h_avg"));
      if (r.contains("seconds")) l.core_seconds += read_number(r.at("seconds"));
      if (!r.contains(quantity)) continue;
      const double v = read_number(r.at(quantity));
      if (!std::isfinite(v)) continue;  // not measured in this run (a column that never struck)
      l.realization.push_back(l.complete.back());
      l.value.push_back(v);
    }
    std::map<std::string, std::vector<LevelSample>> by_mesh;
    for (auto& [key, l] : levels) {
      l.level = key.second;
      l.h_avg /= static_cast<double>(l.complete.size());
      if (l.value.size() >= 2) by_mesh[key.first].push_back(std::move(l));
    }
    for (auto& [mesh, samples] : by_mesh) {
      if (samples.size() < 2) continue;
      out.push_back(statistical_convergence(quantity, std::move(samples), settings.options));
      out.back().mesh = mesh;
    }
  }
  return out;
}

std::string write_statistical_report(const std::vector<nlohmann::json>& records,
                                     const StatisticalSettings& settings,
                                     const std::filesystem::path& out) {
  const std::vector<QuantityConvergence> q = statistical_convergence_of(records, settings);
  if (q.empty()) return "";
  const std::string md = statistical_convergence_md(q, settings.options);
  write_file_atomically(out / "statistical-convergence.csv", statistical_convergence_csv(q));
  write_file_atomically(out / "statistical-levels.csv", statistical_levels_csv(q));
  write_file_atomically(out / "statistical-convergence.md", md);
  return md;
}

}  // namespace vorodg
