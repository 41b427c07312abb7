#include "verification/cli/SolveCommand.hpp"

#include <iostream>

#include "core/io/VtuMesh.hpp"
#include "core/mesh/MeshValidator.hpp"
#include "core/util/BlasInfo.hpp"
#include "core/util/Errors.hpp"
#include "verification/cli/JsonOutput.hpp"

namespace vorodg {
namespace {

VtuFields result_fields(const PolygonMesh& mesh, const SolveResult& r, const ExactSolution& exact) {
  VtuField u{"displacement", 3, {}}, ue{"exact_displacement", 3, {}}, err{"error", 3, {}};
  for (int v = 0; v < mesh.num_vertices(); ++v) {
    const Eigen::Vector2d uh = r.vertex_displacement.col(v), ux = exact.displacement(mesh.vertex(v));
    u.values.insert(u.values.end(), {uh.x(), uh.y(), 0.0});
    ue.values.insert(ue.values.end(), {ux.x(), ux.y(), 0.0});
    err.values.insert(err.values.end(), {uh.x() - ux.x(), uh.y() - ux.y(), 0.0});
  }
  VtuField stress{"mean_stress", 3, {}}, vm{"von_mises", 1, {}}, id{"cell_id", 1, {}};
  for (int c = 0; c < mesh.num_cells(); ++c) {
    const Eigen::Vector3d& s = r.cell_mean_stress[c];
    stress.values.insert(stress.values.end(), {s[0], s[1], s[2]});
    vm.values.push_back(von_mises(s, exact.material()));
    id.values.push_back(c);
  }
  return {{u, ue, err},
          {stress, vm, {"l2_error_density", 1, r.cell_l2_density},
           {"energy_error_density", 1, r.cell_energy_density}, id}};
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
  cmd->add_option("--formulation", s.formulation, "cg")->capture_default_str();
  cmd->add_option("--plane", o.plane, "stress | strain")->capture_default_str();
  cmd->add_option("--E", s.E, "Young's modulus")->capture_default_str();
  cmd->add_option("--nu", s.nu, "Poisson's ratio")->capture_default_str();
  cmd->add_option("--load", s.load, "beam: end load P")->capture_default_str();
  cmd->add_flag("--mean-dilation", s.mean_dilation, "Mean-dilation (B-bar) strain operator");
  cmd->add_flag("--no-correction", o.no_correction, "Skip the divergence-consistency correction");
  cmd->add_option("--rule", s.element.rule_points, "Quadrature points per fan triangle: 1, 3 or 6")
      ->capture_default_str();
  cmd->add_option("--refinement", s.element.weights.refinement,
                  "Weight functions: fan triangles cut into 4^refinement")
      ->capture_default_str();
  cmd->add_option("--degree", s.element.weights.degree, "Weight functions: P1 or P2")
      ->capture_default_str();
  cmd->add_option("--threads", s.element.threads, "Threads for setup, assembly and errors")
      ->capture_default_str();
  cmd->add_option("-o,--output", o.output, "Result file to write (.vtu)");
  cmd->add_option("--metrics", o.metrics, "Metrics file to write (.json)");
  return cmd;
}

int run_solve_command(const SolveCommandOptions& o, const CLI::App& command) {
  echo_options("vorodg solve", command);
  SolveSettings settings = o.settings;
  if (o.plane != "stress" && o.plane != "strain")
    throw InputError("--plane '" + o.plane + "': expected stress or strain");
  settings.plane = o.plane == "strain" ? PlaneModel::strain : PlaneModel::stress;
  settings.element.divergence_correction = !o.no_correction;
  check_output_folder(o.output, "--output");
  check_output_folder(o.metrics, "--metrics");
  const IsotropicElasticity material(settings.E, settings.nu, settings.plane);  // validates

  Stopwatch clock;
  const MeshSpec spec = mesh_spec(o.mesh, command.count("--domain") > 0);
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
  json["max_divergence_defect"] = r.max_divergence_defect;
  json["min_moment_rcond"] = r.min_moment_rcond;
  json["seconds"] = to_json(r.seconds);
  json["blas"] = blas_description();
  if (!o.metrics.empty()) write_json(o.metrics, json);
  if (!o.output.empty()) write_vtu(o.output, mesh, result_fields(mesh, r, *exact));

  std::cout << settings.problem << " on " << family_name(spec.family) << ": " << mesh.num_cells()
            << " cells, " << r.dofs << " dofs, h_avg " << mesh.h_avg() << ", L2 error "
            << r.l2_error << ", energy error " << r.energy_error << ", rcond " << r.rcond << "\n";
  std::cout << "seconds:";
  for (const auto& [stage, s] : r.seconds) std::cout << " " << stage << " " << s;
  std::cout << "\nblas: " << blas_description() << "\n";
  return 0;
}

}  // namespace vorodg
