#pragma once
// The fragment statistics of a fragmentation study per mesh level (docs/fragmentation.md, "Over
// the levels"): over the complete realizations of each (mesh block, level), the fragment count,
// the largest fragment's mass fraction and the run time, and the pooled fragment mass fractions
// (each fragment's mass over its run's total, read from fragments/<run>.csv). The levels are
// ordered from coarse to fine by h_avg, and the two-sample Kolmogorov-Smirnov distance between the
// pooled fractions of each level and the next coarser one says whether the distributions settle.
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "verification/kinds/dynamics/DynamicsRun.hpp"
#include "verification/report/KolmogorovSmirnov.hpp"
#include "verification/report/SampleStatistics.hpp"

namespace vorodg {

struct FragmentLevel {
  std::string mesh;  // the mesh block's label
  int level = 0;
  double h_avg = 0.0;  // mean over the realizations
  SampleStatistics fragments, largest;
  double median_seconds = 0.0;
  std::vector<double> mass_fractions;       // every fragment of every realization
  std::optional<KsResult> against_coarser;  // none for the coarsest level
};

/// The levels with at least one complete run, coarse to fine; `out` holds fragments/<run>.csv.
/// Throws InputError naming the file if a fragment table is missing or malformed.
std::vector<FragmentLevel> fragment_levels(const std::vector<DynamicsRecord>& records,
                                           const std::filesystem::path& out);

/// levels.csv: mesh,level,h_avg,runs,fragments_mean,fragments_sd,largest_mean,largest_sd,
/// median_seconds,fragments_pooled,ks_distance,ks_p_value (the last two empty at the coarsest).
std::string fragment_levels_csv(const std::vector<FragmentLevel>& levels);
/// The report's section: the table and what the KS distances say.
std::string fragment_levels_md(const std::vector<FragmentLevel>& levels);

}  // namespace vorodg
