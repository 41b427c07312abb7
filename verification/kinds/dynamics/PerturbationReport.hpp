#pragma once
// The report of a `perturb` study (report section 7, Figures 21 and 22): every run of every
// variant perturb-<i> against the same run (same mesh, level, realization) of perturb-0, by the
// Hamming distance of their crack states after every step at which either cracked
// (fracture/CrackHistory). Written to DIR/perturbation.csv (variant, value, run, step, distance)
// and DIR/perturbation.md (per variant and run: the final distance and the first step at which
// the states differ), both atomically, from the variants' cracks/<run id>.csv.
#include <filesystem>

#include "verification/kinds/dynamics/DynamicsScene.hpp"

namespace vorodg {

/// `scene` is the top-level scene of a perturb study, `out` its output folder (the variants'
/// results in out/<label>/). Throws InputError if a variant's crack list is missing or malformed.
void write_perturbation_report(const DynamicsScene& scene, const std::filesystem::path& out);

}  // namespace vorodg
