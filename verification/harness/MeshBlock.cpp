#include "verification/harness/MeshBlock.hpp"

#include <cmath>
#include <nlohmann/json.hpp>

#include "core/io/VtuMesh.hpp"
#include "core/mesh/MeshValidator.hpp"
#include "core/schema/SceneKeyReader.hpp"
#include "core/util/Errors.hpp"
#include "core/util/Format.hpp"
#include "verification/harness/CommonKeys.hpp"

namespace vorodg {
namespace {

using nlohmann::json;

/// A number of a mesh block within the bounds of its key (CommonKeys: mesh_keys).
double bounded_number(SceneObject& m, const std::string& name, double fallback) {
  return checked_number(m, name, mesh_key("meshes[]." + name), fallback);
}

void check_sizes(SceneObject& m, const std::vector<double>& sizes, const Rectangle& domain) {
  if (sizes.empty()) m.fail_value("sizes", "missing (required): the d or h of every level");
  for (std::size_t i = 0; i < sizes.size(); ++i) {
    if (!(sizes[i] > 0)) m.fail_value("sizes", "every size must be > 0");
    if (sizes[i] > domain.scale())
      m.fail_value("sizes", "size " + fmt(sizes[i]) + " exceeds the domain's longer side " +
                                fmt(domain.scale()));
    if (domain.area() / (sizes[i] * sizes[i]) > 1.5e8)
      m.fail_value("sizes", "size " + fmt(sizes[i]) + " gives more than 1.5e8 cells");
    if (i > 0 && !(sizes[i] < sizes[i - 1]))
      m.fail_value("sizes", "levels must go from coarse to fine (strictly decreasing), found " +
                                fmt(sizes[i - 1]) + " then " + fmt(sizes[i]));
  }
}

std::string domain_text(const Rectangle& d) {
  // Appended piece by piece: g++ 12 warns falsely (-Wrestrict) on "[" + std::string here.
  std::string out = "[";
  out.append(fmt(d.x0())).append(", ").append(fmt(d.y0())).append(", ");
  return out.append(fmt(d.x1())).append(", ").append(fmt(d.y1())).append("]");
}

/// One level of a file family, read and validated now so that a missing or broken file is
/// refused before anything runs.
PolygonMesh read_level_file(SceneObject& m, const std::string& name,
                            const std::filesystem::path& path, const Rectangle& domain) {
  std::error_code ec;  // a device (/dev/zero) would be read for ever
  if (std::filesystem::exists(path, ec) && !std::filesystem::is_regular_file(path, ec))
    m.fail_value("files", "cannot read '" + name + "': not a regular file");
  PolygonMesh level;
  try {
    level = read_vtu(path, &domain);
  } catch (const InputError& e) {
    m.fail_value("files", "cannot read '" + name + "': " + e.what());
  }
  if (const auto report = validate_mesh(level); !report.ok())
    m.fail_value("files", "'" + name + "' is not a valid mesh of the domain " +
                              domain_text(domain) + ": " + report.defects.front().what);
  return level;
}

/// Family file: one level per file, its size the mesh's h_avg. A scene's source is its path
/// (with " variants[i]" or " sweeps[i]" after it for a part of a scene): its folder is where
/// relative names start.
void read_file_levels(SceneObject& m, SceneMesh& mesh, const Rectangle& domain) {
  if (m.has("sizes"))
    m.fail_value("sizes", "not allowed with family file: its levels are the meshes of 'files'");
  if (!m.has("files"))
    m.fail_value("files", "missing (required with family file): one .vtu mesh per level");
  const std::filesystem::path folder = std::filesystem::path(m.source()).parent_path();
  for (const std::string& name : m.texts("files", {})) {
    const std::filesystem::path path = (folder / name).lexically_normal();
    const double h = read_level_file(m, name, path, domain).h_avg();
    if (!mesh.sizes.empty() && !(h < mesh.sizes.back()))
      m.fail_value("files",
                   "levels must go from coarse to fine (h_avg strictly decreasing), "
                   "found " +
                       fmt(mesh.sizes.back()) + " then " + fmt(h) + " for '" + name + "'");
    mesh.files.push_back(path);
    mesh.sizes.push_back(h);
  }
  if (m.has("realizations_per_level"))
    m.fail_value("realizations_per_level", "a file family has one mesh per level");
  mesh.realizations = m.integer("realizations", mesh.realizations);
  if (mesh.realizations != 1)
    m.fail_value("realizations", "a file family has one mesh per level: expected 1, found " +
                                     std::to_string(mesh.realizations));
}

/// `symmetric`: true (the whole rcp mesh mirrored), "notch" (mirrored along the notch and at the
/// load point only) or false.
void read_symmetry(SceneObject& m, SceneMesh& mesh, const std::string& family) {
  if (!m.has("symmetric")) return;
  const json& value = m.at("symmetric");
  if (value.is_boolean()) {
    mesh.symmetric = value.get<bool>();
  } else if (value.is_string() && value.get<std::string>() == "notch") {
    mesh.symmetric = mesh.notch_only = true;
  } else {
    m.fail("symmetric", "true, false or \"notch\"", value);
  }
  if (mesh.symmetric && mesh.family != MeshFamily::rcp)
    m.fail_value("symmetric", "only the rcp family is mirrored, found family " + family);
}

/// realizations_per_level: one whole count in [1, 1e6] per size, instead of `realizations`.
void read_realizations_per_level(SceneObject& m, SceneMesh& mesh) {
  if (m.has("realizations"))
    m.fail_value("realizations_per_level",
                 "beside realizations: expected one way of giving the realizations");
  const std::vector<double> counts = m.numbers("realizations_per_level", {});
  if (counts.size() != mesh.sizes.size())
    m.fail_value("realizations_per_level", "expected one count per size (" +
                                               std::to_string(mesh.sizes.size()) + "), found " +
                                               std::to_string(counts.size()));
  for (double n : counts) {
    if (!(n >= 1 && n <= 1e6 && n == std::floor(n)))
      m.fail_value("realizations_per_level", "expected whole counts in [1, 1e6], found " + fmt(n));
    mesh.realizations_per_level.push_back(static_cast<int>(n));
  }
}

/// The families a scene can name: those generated, and meshes read from files.
const Choices& scene_family_choices() {
  static const Choices choices = [] {
    Choices out = generated_family_choices();
    out.push_back({std::string(family_name(MeshFamily::file)), "one .vtu mesh per level"});
    return out;
  }();
  return choices;
}

}  // namespace

SceneMesh read_mesh(SceneObject& m, const Rectangle& domain) {
  SceneMesh mesh;
  const std::string family = m.text("family", std::string(family_name(mesh.family)));
  if (!is_choice(scene_family_choices(), family))
    m.fail_value("family", "'" + family + "': expected " + choice_list(scene_family_choices()));
  mesh.family = parse_family(family);
  mesh.label = m.text("label", family);
  if (mesh.family == MeshFamily::file) {
    read_file_levels(m, mesh, domain);
  } else {
    if (m.has("files")) m.fail_value("files", "only with family file, found family " + family);
    mesh.sizes = m.numbers("sizes", {});
    check_sizes(m, mesh.sizes, domain);
    mesh.realizations = m.integer("realizations", mesh.realizations);
    bounded_number(m, "realizations", mesh.realizations);
    if (m.has("realizations_per_level")) read_realizations_per_level(m, mesh);
  }
  const double seed = bounded_number(m, "seed", static_cast<double>(mesh.seed));
  if (seed != std::floor(seed)) m.fail_value("seed", "expected an integer, found " + fmt(seed));
  mesh.seed = static_cast<std::uint64_t>(seed);
  mesh.perturbation = bounded_number(m, "perturbation", mesh.perturbation);
  mesh.regularization = bounded_number(m, "regularization", mesh.regularization);
  read_symmetry(m, mesh, family);
  m.finish();
  return mesh;
}

MeshSpec SceneMesh::spec(const Rectangle& domain, int level, std::uint64_t realization_seed) const {
  MeshSpec out;
  out.family = family;
  out.domain = domain;
  out.size = sizes.at(level);
  out.seed = realization_seed;
  out.perturbation = perturbation;
  out.regularization = regularization;
  out.symmetric = symmetric;
  out.notch_only = notch_only;
  if (family == MeshFamily::file) out.path = files.at(level).string();
  return out;
}

}  // namespace vorodg
