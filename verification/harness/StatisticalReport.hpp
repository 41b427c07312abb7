#pragma once
// The statistical-convergence report of an ensemble scene with several mesh levels
// (docs/statistics.md): the scene's `statistics` block names the quantities of interest (fields
// of the kind's records) and how they are judged; after the study, each quantity of each mesh
// block with two or more levels of two or more complete runs is analysed
// (report/StatisticalConvergence) and the whole written as statistical-convergence.md and .csv.
#include <filesystem>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "core/schema/SceneKeyReader.hpp"
#include "core/schema/SceneKeys.hpp"
#include "verification/report/StatisticalConvergence.hpp"

namespace vorodg {

struct StatisticalSettings {
  std::vector<std::string> quantities;  // none: no report
  StatisticalOptions options;
};

/// statistics.quantities, .confidence, .tolerance, .ks_resolution, .probability, .resamples.
std::vector<SceneKey> statistics_keys();

/// Reads the `statistics` block; a quantity that is not one of `fields` (the kind's numeric
/// record fields) is refused in one line naming the nearest. `coupled`: the scene's levels share
/// their random material field.
StatisticalSettings read_statistical_settings(SceneKeyReader& reader,
                                              const std::vector<std::string>& fields, bool coupled);

/// The analyses of the complete records (JSON lines with mesh, level, h_avg, realization and the
/// quantities), per mesh block and quantity, where there is something to analyse.
std::vector<QuantityConvergence> statistical_convergence_of(
    const std::vector<nlohmann::json>& records, const StatisticalSettings& settings);

/// Writes DIR/statistical-convergence.md and .csv; returns the Markdown (empty, and nothing
/// written, when no quantity has two levels to compare).
std::string write_statistical_report(const std::vector<nlohmann::json>& records,
                                     const StatisticalSettings& settings,
                                     const std::filesystem::path& out);

}  // namespace vorodg
