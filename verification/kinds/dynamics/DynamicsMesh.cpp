#include "verification/kinds/dynamics/DynamicsMesh.hpp"

#include <algorithm>
#include <cmath>

#include "core/mesh/MeshValidator.hpp"
#include "core/meshgen/MeshFamily.hpp"
#include "core/util/Errors.hpp"
#include "core/util/Format.hpp"
#include "core/util/Random.hpp"

namespace vorodg {
namespace {

PolygonMesh body_mesh(const DynamicsScene& scene, const EnsembleRunId& run, int body) {
  const SceneMesh& block = scene.meshes[run.mesh];
  const Rectangle& domain = scene.bodies[body].domain;
  // The first body as its problem needs it (a notch tip made a vertex).
  MeshSpec spec = scene.problem->mesh_spec(block.spec(scene.bodies[0].domain, run.level, run.seed));
  if (body > 0 && block.family != MeshFamily::file) {
    spec.domain = domain;
    spec.seed = derive_seed(run.seed, static_cast<std::uint64_t>(body));
  }
  PolygonMesh mesh = generate_mesh(spec).mesh;
  if (const auto report = validate_mesh(mesh); !report.ok())
    throw NumericalError("invalid mesh of body " + std::to_string(body) + ": " +
                         report.defects.front().what);
  if (body == 0 || block.family != MeshFamily::file) return mesh;
  // A file mesh is read once: the second block is the same cells, moved.
  const Rectangle& first = scene.bodies[0].domain;
  const double tolerance = 1e-12 * first.scale();
  if (std::abs(domain.width() - first.width()) > tolerance ||
      std::abs(domain.height() - first.height()) > tolerance)
    throw InputError(
        "second_block.domain: with family file the second block is the first "
        "block's mesh moved: expected the size of domain, " +
        fmt(first.width()) + " x " + fmt(first.height()));
  std::vector<Point> moved = mesh.vertices();
  for (Point& p : moved) p += domain.lo() - scene.bodies[0].domain.lo();
  return PolygonMesh(domain, moved, mesh.offsets(), mesh.cell_vertex_list());
}

}  // namespace

BodiesMesh bodies_mesh(const DynamicsScene& scene, const EnsembleRunId& run) {
  std::vector<Point> vertices;
  std::vector<int> offsets{0}, loops;
  BodiesMesh out;
  double area = 0.0;
  Point lo = scene.bodies[0].domain.lo(), hi = scene.bodies[0].domain.hi();
  for (int b = 0; b < static_cast<int>(scene.bodies.size()); ++b) {
    const PolygonMesh mesh = body_mesh(scene, run, b);
    out.first_cell.push_back(static_cast<int>(offsets.size()) - 1);
    const int shift = static_cast<int>(vertices.size());
    vertices.insert(vertices.end(), mesh.vertices().begin(), mesh.vertices().end());
    for (int v : mesh.cell_vertex_list()) loops.push_back(v + shift);
    for (int c = 0; c < mesh.num_cells(); ++c)
      offsets.push_back(offsets.back() + mesh.cell_size(c));
    area += mesh.total_area();
    lo = lo.cwiseMin(scene.bodies[b].domain.lo());
    hi = hi.cwiseMax(scene.bodies[b].domain.hi());
  }
  out.first_cell.push_back(static_cast<int>(offsets.size()) - 1);
  out.mesh = PolygonMesh(Rectangle(lo.x(), lo.y(), hi.x(), hi.y()), std::move(vertices),
                         std::move(offsets), std::move(loops));
  out.h_avg = std::sqrt(area / out.mesh.num_cells());
  scene.problem->check_mesh(out.mesh);
  return out;
}

}  // namespace vorodg
