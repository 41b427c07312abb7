#include "verification/cli/RunCommand.hpp"

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <iomanip>
#include <iostream>
#include <nlohmann/json.hpp>
#include <sstream>

#include "core/io/AtomicFile.hpp"
#include "core/util/Errors.hpp"
#include "core/util/Stopwatch.hpp"
#include "verification/cli/CliSupport.hpp"
#include "verification/dynamics/DynamicsStudy.hpp"
#include "verification/dynamics/PerturbationReport.hpp"
#include "verification/fracture/FractureStudy.hpp"
#include "verification/study/Ensemble.hpp"
#include "verification/study/ExtremesReport.hpp"
#include "verification/study/Scene.hpp"
#include "verification/study/StudyReport.hpp"
#include "verification/study/StudyRunner.hpp"
#include "verification/study/TradeoffVerification.hpp"

namespace vorodg {
namespace {

namespace fs = std::filesystem;

fs::path scenes_dir() {
  return fs::path(VORODG_DATA_DIR) / "scenes";
}

/// A scene given by name ("demo") is looked up among the shipped ones.
/// "K/N" of --shard.
Shard parse_shard(const std::string& text) {
  Shard shard;
  char slash = 0;
  std::istringstream in(text);
  if (!(in >> shard.index >> slash >> shard.count) || slash != '/' || !in.eof())
    throw InputError("--shard '" + text + "': expected K/N, e.g. 3/16");
  return shard;
}

/// Names the scene in the output folder (for `vorodg merge`), once its runs are done: bad input
/// leaves nothing behind. Rank 0 of an MPI job, or each shard, writes it.
void record_scene(const fs::path& out, const fs::path& scene) {
  if (!Ensemble::coordinator()) return;
  write_file_atomically(out / kRunInfoFile,
                        nlohmann::json{{"scene", fs::absolute(scene).string()}}.dump(1) + "\n");
}

fs::path resolve_scene(const std::string& name) {
  if (fs::exists(name)) return name;
  const fs::path shipped = scenes_dir() / (name + ".json");
  if (fs::exists(shipped)) return shipped;
  throw InputError("scene '" + name +
                   "': no such file, and no shipped scene of that name (see vorodg run --list)");
}

int list_scenes() {
  std::vector<fs::path> files;
  for (const auto& e : fs::directory_iterator(scenes_dir()))
    if (e.path().extension() == ".json") files.push_back(e.path());
  std::sort(files.begin(), files.end());
  for (const fs::path& f : files) {
    std::cout << std::left << std::setw(28) << f.stem().string();
    if (is_fracture_scene(f)) {  // its own keys: the convergence reader would refuse them
      std::cout << "fracture: " << read_fracture_scene(f).description << "\n";
    } else if (is_dynamics_scene(f)) {
      const DynamicsScene d = read_dynamics_scene(f, true);
      std::cout << (d.fragmentation ? "fragmentation: " : "dynamics: ") << d.description << "\n";
    } else {
      const Scene s = read_scene(f);
      std::cout << s.study << ": " << s.description << "\n";
    }
  }
  return 0;
}

/// Draws the plots with Debian's python and matplotlib; a missing plotter is a note, not an
/// error (the numbers are all in the report files).
void draw_plots(const fs::path& out) {
  const fs::path script = fs::path(VORODG_SOURCE_DIR) / "scripts" / "plot_study.py";
  const char* python = fs::exists("/usr/bin/python3") ? "/usr/bin/python3" : "python3";
  if (!fs::exists(script)) {
    std::cerr << "note: " << script << " not found; no plots drawn\n";
    return;
  }
  const std::string cmd =
      std::string(python) + " '" + script.string() + "' '" + out.string() + "' >/dev/null";
  if (std::system(cmd.c_str()) != 0)
    std::cerr << "note: the plots could not be drawn (" << cmd << ")\n";
}

/// Draws the fracture study's pictures with scripts/fracture_plots.py (a note if it cannot).
void draw_fracture_plots(const fs::path& out) {
  const fs::path script = fs::path(VORODG_SOURCE_DIR) / "scripts" / "fracture_plots.py";
  const char* python = fs::exists("/usr/bin/python3") ? "/usr/bin/python3" : "python3";
  const std::string cmd =
      std::string(python) + " '" + script.string() + "' '" + out.string() + "' >/dev/null";
  if (!fs::exists(script) || std::system(cmd.c_str()) != 0)
    std::cerr << "note: the fracture plots could not be drawn (" << cmd << ")\n";
}

/// Draws the dynamics study's energy plots with scripts/dynamics_plots.py (a note if it cannot).
void draw_dynamics_plots(const fs::path& out) {
  const fs::path script = fs::path(VORODG_SOURCE_DIR) / "scripts" / "dynamics_plots.py";
  const char* python = fs::exists("/usr/bin/python3") ? "/usr/bin/python3" : "python3";
  const std::string cmd =
      std::string(python) + " '" + script.string() + "' '" + out.string() + "' >/dev/null";
  if (!fs::exists(script) || std::system(cmd.c_str()) != 0)
    std::cerr << "note: the dynamics plots could not be drawn (" << cmd << ")\n";
}

/// A dynamics study (each variant in its own subfolder), after echoing every scene key with the
/// value used. A run that became unstable or broke down keeps its history; the study then
/// exits 3.
int run_dynamics(const fs::path& path, const StudyOptions& options, bool no_plots, bool force,
                 const Stopwatch& clock) {
  const DynamicsScene scene = read_dynamics_scene(path, force);
  std::vector<const DynamicsScene*> parts;
  if (scene.variants.empty()) parts.push_back(&scene);
  for (const DynamicsScene& v : scene.variants) parts.push_back(&v);
  int incomplete = 0;
  std::size_t runs = 0;
  for (const DynamicsScene* part : parts) {
    const fs::path out = part->label.empty() ? options.out : options.out / part->label;
    std::cout << "\n== " << (part->label.empty() ? part->name : part->label) << "\n";
    for (const auto& [key, value] : part->settings)
      std::cout << "#   " << key << " = " << value << "\n";
    const DynamicsStudyResult r = run_dynamics_study(*part, out, options.threads, options.progress);
    incomplete += r.incomplete;
    runs += r.records.size();
    if (!no_plots && Ensemble::writes_reports()) draw_dynamics_plots(out);
  }
  record_scene(options.out, path);
  if (!Ensemble::writes_reports()) return 0;  // the reports are the coordinator's
  if (!scene.perturb_key.empty() && incomplete == 0) write_perturbation_report(scene, options.out);
  if (scene.fragmentation && scene.variants.size() >= 2 && !no_plots)
    draw_dynamics_plots(options.out);  // across the variants (and the perturbation plot)
  std::cout << "\n" << scene.name << ": " << runs << " runs, " << clock.seconds() << " s\n";
  if (incomplete > 0) {
    std::cerr << "vorodg: " << incomplete << " dynamics runs are incomplete (see report.md)\n";
    return 3;
  }
  return 0;
}

/// A fracture study (each variant in its own subfolder). A run whose path could not be
/// followed to its end keeps its converged points; the study then exits 3.
int run_fracture(const fs::path& path, const StudyOptions& options, bool no_plots,
                 const Stopwatch& clock) {
  const FractureScene scene = read_fracture_scene(path);
  std::vector<const FractureScene*> parts;
  if (scene.variants.empty()) parts.push_back(&scene);
  for (const FractureScene& v : scene.variants) parts.push_back(&v);
  int incomplete = 0;
  std::size_t runs = 0;
  for (const FractureScene* part : parts) {
    const fs::path out = part->label.empty() ? options.out : options.out / part->label;
    if (!part->label.empty()) std::cout << "\n== " << part->label << "\n";
    const FractureStudyResult r = run_fracture_study(*part, out, options.threads, options.progress);
    incomplete += r.incomplete;
    runs += r.records.size();
    if (!no_plots && Ensemble::writes_reports()) draw_fracture_plots(out);
  }
  record_scene(options.out, path);
  if (!Ensemble::writes_reports()) return 0;  // the reports are the coordinator's
  std::cout << "\n" << scene.name << ": " << runs << " runs, " << clock.seconds() << " s\n";
  if (incomplete > 0) {
    std::cerr << "vorodg: " << incomplete << " fracture runs are incomplete (see report.md)\n";
    return 3;
  }
  return 0;
}

/// An extremes study: each sweep runs (and reports) in its own subfolder, then every run gets
/// its verdict. Broken runs are findings of the study, not a failure of the program: exit 0.
int run_extremes(const Scene& scene, const StudyOptions& options, bool no_plots,
                 const Stopwatch& clock) {
  std::vector<std::vector<RunRecord>> results;
  std::size_t runs = 0;
  for (const auto& sweep : scene.sweeps) {
    StudyOptions sub = options;
    sub.out = options.out / sweep->name;
    std::cout << "\n== sweep " << sweep->name << " (" << sweep->axis << ")\n";
    results.push_back(run_study(*sweep, sub));
    if (!Ensemble::writes_reports()) continue;  // the reports are the coordinator's
    // A sweep's own report has no pictures: the extremes plot stands for them all.
    finish_report_markdown(write_study_report(*sweep, results.back(), sub.out).markdown, sub.out,
                           {});
    runs += results.back().size();
  }
  if (!Ensemble::writes_reports()) return 0;
  std::string markdown;
  const int broken = write_extremes_report(scene, results, options.out, markdown);
  if (!no_plots) draw_plots(options.out);
  finish_report_markdown(markdown, options.out, study_pictures());
  std::cout << "\n"
            << scene.name << ": " << runs << " runs (" << broken << " broken), " << clock.seconds()
            << " s; report in " << (options.out / "report.md").string() << "\n";
  return 0;
}

}  // namespace

CLI::App* add_run_command(CLI::App& app, RunCommandOptions& o) {
  CLI::App* cmd = app.add_subcommand("run", "Run a study scene and write its report");
  cmd->add_option("scene", o.scene, "Scene file (.json) or the name of a shipped scene");
  cmd->add_option("-o,--output", o.out, "Output folder (created; a rerun resumes)");
  cmd->add_option("--threads", o.threads, "Runs in parallel")->capture_default_str();
  cmd->add_flag("--list", o.list, "List the shipped scenes");
  cmd->add_flag("--no-plots", o.no_plots, "Skip the PNG plots");
  cmd->add_flag("--quiet", o.quiet, "No progress bar");
  cmd->add_option("--shard", o.shard,
                  "K/N: run only the tasks whose place is K modulo N, into their own results "
                  "file (a job array without MPI; then `vorodg merge DIR`)");
  cmd->add_flag("--force", o.force,
                "Dynamics scenes: allow time.safety >= 1 (a step at or above the critical one)");
  return cmd;
}

int run_run_command(const RunCommandOptions& o, const CLI::App& command) {
  if (o.list) return list_scenes();
  if (o.scene.empty())
    throw InputError("run: expected a scene (a file or a shipped name; see --list)");
  if (o.out.empty()) throw InputError("run: expected an output folder (-o DIR)");
  if (o.threads < 1) throw InputError("--threads " + std::to_string(o.threads) + ": expected >= 1");
  echo_options("vorodg run", command);
  return run_study_scene(o);
}

int run_study_scene(const RunCommandOptions& o) {
  if (!o.shard.empty()) Ensemble::set_shard(parse_shard(o.shard));
  const fs::path scene_path = fs::absolute(resolve_scene(o.scene));
  Stopwatch clock;
  StudyOptions options;
  options.out = o.out;
  options.threads = o.threads;
  options.progress = !o.quiet;
  if (is_fracture_scene(scene_path)) return run_fracture(scene_path, options, o.no_plots, clock);
  if (is_dynamics_scene(scene_path))
    return run_dynamics(scene_path, options, o.no_plots, o.force, clock);
  const Scene scene = read_scene(scene_path);
  if (scene.study == "extremes") {
    const int code = run_extremes(scene, options, o.no_plots, clock);
    record_scene(o.out, scene_path);
    return code;
  }
  const auto results = run_study(scene, options);
  if (scene.study == "trade-off") run_tradeoff_check(scene, results, options);
  record_scene(o.out, scene_path);
  if (!Ensemble::writes_reports()) return 0;  // the reports are the coordinator's
  const StudyReport report = write_study_report(scene, results, o.out);
  if (!o.no_plots) draw_plots(o.out);
  finish_report_markdown(report.markdown, o.out, study_pictures());
  const int unexpected = report.unexpected;
  std::cout << "\n"
            << scene.name << ": " << results.size() << " runs, " << clock.seconds()
            << " s; report in " << (fs::path(o.out) / "report.md").string() << "\n";
  if (unexpected > 0) {
    std::cerr << "vorodg: " << unexpected
              << " patch-suite outcomes differ from the expected ones\n";
    return 1;
  }
  return 0;
}

}  // namespace vorodg
