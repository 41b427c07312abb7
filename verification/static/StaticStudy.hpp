#pragma once
// The solve ensemble behind the static study kinds (convergence, penalty-sweep, patch-suite,
// trade-off): every run of the scene (StudyRunner), then the study report with its tables,
// plots and summary (StudyReport). A kind gives its report sections and may check the finished
// runs before the report.
#include <functional>
#include <vector>

#include "verification/harness/StudyKind.hpp"
#include "verification/solve/RunRecord.hpp"
#include "verification/static/Scene.hpp"
#include "verification/static/StaticSceneKeys.hpp"
#include "verification/static/StudyReport.hpp"
#include "verification/static/StudyRunner.hpp"

namespace vorodg {

/// The harness's options of a run, in the static runner's terms.
StudyOptions study_options(const StudyCall& call);

/// Runs the scene, then `check` (if any) on its records, then writes the report with the kind's
/// `sections` and its plots. Returns 1 if the sections found outcomes other than the expected
/// ones (a patch suite's), else 0.
int run_static_study(
    const Scene& scene, const StudyCall& call,
    const ReportSections& sections = convergence_sections,
    const std::function<void(const std::vector<RunRecord>&, const StudyOptions&)>& check = {});

/// The registry's reader of a static kind whose scenes have that form: reads and validates,
/// returns the description.
std::function<std::string(const std::string&, const std::string&)> static_scene_reader(
    StaticSceneForm form = {});

}  // namespace vorodg
