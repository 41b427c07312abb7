#include "verification/kinds/dynamics/PerturbationReport.hpp"

#include <algorithm>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "core/io/AtomicFile.hpp"
#include "core/util/Errors.hpp"
#include "fracture/CrackHistory.hpp"
#include "verification/kinds/dynamics/DynamicsRun.hpp"
#include "verification/report/ConvergenceTable.hpp"

namespace fs = std::filesystem;

namespace vorodg {
namespace {

/// A run's crack events from its cracks/<id>.csv (header step,edge).
std::vector<CrackEvent> read_events(const fs::path& file) {
  std::ifstream in(file);
  if (!in) throw InputError(file.string() + ": cannot read (did the run finish?)");
  std::string line;
  std::getline(in, line);
  if (line != "step,edge")
    throw InputError(file.string() + ": expected the header step,edge, found '" + line + "'");
  std::vector<CrackEvent> events;
  for (int row = 2; std::getline(in, line); ++row) {
    std::istringstream fields(line);
    CrackEvent e{};
    char comma = 0;
    if (!(fields >> e.step >> comma >> e.edge) || comma != ',' || e.step < 0 || e.edge < 0)
      throw InputError(file.string() + ":" + std::to_string(row) + ": expected step,edge, found '" +
                       line + "'");
    events.push_back(e);
  }
  return events;
}

}  // namespace

void write_perturbation_report(const DynamicsScene& scene, const fs::path& out) {
  if (scene.variants.size() < 2 || scene.perturb_values.size() != scene.variants.size())
    throw InputError("perturbation report: expected a perturb scene with two or more values");
  ColumnStyle plain, quoted;  // the value is JSON text: quoted, since arrays hold commas
  plain.csv_quoted = false;
  ConvergenceTable steps, runs;  // perturbation.csv: every step; the report: every run
  for (const char* name : {"variant", "value", "run", "step", "distance"})
    steps.declare_column(name, std::string(name) == "value" ? quoted : plain);
  const fs::path reference = out / scene.variants[0].label / "cracks";
  for (std::size_t i = 1; i < scene.variants.size(); ++i) {
    const DynamicsScene& v = scene.variants[i];
    for (const EnsembleRunId& id : ensemble_runs(v.meshes)) {
      const std::string file = id.id() + ".csv";
      const auto ref = read_events(reference / file),
                 mine = read_events(out / v.label / "cracks" / file);
      const std::vector<DistanceAtStep> history = hamming_history(mine, ref);
      long first = -1;
      int largest = 0;
      for (const DistanceAtStep& d : history) {
        largest = std::max(largest, d.distance);
        steps.start_row();
        steps.add_text("variant", v.label);
        steps.add_text("value", scene.perturb_values[i]);
        steps.add_text("run", id.id());
        steps.add_value("step", static_cast<double>(d.step), {}, integer_style());
        steps.add_value("distance", d.distance, {}, integer_style());
        if (first < 0 && d.distance > 0) first = d.step;
      }
      runs.start_row();
      runs.add_text("variant", v.label);
      runs.add_text(scene.perturb_key, scene.perturb_values[i]);
      runs.add_text("run", id.id());
      runs.add_text("cracks (this, reference)",
                    std::to_string(mine.size()) + ", " + std::to_string(ref.size()));
      runs.add_text("first step that differs", first < 0 ? "-" : std::to_string(first));
      runs.add_value("largest distance", largest, {}, integer_style());
      runs.add_value("final distance", history.empty() ? 0 : history.back().distance, {},
                     integer_style());
    }
  }
  std::ostringstream csv, md;
  steps.write_csv(csv, {.quote_names = false});
  md << "# " << scene.name << ": sensitivity to " << scene.perturb_key << "\n\n"
     << "Hamming distance of each run's crack state to the same run of `perturb-0` ("
     << scene.perturb_key << " = " << scene.perturb_values[0]
     << "), after every step at which either cracked (perturbation.csv).\n\n";
  runs.write_markdown(md);
  write_file_atomically(out / "perturbation.csv", csv.str());
  write_file_atomically(out / "perturbation.md", md.str());
}

}  // namespace vorodg
