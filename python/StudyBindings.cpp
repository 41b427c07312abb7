// vorodg.run: a study scene (a file, a shipped name, or a dict) run as `vorodg run` runs it,
// into an output folder, with its progress line; its summary and records come back as Python
// objects from the files the run wrote (the files are the result: a rerun resumes them).
#include <pybind11/iostream.h>
#include <pybind11/stl.h>

#include <filesystem>
#include <fstream>
#include <optional>

#include "core/io/AtomicFile.hpp"
#include "core/util/Errors.hpp"
#include "python/Bindings.hpp"
#include "verification/api/SceneStudy.hpp"
#include "verification/harness/Ensemble.hpp"
#include "verification/harness/StudyKind.hpp"

namespace vorodg::python {
namespace {

namespace fs = std::filesystem;

/// One folder's summary.json and results*.jsonl records (in file order).
py::dict folder_results(const fs::path& folder) {
  py::dict out;
  out["summary"] = fs::exists(folder / "summary.json")
                       ? to_python(nlohmann::json::parse(read_file(folder / "summary.json")))
                       : py::none();
  nlohmann::json records = nlohmann::json::array();
  std::vector<fs::path> files;
  for (const auto& e : fs::directory_iterator(folder))
    if (e.path().filename().string().starts_with("results") && e.path().extension() == ".jsonl")
      files.push_back(e.path());
  std::sort(files.begin(), files.end());
  for (const fs::path& file : files) {
    std::ifstream in(file);
    for (std::string line; std::getline(in, line);)
      if (!line.empty()) records.push_back(nlohmann::json::parse(line));
  }
  out["records"] = to_python(records);
  return out;
}

/// The run's results: the folder's own, and each variant's (a subfolder with a summary).
py::dict results(const fs::path& out) {
  py::dict r = folder_results(out);
  py::dict variants;
  for (const auto& e : fs::directory_iterator(out))
    if (e.is_directory() && fs::exists(e.path() / "summary.json"))
      variants[py::str(e.path().filename().string())] = folder_results(e.path());
  r["variants"] = variants;
  return r;
}

/// A scene given as a dict is written into the output folder as scene.json and run from there
/// (its relative mesh files then resolve against the output folder: give them absolute).
std::string scene_source(const py::handle& scene, const std::string& output) {
  if (py::isinstance<py::str>(scene) ||
      py::isinstance(scene, py::module_::import("os").attr("PathLike")))
    return py::str(scene);
  if (!py::isinstance<py::dict>(scene))
    throw InputError("run: scene " + std::string(py::str(py::repr(scene))) +
                     ": expected a file, a shipped scene's name or a dict");
  fs::create_directories(output);
  const fs::path file = fs::path(output) / "scene.json";
  write_file_atomically(file, from_python(scene).dump(2) + "\n");
  return file.string();
}

py::dict run(const py::handle& scene, const std::string& output, int threads, bool progress,
             bool plots, bool force, const std::optional<std::string>& shard) {
  if (output.empty()) throw InputError("run: expected an output folder");
  if (threads < 1) throw InputError("threads " + std::to_string(threads) + ": expected >= 1");
  SceneStudyOptions o;
  o.scene = scene_source(scene, output);
  o.out = output;
  o.threads = threads;
  o.quiet = !progress;
  o.no_plots = !plots;
  o.force = force;
  Ensemble::set_shard({});  // a shard is one call's, not the session's
  o.shard = shard.value_or("");
  int code = 0;
  {
    py::scoped_ostream_redirect out(std::cout, py::module_::import("sys").attr("stdout"));
    py::scoped_ostream_redirect err(std::cerr, py::module_::import("sys").attr("stderr"));
    // The runs' worker threads print through the redirection, which takes the interpreter's
    // lock: this thread must not hold it meanwhile.
    py::gil_scoped_release unlocked;
    code = run_scene_study(o);
  }
  Ensemble::set_shard({});
  py::dict r = results(output);
  r["exit_code"] = code;
  return r;
}

}  // namespace

void bind_study(py::module_& m) {
  m.def("run", &run, py::arg("scene"), py::arg("output"), py::arg("threads") = 2,
        py::arg("progress") = true, py::arg("plots") = true, py::arg("force") = false,
        py::arg("shard") = py::none(),
        "Runs a study scene as `vorodg run SCENE -o OUTPUT --threads N` does (a file, a shipped "
        "scene's name, or a dict, written to OUTPUT/scene.json): the same files, the same "
        "progress line (unless progress=False), a rerun resumes. Returns a dict: summary "
        "(summary.json), records (results.jsonl), variants (per variant label: its summary and "
        "records) and exit_code (0, or the program's code for incomplete runs).");
  m.def(
      "scene_keys",
      [](const std::string& kind) { return key_table_markdown(study_kind(kind, "scene_keys: ")); },
      py::arg("kind"),
      "Every key of a study kind (as `vorodg run --keys KIND`): a Markdown table of name, type, "
      "default, range and meaning.");
  // An AMG solve may have started an MPI session: end it with the interpreter.
  py::module_::import("atexit").attr("register")(py::cpp_function([] { Ensemble::stop(); }));
}

}  // namespace vorodg::python
