#include "verification/cli/SolveCommand.hpp"

#include <charconv>
#include <iostream>
#include <string_view>

#include <thread>

#include "core/io/VtuMesh.hpp"
#include "core/mesh/MeshValidator.hpp"
#include "core/util/BlasInfo.hpp"
#include "core/util/PeakMemory.hpp"
#include "core/util/Errors.hpp"
#include "core/util/Format.hpp"
#include "verification/cli/JsonOutput.hpp"

namespace vorodg {
namespace {

/// The shortest text that reads back to x (0.7, not 0.69999999999999996; 0.49999999999999 exact).
std::string exact(double x) {
  char buf[32];
  const auto [end, ec] = std::to_chars(buf, buf + sizeof buf, x);
  return std::string(buf, end);
}

/// Per-cell result fields (mean stress, von Mises, error densities, largest interface gap).
std::vector<VtuField> cell_fields(const PolygonMesh& mesh, const SolveResult& r,
                                  const ExactSolution& exact) {
  VtuField stress{"mean_stress", 3, {}}, vm{"von_mises", 1, {}}, id{"cell_id", 1, {}};
  VtuField gap{"max_interface_gap", 1, {}};
  for (int c = 0; c < mesh.num_cells(); ++c) {
    const Eigen::Vector3d& s = r.cell_mean_stress[c];
    stress.values.insert(stress.values.end(), {s[0], s[1], s[2]});
    vm.values.push_back(von_mises(s, exact.material()));
    id.values.push_back(c);
    double largest = 0.0;
    for (int e : mesh.cell_edges(c)) largest = std::max(largest, r.edge_gaps[e]);
    gap.values.push_back(largest);
  }
  return {stress, vm, {"l2_error_density", 1, r.cell_l2_density},
          {"energy_error_density", 1, r.cell_energy_density}, id, gap};
}

/// Displacement, exact displacement and error at the given points (3 components, z = 0).
std::vector<VtuField> point_fields(const std::vector<Point>& points, const Eigen::Matrix2Xd& uh,
                                   const ExactSolution& exact) {
  VtuField u{"displacement", 3, {}}, ue{"exact_displacement", 3, {}}, err{"error", 3, {}};
  for (std::size_t i = 0; i < points.size(); ++i) {
    const Eigen::Vector2d h = uh.col(i), x = exact.displacement(points[i]);
    u.values.insert(u.values.end(), {h.x(), h.y(), 0.0});
    ue.values.insert(ue.values.end(), {x.x(), x.y(), 0.0});
    err.values.insert(err.values.end(), {h.x() - x.x(), h.y() - x.y(), 0.0});
  }
  return {u, ue, err};
}

/// Writes the result. CG: the mesh itself. DG: every cell with its own copies of its vertices,
/// so the displacement of each cell is its own and ParaView shows the jumps between cells.
void write_result(const std::string& path, const PolygonMesh& mesh, const SolveResult& r,
                  const ExactSolution& exact, bool discontinuous) {
  if (!discontinuous) {
    write_vtu(path, mesh, {point_fields(mesh.vertices(), r.vertex_displacement, exact),
                           cell_fields(mesh, r, exact)});
    return;
  }
  std::vector<Point> points;
  std::vector<int> offsets{0}, cells;
  Eigen::Matrix2Xd uh(2, r.cell_dof_values.size() / 2);
  for (int c = 0; c < mesh.num_cells(); ++c)
    for (int k = 0; k < mesh.cell_size(c); ++k) {
      const int copy = static_cast<int>(points.size());
      points.push_back(mesh.vertex(mesh.cell_vertices(c)[k]));
      uh.col(copy) = r.cell_dof_values.segment<2>(r.cell_offsets[c] + 2 * k);
      cells.push_back(copy);
      if (k + 1 == mesh.cell_size(c)) offsets.push_back(static_cast<int>(cells.size()));
    }
  const PolygonMesh exploded(mesh.domain(), points, offsets, cells);
  write_vtu(path, exploded, {point_fields(points, uh, exact), cell_fields(mesh, r, exact)});
}

}  // namespace

CLI::App* add_solve_command(CLI::App& app, SolveCommandOptions& o) {
  CLI::App* cmd = app.add_subcommand("solve", "Solve one problem on one mesh and measure its error");
  add_mesh_source_options(*cmd, o.mesh);
  o.mesh.domain = "0,-0.5,4,0.5";  // the beam's default: [0, L] x [-D/2, D/2], L/D = 4
  cmd->get_option("--domain")->default_str(o.mesh.domain);
  cmd->add_option("--mesh", o.mesh.file, "Read the mesh from this .vtu instead of generating one");
  SolveSettings& s = o.settings;
  cmd->add_option("--problem", s.problem, "beam | patch | patch-mixed | patch-traction | mms")->capture_default_str();
  cmd->add_option("--formulation", s.formulation, "cg | dg-penalty | dg-al | dg-nitsche | dg-sipg")
      ->capture_default_str();
  cmd->add_option("--kp", s.dg.kp, "DG penalty k_p relative to E: eps = k_p E / h")
      ->capture_default_str()
      ->check(finite_number());
  cmd->add_flag("--local-h", s.dg.local_h, "DG: h per interface instead of h_avg");
  cmd->add_option("--tol", s.dg.tolerance, "DG iterations: relative change to stop at")
      ->capture_default_str()
      ->check(finite_number());
  cmd->add_option("--max-iter", s.dg.max_iterations, "DG iterations: at most this many")
      ->capture_default_str();
  cmd->add_flag("--al-update-kp", s.dg.al_update_kp,
                "dg-al: update lambda with k_p E [u] (the report's Eq. 26) instead of eps [u]");
  cmd->add_flag("--sipg-mean-stress", s.dg.sipg_mean_stress,
                "dg-sipg: each cell's mean stress instead of its own stress on the edge");
  cmd->add_option("--sipg-sign", s.dg.sipg_sign, "dg-sipg: -1 symmetric, +1 non-symmetric")
      ->capture_default_str()
      ->check(CLI::IsMember({-1, 1}));
  cmd->add_option("--plane", o.plane, "stress | strain")->capture_default_str();
  cmd->add_option("--E", s.E, "Young's modulus")->capture_default_str()->check(finite_number());
  cmd->add_option("--nu", s.nu, "Poisson's ratio")->capture_default_str()->check(finite_number());
  cmd->add_option("--load", s.load, "beam: end load P")->capture_default_str()->check(finite_number());
  cmd->add_flag("--mean-dilation", s.mean_dilation, "Mean-dilation (B-bar) strain operator");
  cmd->add_flag("--no-correction", o.no_correction, "Skip the divergence-consistency correction");
  cmd->add_option("--rule", s.element.rule_points, "Quadrature points per fan triangle: 1, 3 or 6")
      ->capture_default_str();
  cmd->add_option("--refinement", s.element.weights.refinement,
                  "Weight functions: fan triangles cut into 4^refinement")
      ->capture_default_str();
  cmd->add_option("--degree", s.element.weights.degree, "Weight functions: P1 or P2")
      ->capture_default_str();
  // Both cores by default; results are bitwise the same for any thread count.
  s.element.threads = static_cast<int>(std::max(1u, std::thread::hardware_concurrency()));
  cmd->add_option("--threads", s.element.threads, "Threads for setup, assembly and errors")
      ->capture_default_str();
  cmd->add_option("--ordering", o.ordering,
                  "Fill-reducing ordering of the sparse factor: node-metis | node-amd | amd | cholmod")
      ->capture_default_str();
  cmd->add_option("-o,--output", o.output, "Result file to write (.vtu)");
  cmd->add_option("--metrics", o.metrics, "Metrics file to write (.json)");
  return cmd;
}

int run_solve_command(const SolveCommandOptions& o, const CLI::App& command) {
  // Every value is checked, naming its option, before anything is echoed, meshed or solved.
  SolveSettings settings = o.settings;
  if (o.plane != "stress" && o.plane != "strain")
    throw InputError("--plane '" + o.plane + "': expected stress or strain");
  settings.plane = o.plane == "strain" ? PlaneModel::strain : PlaneModel::stress;
  settings.element.divergence_correction = !o.no_correction;
  if (o.ordering == "node-metis") settings.ordering = FillOrdering::node_metis;
  else if (o.ordering == "node-amd") settings.ordering = FillOrdering::node_amd;
  else if (o.ordering == "amd") settings.ordering = FillOrdering::amd;
  else if (o.ordering == "cholmod") settings.ordering = FillOrdering::cholmod_default;
  else throw InputError("--ordering '" + o.ordering + "': expected node-metis, node-amd, amd or cholmod");
  if (!(settings.E > 0))
    throw InputError("--E " + exact(settings.E) + ": expected Young's modulus E > 0");
  if (!(settings.nu > -1 && settings.nu < 0.5))
    throw InputError("--nu " + exact(settings.nu) + ": expected Poisson's ratio -1 < nu < 0.5");
  const auto& p = settings.problem;
  if (p != "beam" && p != "patch" && p != "patch-mixed" && p != "patch-traction" && p != "mms")
    throw InputError("--problem '" + p + "': expected beam, patch, patch-mixed, patch-traction or mms");
  if (settings.formulation != "cg") parse_dg_method(settings.formulation);  // names it if unknown
  if (!(settings.dg.kp > 0))
    throw InputError("--kp " + exact(settings.dg.kp) + ": expected k_p > 0 (the penalty relative to E)");
  if (!(settings.dg.tolerance > 0))
    throw InputError("--tol " + exact(settings.dg.tolerance) + ": expected > 0");
  if (settings.dg.max_iterations < 1)
    throw InputError("--max-iter " + std::to_string(settings.dg.max_iterations) + ": expected >= 1");
  const int rule = settings.element.rule_points;
  if (rule != 1 && rule != 3 && rule != 6)
    throw InputError("--rule " + std::to_string(rule) + ": expected 1, 3 or 6 points per fan triangle");
  try {
    check_weight_options(settings.element.weights);
  } catch (const InputError& e) {
    const bool degree = std::string_view(e.what()).find("degree") != std::string_view::npos;
    throw InputError(std::string(degree ? "--degree: " : "--refinement: ") + e.what());
  }
  if (settings.element.threads < 1)
    throw InputError("--threads " + std::to_string(settings.element.threads) + ": expected >= 1");
  check_output_folder(o.output, "--output");
  check_output_folder(o.metrics, "--metrics");
  Stopwatch clock;
  const MeshSpec spec = mesh_spec(o.mesh, command.count("--domain") > 0);
  echo_options("vorodg solve", command);
  const GeneratedMesh generated = generate_mesh(spec);
  const PolygonMesh& mesh = generated.mesh;
  const auto validation = validate_mesh(mesh);
  if (!validation.ok())
    throw InputError("mesh " + (spec.path.empty() ? std::string(family_name(spec.family)) : spec.path) +
                     " is invalid: " + validation.defects.front().what + " (" +
                     std::to_string(validation.defect_count) + " defects; see vorodg mesh --check)");
  const double mesh_seconds = clock.seconds();

  SolveResult r = run_solve(mesh, settings);
  r.seconds["mesh"] = mesh_seconds;
  // A DG iteration that did not converge leaves a plausible-looking wrong answer: refuse it.
  if (r.dg && r.dg->stop_reason != "converged" && r.dg->stop_reason != "direct")
    throw NumericalError(settings.formulation + ": the interface iteration " +
                         (r.dg->stop_reason == "diverged" ? "diverged" : "did not converge") +
                         " (stop reason " + r.dg->stop_reason + " after " +
                         std::to_string(r.dg->iterations) + " iterations, relative change " +
                         fmt(r.dg->last_change, 3) + ", tolerance " + fmt(settings.dg.tolerance, 3) +
                         "); nothing written: raise --max-iter, or --kp");
  const auto exact = make_problem(settings, mesh.domain());

  nlohmann::json json;
  json["problem"] = settings.problem;
  json["formulation"] = settings.formulation;
  json["family"] = family_name(spec.family);
  json["cells"] = mesh.num_cells();
  json["vertices"] = mesh.num_vertices();
  json["dofs"] = r.dofs;
  json["free_dofs"] = r.free_dofs;
  json["h_avg"] = mesh.h_avg();
  json["l2_error"] = r.l2_error;
  json["energy_error"] = r.energy_error;
  json["rcond"] = r.rcond;
  json["factor_nonzeros"] = r.factor_nonzeros;
  json["max_divergence_defect"] = r.max_divergence_defect;
  json["min_moment_rcond"] = r.min_moment_rcond;
  json["seconds"] = to_json(r.seconds);
  if (r.dg) {
    json["kp"] = settings.dg.kp;
    json["penalty"] = r.dg->penalty;
    json["iterations"] = r.dg->iterations;
    json["stop_reason"] = r.dg->stop_reason;
    json["last_change"] = r.dg->last_change;
    json["gap_norm"] = r.dg->gap_norm;
    json["relative_gap"] = r.dg->relative_gap;
    json["seconds_per_iteration"] = r.dg->seconds_per_iteration;
  }
  json["blas"] = blas_description();
  json["peak_memory_mb"] = peak_memory_mb();  // of the whole process, mesh generation included
  if (!o.metrics.empty()) write_json(o.metrics, json);
  if (!o.output.empty()) write_result(o.output, mesh, r, *exact, settings.formulation != "cg");

  std::cout << settings.problem << " on " << family_name(spec.family) << ": " << mesh.num_cells()
            << " cells, " << r.dofs << " dofs, h_avg " << mesh.h_avg() << ", L2 error "
            << r.l2_error << ", energy error " << r.energy_error << ", rcond " << r.rcond << "\n";
  if (r.dg)
    std::cout << settings.formulation << ": k_p " << settings.dg.kp << ", " << r.dg->iterations
              << " iterations, " << r.dg->stop_reason << ", relative gap " << r.dg->relative_gap
              << ", " << r.dg->seconds_per_iteration << " s per iteration\n";
  std::cout << "seconds:";
  for (const auto& [stage, s] : r.seconds) std::cout << " " << stage << " " << s;
  std::cout << "\nblas: " << blas_description() << "\n";
  return 0;
}

}  // namespace vorodg
