#include "verification/kinds/convergence/PenaltyAnalysis.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <tuple>

#include "core/io/AtomicFile.hpp"
#include "core/solve/SparseCholesky.hpp"
#include "core/util/Errors.hpp"
#include "core/util/Format.hpp"
#include "core/util/Random.hpp"
#include "dg/DgElasticity.hpp"
#include "verification/model/Choices.hpp"
#include "verification/report/ConvergenceTable.hpp"
#include "verification/report/SampleStatistics.hpp"
#include "verification/solve/SolveRun.hpp"

namespace vorodg {
namespace {

constexpr double kMaxKp = 1e8;  // the largest k_p the penalty study sweeps
constexpr TractionKind kKinds[] = {TractionKind::point, TractionKind::fan, TractionKind::mean};

/// The assembled SIPG matrix with eps = k_p E / h_avg for the given traction.
Eigen::SparseMatrix<double> sipg_matrix(const ElementTable& table,
                                        const ElasticityIntegrator& integrator,
                                        const ExactSolution& problem, TractionKind kind,
                                        double kp) {
  DgOptions o;
  o.formulation = "dg-sipg";
  o.penalty = PenaltyScaling::h_avg;
  o.kp = kp;
  o.traction = kind;
  DgElasticity dg(table, integrator, problem, o);
  dg.setup_system();
  dg.assemble_system();
  return dg.system_matrix();
}

bool positive_definite(const Eigen::SparseMatrix<double>& A) {
  try {
    SparseCholesky cholesky;
    cholesky.factorize(A.triangularView<Eigen::Lower>());
    return true;
  } catch (const NumericalError&) {
    return false;
  }
}

/// The smallest k_p (to 1% in the bisection) with A0 + k_p P positive definite, or infinity if
/// even kMaxKp is not (past it round-off, not the penalty, decides); A is affine in k_p, so two
/// assemblies give A0 and P.
double smallest_definite_kp(const ElementTable& table, const ElasticityIntegrator& integrator,
                            const ExactSolution& problem, TractionKind kind) {
  const Eigen::SparseMatrix<double> one = sipg_matrix(table, integrator, problem, kind, 1.0);
  const Eigen::SparseMatrix<double> two = sipg_matrix(table, integrator, problem, kind, 2.0);
  const Eigen::SparseMatrix<double> P = two - one, A0 = one - P;
  double lo = -4.0, hi = std::log10(kMaxKp);
  if (!positive_definite(A0 + std::pow(10.0, hi) * P)) return INFINITY;
  while (hi - lo > std::log10(1.01)) {
    const double mid = 0.5 * (lo + hi);
    (positive_definite(A0 + std::pow(10.0, mid) * P) ? hi : lo) = mid;
  }
  return std::pow(10.0, hi);
}

/// The distinct elements of the scene's formulations, in formulation order: each is analysed.
std::vector<ElementOptions> scene_elements(const Scene& scene) {
  std::vector<ElementOptions> elements;
  for (const SceneFormulation& f : scene.formulations)
    if (std::find(elements.begin(), elements.end(), f.settings.element) == elements.end())
      elements.push_back(f.settings.element);
  return elements;
}

/// What the analysis writes: the per-edge penalties (penalty_edges.csv), and the thresholds
/// (penalty_thresholds.csv and the report's table: one table, some columns in one only).
struct PenaltyOutputs {
  ConvergenceTable edges, thresholds;
};

ColumnStyle csv_digits(int precision, bool in_text = true) {
  ColumnStyle s;
  s.csv_precision = precision, s.csv_quoted = false, s.in_text = in_text;
  return s;
}

/// The columns of both tables, in their order.
PenaltyOutputs penalty_tables() {
  PenaltyOutputs out;
  const ColumnStyle text = csv_digits(6), number = csv_digits(6);
  ColumnStyle count{6, false}, sci{3, true};
  count.csv_precision = 17;
  sci.csv_precision = 6;
  for (const char* c : {"mesh", "level", "h_avg", "element", "traction", "edge_length_over_h_avg",
                        "eps_over_E_per_h_avg"})
    out.edges.declare_column(c, std::string(c) == "level" ? count : number);
  ColumnStyle median = sci, max = sci, md_only = sci;
  median.csv_name = "auto_median", max.csv_name = "auto_max", md_only.in_csv = false;
  for (const auto& [name, style] : std::vector<std::pair<std::string, ColumnStyle>>{
           {"mesh", text},
           {"level", count},
           {"cells", count},
           {"h_avg", csv_digits(6, false)},
           {"element", text},
           {"traction", text},
           {"auto eps h/E median", median},
           {"auto eps h/E max", max},
           {"smallest definite k_p", md_only},
           {"smallest_definite_kp", csv_digits(6, false)}})
    out.thresholds.declare_column(name, style);
  return out;
}

/// One level of a mesh block, realization 0: the coercive penalty of every interface and the
/// definiteness threshold, for every element of the scene and every traction kind.
void analyse_level(const Scene& scene, const SceneMesh& sm, int level,
                   const SolveSettings& settings, PenaltyOutputs& out) {
  const std::uint64_t seed = derive_seed(derive_seed(sm.seed, level), 0);
  const GeneratedMesh mesh = generate_mesh(sm.spec(scene.domain, level, seed));
  const auto problem = make_problem(settings, mesh.mesh.domain());
  const DgSpace space(mesh.mesh);
  const double h = mesh.mesh.h_avg();
  for (const ElementOptions& options : scene_elements(scene)) {
    const ElementTable element(mesh.mesh, options);
    const std::string name = element_name(options.family);
    const ElasticityIntegrator integrator(element, problem->material(), false);
    const InterfaceOperators ops(space, integrator, element);
    const auto stiffness = integrator.all_cell_matrices(1);
    for (TractionKind kind : kKinds) {
      const InterfacePenalty penalty(ops, integrator, stiffness, PenaltyScaling::coercive, 1.0,
                                     false, kind, 1);
      const std::vector<double> eps = penalty.relative_to_h_avg();
      if (kind != TractionKind::mean)
        for (std::size_t i = 0; i < eps.size(); ++i) {
          ConvergenceTable& e = out.edges;
          e.start_row();
          e.add_text("mesh", sm.label);
          e.add_value("level", level);
          e.add_value("h_avg", h);
          e.add_text("element", name);
          e.add_text("traction", traction_name(kind));
          e.add_value("edge_length_over_h_avg", space.interfaces()[i].length / h);
          e.add_value("eps_over_E_per_h_avg", eps[i]);
        }
      const double threshold = smallest_definite_kp(element, integrator, *problem, kind);
      const SampleStatistics spread = sample_statistics(eps);
      ConvergenceTable& t = out.thresholds;
      t.start_row();
      t.add_text("mesh", sm.label);
      t.add_value("level", level);
      t.add_value("cells", mesh.mesh.num_cells());
      t.add_value("h_avg", h);
      t.add_text("element", name);
      t.add_text("traction", traction_name(kind));
      t.add_value("auto eps h/E median", spread.median);
      t.add_value("auto eps h/E max", spread.max);
      t.add_value("smallest_definite_kp", threshold);
      if (std::isfinite(threshold))
        t.add_value("smallest definite k_p", threshold);
      else
        t.add_text("smallest definite k_p", "> " + fmt(kMaxKp));
    }
  }
}

}  // namespace

void write_penalty_analysis(const Scene& scene, const std::filesystem::path& out,
                            std::ostringstream& md) {
  PenaltyOutputs outputs = penalty_tables();
  SolveSettings settings;
  settings.problem = scene.problems.front();
  settings.E = scene.E;
  settings.nu = scene.nu.front();
  settings.plane = scene.plane;
  settings.load = scene.load;
  for (const SceneMesh& sm : scene.meshes)
    for (int level = 0; level < static_cast<int>(sm.sizes.size()); ++level)
      analyse_level(scene, sm, level, settings, outputs);
  for (const auto& [file, table] : {std::pair{"penalty_edges.csv", &outputs.edges},
                                    std::pair{"penalty_thresholds.csv", &outputs.thresholds}}) {
    std::ostringstream csv;
    table->write_csv(csv, {.quote_names = false});
    write_file_atomically(out / file, csv.str());
  }
  md << "## The coercive penalty and the definiteness threshold\n\n"
     << "Realization 0 of each level, problem " << settings.problem
     << ". `auto eps h/E`: the proven coercive penalty (k_p = 1) of each interface relative to E / "
        "h_avg; `smallest definite k_p`: the smallest k_p with eps = k_p E / h_avg for which the "
        "symmetric SIPG matrix is positive definite (bisection to 1%). Per-edge values in "
        "penalty_edges.csv, plotted in penalty_edges.png.\n\n";
  outputs.thresholds.write_markdown(md);
  md << "\n";
}

void write_penalty_comparison(const Scene& scene, const std::vector<RunRecord>& records,
                              std::ostringstream& md) {
  // (mesh, level, reading) -> the run shown: k_p = 1 if the reading's penalty is the coercive
  // one, else the smallest k_p that solved.
  std::map<std::tuple<std::string, int, std::string>, const RunRecord*> shown;
  for (const RunRecord& r : records) {
    if (r.run.formulation_name != "dg-sipg" || r.run.realization != 0 || !r.ok() || !r.run.kp)
      continue;
    const SolveSettings& settings = scene.formulations[r.run.formulation].settings;
    const bool coercive = penalty_scaling(dg_options(settings)) == PenaltyScaling::coercive;
    if (coercive && *r.run.kp != 1.0) continue;
    const auto key = std::make_tuple(r.run.mesh_label, r.run.level, r.run.formulation_label);
    const auto at = shown.find(key);
    if (at == shown.end() || *r.run.kp < *at->second->run.kp) shown[key] = &r;
  }
  if (shown.empty()) return;
  ConvergenceTable table;
  const ConvergenceTable::Style sci{3, true}, count{6, false}, seconds{3, false};
  for (const auto& [key, r] : shown) {
    table.start_row();
    table.add_text("mesh", std::get<0>(key));
    table.add_value("level", std::get<1>(key), std::nullopt, count);
    table.add_text("reading", std::get<2>(key));
    table.add_value("k_p", *r->run.kp, std::nullopt, sci);
    table.add_value("L2 error", r->metrics->l2_error, std::nullopt, sci);
    table.add_value("rcond", r->metrics->rcond, std::nullopt, sci);
    table.add_value("seconds", r->metrics->total_seconds(), std::nullopt, seconds);
  }
  md << "## dg-sipg at its cheapest working penalty\n\n"
     << "Realization 0: the coercive readings at k_p = 1 (the proven bound), the fixed ones at the "
        "smallest k_p of the sweep that solved. Seconds are wall times of one run (noisy).\n\n";
  table.write_markdown(md);
  md << "\n";
}

}  // namespace vorodg
