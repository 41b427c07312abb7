// libFuzzer target: a .vtu file read as `vorodg mesh --check` reads it (read_vtu, then
// validate_mesh), with ASCII, base64 binary or appended data, zlib-compressed or not. Findings:
// crashes, sanitizer reports, exceptions other than our error types, hangs, and a mesh the
// validator passes although its geometry is not finite and positive, or that does not survive a
// write and read back unchanged (binary and ASCII).
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <string>

#include "FuzzSupport.hpp"
#include "core/io/VtuMesh.hpp"
#include "core/mesh/MeshValidator.hpp"
#include "core/util/Errors.hpp"

namespace {

using namespace vorodg;
using fuzz::require;

bool finite(const Point& p) {
  return std::isfinite(p.x()) && std::isfinite(p.y());
}

/// What every stage after validation relies on.
void check_valid_mesh(const PolygonMesh& mesh) {
  const Rectangle& d = mesh.domain();
  require(std::isfinite(d.area()) && d.area() > 0,
          "valid mesh on a domain of area " + std::to_string(d.area()));
  require(mesh.num_cells() > 0, "valid mesh without cells");
  const double h = mesh.h_avg();
  require(std::isfinite(h) && h > 0, "valid mesh with h_avg " + std::to_string(h));
  for (int v = 0; v < mesh.num_vertices(); ++v)
    require(finite(mesh.vertex(v)), "valid mesh with a non-finite vertex " + std::to_string(v));
  for (int c = 0; c < mesh.num_cells(); ++c) {
    const double a = mesh.cell_area(c);
    require(std::isfinite(a) && a > 0,
            "valid mesh, cell " + std::to_string(c) + " has area " + std::to_string(a));
    require(finite(mesh.cell_centroid(c)),
            "valid mesh, cell " + std::to_string(c) + " has a non-finite centroid");
  }
  const double total = mesh.total_area();
  require(std::isfinite(total) && std::abs(total - d.area()) <= 1e-6 * d.area(),
          "valid mesh covers area " + std::to_string(total) + " of a domain of area " +
              std::to_string(d.area()));
  for (const MeshEdge& e : mesh.edges()) {
    require(e.cell0 >= 0 && e.cell0 < mesh.num_cells() && e.cell1 < mesh.num_cells(),
            "valid mesh, edge cell out of range");
    require(!e.on_boundary() || e.side != Side::none, "valid mesh with a boundary edge on no side");
  }
  // What vorodg writes it reads back unchanged, in both encodings.
  for (VtuEncoding encoding : {VtuEncoding::binary_zlib, VtuEncoding::ascii}) {
    const char* name = encoding == VtuEncoding::ascii ? "ascii" : "binary";
    PolygonMesh back;
    try {
      back = read_vtu_text(vtu_text(mesh, {}, encoding), "round trip");
    } catch (const std::exception& e) {
      fuzz::finding(std::string("valid mesh written (") + name + ") and read back: " + e.what());
    }
    require(back.vertices() == mesh.vertices() && back.offsets() == mesh.offsets() &&
                back.cell_vertex_list() == mesh.cell_vertex_list() &&
                back.domain().lo() == d.lo() && back.domain().hi() == d.hi(),
            std::string("valid mesh changed in a write (") + name + ") and read back");
  }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string text(reinterpret_cast<const char*>(data), size);
  try {
    const PolygonMesh mesh = read_vtu_text(text, "fuzz.vtu");
    const MeshValidationReport report = validate_mesh(mesh);
    const std::string summary = report.summary();
    require(report.ok() == summary.empty(), "validation summary disagrees with ok()");
    if (report.ok()) check_valid_mesh(mesh);
  } catch (const InputError&) {
    // the correct answer to bad input
  } catch (const NumericalError&) {
  }
  return 0;
}
