#pragma once
// The report of a time-refinement study (`time.refinement`, docs/dynamics.md "Time refinement"):
// for each refined part and each (mesh block, level), every measure at every fraction of the
// step over the complete realizations (mean and standard error), the differences between
// successive steps with their standard errors, the observed order and the extrapolated value
// dt -> 0 where the trend is monotone over three or more steps with shrinking differences
// (Extrapolation: Richardson with the observed order), a weighted line against the step (its
// slope and the slope's standard error: zero within two says the measure no longer moves with
// the step), and for fragmentation the two-sample Kolmogorov-Smirnov distance between the pooled
// fragment masses of successive steps. Written as DIR/time-refinement.csv (one row per measure
// and step) and DIR/time-refinement.md.
#include <filesystem>
#include <vector>

#include "verification/kinds/dynamics/DynamicsRun.hpp"

namespace vorodg {

/// One part of a time-refinement study as it ran: its scene, its records and its folder.
struct RefinedPart {
  const DynamicsScene* scene = nullptr;
  std::vector<DynamicsRecord> records;
  std::filesystem::path folder;
};

/// What one measure did over the steps of one (part, mesh block, level).
struct StepTrend {
  std::vector<double> fraction, mean, std_error;  // per step, coarse to fine
  std::vector<int> runs;
  double slope = NAN, slope_error = NAN;   // of the weighted line mean = a + slope x fraction
  double order = NAN, extrapolated = NAN;  // settling over >= 3 steps only
};

/// The trend of values[i] (the sample at fraction[i]); non-finite values are left out.
StepTrend step_trend(const std::vector<double>& fraction,
                     const std::vector<std::vector<double>>& values);

/// Writes DIR/time-refinement.csv and .md for the refined parts (in the scene's order, each
/// group's steps descending). Does nothing without a refined part.
void write_time_refinement_report(const DynamicsScene& top, const std::vector<RefinedPart>& parts,
                                  const std::filesystem::path& out);

}  // namespace vorodg
