#pragma once
// From a study's results to what a researcher reads: statistics per (mesh, problem, material,
// variant) and level over the realizations (mean, standard deviation, min, max, the values
// themselves for CDFs), least-squares convergence rates with 95% intervals and the spread of the
// per-realization rates between consecutive levels; then the console table (as deal.II's
// ConvergenceTable), results.csv, summary.json (deterministic: no wall times), timings.json and
// report.md with each rate beside the published one.
#include <filesystem>
#include <nlohmann/json.hpp>
#include <vector>

#include "verification/study/Scene.hpp"

namespace vorodg {

/// The deterministic summary of a study (the same results give the same bytes).
nlohmann::json summarize_study(const Scene& scene, const std::vector<nlohmann::json>& results,
                               const nlohmann::json& published);

/// Writes results.csv, summary.json, timings.json and report.md into `out` (atomically) and
/// prints the convergence tables. Returns the number of patch-suite runs whose outcome was not
/// the expected one (0 for other studies).
int write_study_report(const Scene& scene, const std::vector<nlohmann::json>& results,
                       const std::filesystem::path& out);

/// Least-squares slope of log(e) against log(h) and its 95% confidence half-width.
std::pair<double, double> fit_rate(const std::vector<double>& h, const std::vector<double>& e);

}  // namespace vorodg
