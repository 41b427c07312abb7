#include "verification/cli/MeshCommand.hpp"

#include <filesystem>
#include <iostream>
#include <sstream>

#include "core/io/JsonOutput.hpp"
#include "core/io/VtuMesh.hpp"
#include "core/mesh/MeshStatistics.hpp"
#include "core/mesh/MeshValidator.hpp"
#include "core/meshgen/MeshFamily.hpp"
#include "core/util/Errors.hpp"
#include "core/util/Format.hpp"
#include "verification/cli/CliSupport.hpp"

namespace vorodg {
namespace {

int check_mesh_file(const MeshCommandOptions& o, bool domain_given) {
  const Rectangle domain = Rectangle::parse(o.mesh.domain);
  const PolygonMesh mesh = read_vtu(o.check, domain_given ? &domain : nullptr);
  const auto report = validate_mesh(mesh);
  if (!report.ok()) {
    // One line per defect on stderr, each naming the file; the count on stdout.
    std::istringstream lines(report.summary());
    for (std::string line; std::getline(lines, line);) std::cerr << o.check << ": " << line << "\n";
    std::cout << o.check << ": invalid mesh, " << report.defect_count
              << (report.defect_count == 1 ? " defect\n" : " defects\n");
    return kExitInputError;
  }
  const auto stats = compute_statistics(mesh);
  std::cout << o.check << ": valid mesh, " << stats.cells << " cells, " << stats.vertices
            << " vertices, h_avg " << stats.h_avg << ", domain " << mesh.domain().to_string()
            << "\n";
  return 0;
}

}  // namespace

CLI::App* add_mesh_command(CLI::App& app, MeshCommandOptions& o) {
  CLI::App* cmd = app.add_subcommand("mesh", "Generate a mesh (or --check one) and report on it");
  add_mesh_source_options(*cmd, o.mesh);
  add_vtu_output_options(*cmd, o.output, "Mesh file");
  cmd->add_option("--stats", o.stats, "Statistics file to write (.json)");
  cmd->add_option("--check", o.check, "Validate this .vtu mesh instead of generating one");
  return cmd;
}

namespace {

/// The mesh with its id and number of sides per cell, for ParaView.
void write_mesh_file(const MeshCommandOptions& o, GeneratedMesh& generated) {
  const Stopwatch clock;
  std::vector<double> sides, ids;
  for (int c = 0; c < generated.mesh.num_cells(); ++c) {
    sides.push_back(generated.mesh.cell_size(c));
    ids.push_back(c);
  }
  write_vtu(o.output.path, generated.mesh, {{}, {{"cell_id", 1, ids}, {"sides", 1, sides}}},
            o.output.encoding());
  generated.report.seconds["write"] = clock.seconds();
}

/// The statistics file: the mesh's statistics, the spec, and what the generator reports.
nlohmann::json mesh_stats_json(const MeshSpec& spec, const MeshStatistics& stats,
                               const MeshGenReport& r) {
  nlohmann::json json = to_json(stats);
  json["family"] = family_name(spec.family);
  json["domain"] = {spec.domain.x0(), spec.domain.y0(), spec.domain.x1(), spec.domain.y1()};
  json["size"] = spec.size;
  json["seed"] = spec.seed;
  if (spec.family == MeshFamily::perturbed_hex) json["perturbation"] = spec.perturbation;
  if (spec.family == MeshFamily::rcp || spec.family == MeshFamily::tri) json["seeds"] = r.seeds;
  if (spec.family == MeshFamily::rcp) {
    json["regularization"] = spec.regularization;
    json["covered_fraction"] = *r.covered_fraction;
    json["covered_fraction_interior"] = r.covered_fraction_interior
                                            ? nlohmann::json(*r.covered_fraction_interior)
                                            : nlohmann::json();
    json["side_counts_before"] = histogram_json(r.sides_before);
    json["collapsed_edges"] = r.collapsed_edges;
    json["refused_collapses"] = r.refused_collapses;
    json["merged_cells"] = r.merged_cells;
    json["merged_vertices"] = r.merged_vertices;
  }
  json["seconds"] = nlohmann::json(r.seconds);  // stage -> seconds
  return json;
}

}  // namespace

int run_mesh_command(const MeshCommandOptions& o, const CLI::App& command) {
  const bool domain_given = command.count("--domain") > 0;
  if (!o.check.empty()) return check_mesh_file(o, domain_given);
  const MeshSpec spec = mesh_spec(o.mesh, true);
  check_output_folder(o.output.path, "--output");
  check_output_folder(o.stats, "--stats");
  echo_options("vorodg mesh", command);  // after the checks: the echoed line is a valid run

  const Stopwatch total;
  GeneratedMesh generated = generate_mesh(spec);
  const Stopwatch clock;
  const auto validation = validate_mesh(generated.mesh);
  generated.report.seconds["validation"] = clock.seconds();
  if (!validation.ok())
    throw NumericalError("generated " + std::string(family_name(spec.family)) +
                         " mesh is invalid: " + validation.defects.front().what + " (" +
                         std::to_string(validation.defect_count) + " defects)");
  const MeshStatistics stats = compute_statistics(generated.mesh);
  if (!o.output.path.empty()) write_mesh_file(o, generated);
  const MeshGenReport& r = generated.report;
  nlohmann::json json = mesh_stats_json(spec, stats, r);
  json["seconds"]["total"] = total.seconds();
  if (!o.stats.empty()) write_json(o.stats, json);

  std::cout << family_name(spec.family) << " mesh: " << stats.cells << " cells, " << stats.vertices
            << " vertices, h_avg " << stats.h_avg << ", min edge/h_avg " << stats.min_edge_over_h
            << ", min angle " << stats.min_interior_angle_deg << " deg, area error "
            << stats.area_error;
  if (r.covered_fraction_interior)
    std::cout << ", covered fraction " << *r.covered_fraction_interior << " (interior), "
              << *r.covered_fraction << " (whole)";
  std::cout << ", " << total.seconds() << " s\n";
  return 0;
}

}  // namespace vorodg
