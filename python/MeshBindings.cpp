// vorodg.Mesh and the ways to get one: generated (the parameters and checks of `vorodg mesh`),
// read from .vtu, or built from arrays a user made (validated as every mesh is).
#include <pybind11/eigen.h>
#include <pybind11/numpy.h>
#include <pybind11/stl.h>

#include <functional>
#include <optional>

#include "core/io/JsonOutput.hpp"
#include "core/io/VtuMesh.hpp"
#include "core/mesh/MeshStatistics.hpp"
#include "core/mesh/MeshValidator.hpp"
#include "core/meshgen/MeshFamily.hpp"
#include "core/util/Errors.hpp"
#include "python/Bindings.hpp"
#include "verification/api/MeshSource.hpp"

namespace vorodg::python {
namespace {

using Domain = std::optional<std::array<double, 4>>;
using IntArray = py::array_t<int, py::array::c_style | py::array::forcecast>;
using RealArray = py::array_t<double, py::array::c_style | py::array::forcecast>;

Rectangle rectangle(const std::array<double, 4>& d) {
  return Rectangle(d[0], d[1], d[2], d[3]);
}

/// The smallest rectangle around the vertices.
Rectangle bounding_box(const std::vector<Point>& vertices) {
  if (vertices.empty()) throw InputError("mesh from arrays: no vertices");
  Point lo = vertices.front(), hi = lo;
  for (const Point& p : vertices) lo = lo.cwiseMin(p), hi = hi.cwiseMax(p);
  return Rectangle(lo.x(), lo.y(), hi.x(), hi.y());
}

std::vector<int> int_vector(const IntArray& a, const char* what) {
  if (a.ndim() != 1)
    throw InputError(std::string("mesh from arrays: ") + what + " has " + std::to_string(a.ndim()) +
                     " dimensions, expected 1");
  return std::vector<int>(a.data(), a.data() + a.size());
}

/// A mesh from arrays: vertices (n, 2), cells in CSR form (offsets of length cells + 1, then
/// the vertex indices, counter-clockwise). Refused (ValueError) unless it passes the validator.
MeshObject mesh_from_arrays(const RealArray& vertices, const IntArray& offsets,
                            const IntArray& connectivity, const Domain& domain) {
  if (vertices.ndim() != 2 || vertices.shape(1) != 2)
    throw InputError("mesh from arrays: vertices with " + std::to_string(vertices.ndim()) +
                     " dimensions of " + std::to_string(vertices.size()) +
                     " values, expected shape (n, 2)");
  std::vector<Point> points(vertices.shape(0));
  for (std::size_t i = 0; i < points.size(); ++i)
    points[i] = Point(vertices.at(i, 0), vertices.at(i, 1));
  const Rectangle box = domain ? rectangle(*domain) : bounding_box(points);
  PolygonMesh mesh(box, std::move(points), int_vector(offsets, "offsets"),
                   int_vector(connectivity, "connectivity"));
  require_valid_mesh(mesh, "mesh from arrays");
  return {std::move(mesh), MeshFamily::file};
}

/// `vorodg mesh`'s options, checked by the same code (so the messages name the same options).
MeshObject generated(const std::string& family, const std::array<double, 4>& domain, double d,
                     double h, double r, std::uint64_t seed, double regularize, int threads) {
  MeshSourceOptions o;
  o.family = family;
  o.domain = rectangle(domain).to_string();
  o.d = d, o.h = h, o.r = r, o.seed = seed, o.regularize = regularize;
  MeshSpec spec = mesh_spec(o, true);
  spec.threads = threads;
  GeneratedMesh g = generate_mesh(spec);
  require_valid_mesh(g.mesh, "generated " + family + " mesh");
  return {std::move(g.mesh), spec.family};
}

/// f(mesh) as a method of vorodg.Mesh.
template <class F>
auto on_mesh(F f) {
  return [f](const MeshObject& o) { return f(o.mesh); };
}

py::array_t<int> copy(const std::vector<int>& v) {
  return py::array_t<int>(static_cast<py::ssize_t>(v.size()), v.data());
}

py::array_t<double> vertex_array(const PolygonMesh& mesh) {
  py::array_t<double> out({mesh.num_vertices(), 2});
  auto a = out.mutable_unchecked<2>();
  for (int v = 0; v < mesh.num_vertices(); ++v)
    a(v, 0) = mesh.vertex(v).x(), a(v, 1) = mesh.vertex(v).y();
  return out;
}

/// Per edge, two integers: (v0, v1) or (cell0, cell1), -1 for no cell.
py::array_t<int> edge_pairs(const PolygonMesh& mesh, bool cells) {
  py::array_t<int> out({mesh.num_edges(), 2});
  auto a = out.mutable_unchecked<2>();
  for (int e = 0; e < mesh.num_edges(); ++e) {
    const MeshEdge& edge = mesh.edge(e);
    a(e, 0) = cells ? edge.cell0 : edge.v0;
    a(e, 1) = cells ? edge.cell1 : edge.v1;
  }
  return out;
}

/// vorodg.Mesh: its constructor from arrays, its arrays and measures, and its writer.
void bind_mesh_class(py::module_& m) {
  py::class_<MeshObject, std::shared_ptr<MeshObject>>(
      m, "Mesh",
      "A polygon mesh: vertices, counter-clockwise cells (CSR: offsets, connectivity), unique "
      "edges with their one or two cells, on a rectangle domain.")
      .def(py::init(&mesh_from_arrays), py::arg("vertices"), py::arg("offsets"),
           py::arg("connectivity"), py::arg("domain") = py::none(),
           "A mesh from arrays: vertices (n, 2), offsets (cells + 1), connectivity (vertex "
           "indices, counter-clockwise per cell); domain (x0, y0, x1, y1), default the bounding "
           "box. Raises ValueError naming the first defect of an invalid mesh.")
      .def_property_readonly("vertices", on_mesh(&vertex_array), "(n, 2) vertex coordinates")
      .def_property_readonly("offsets",
                             on_mesh([](const PolygonMesh& mesh) { return copy(mesh.offsets()); }),
                             "cell c's vertices are connectivity[offsets[c]:offsets[c + 1]]")
      .def_property_readonly("connectivity", on_mesh([](const PolygonMesh& mesh) {
                               return copy(mesh.cell_vertex_list());
                             }),
                             "the cells' vertex indices, counter-clockwise")
      .def_property_readonly(
          "edges", on_mesh([](const PolygonMesh& mesh) { return edge_pairs(mesh, false); }),
          "(edges, 2) vertex pairs (v0, v1), v0 -> v1 counter-clockwise for edge_cells[:, 0]")
      .def_property_readonly(
          "edge_cells", on_mesh([](const PolygonMesh& mesh) { return edge_pairs(mesh, true); }),
          "(edges, 2) the cells on either side, -1 outside the domain")
      .def_property_readonly("domain", on_mesh([](const PolygonMesh& mesh) {
                               const Rectangle& d = mesh.domain();
                               return py::make_tuple(d.x0(), d.y0(), d.x1(), d.y1());
                             }),
                             "(x0, y0, x1, y1)")
      .def_property_readonly(
          "family", [](const MeshObject& o) { return std::string(family_name(o.family)); },
          "the generator's family, or file (read, or built from arrays)")
      .def_property_readonly("num_cells", on_mesh(std::mem_fn(&PolygonMesh::num_cells)))
      .def_property_readonly("num_vertices", on_mesh(std::mem_fn(&PolygonMesh::num_vertices)))
      .def_property_readonly("num_edges", on_mesh(std::mem_fn(&PolygonMesh::num_edges)))
      .def_property_readonly("h_avg", on_mesh(std::mem_fn(&PolygonMesh::h_avg)),
                             "the mesh size of the rates: sqrt(domain area / cells)")
      .def("cell_areas", on_mesh([](const PolygonMesh& mesh) {
             Eigen::VectorXd a(mesh.num_cells());
             for (int c = 0; c < mesh.num_cells(); ++c) a[c] = mesh.cell_area(c);
             return a;
           }),
           "each cell's area")
      .def("cell_centroids", on_mesh([](const PolygonMesh& mesh) {
             Eigen::Matrix<double, Eigen::Dynamic, 2, Eigen::RowMajor> c(mesh.num_cells(), 2);
             for (int k = 0; k < mesh.num_cells(); ++k)
               c.row(k) = mesh.cell_centroid(k).transpose();
             return c;
           }),
           "(cells, 2) centroids")
      .def("statistics", on_mesh([](const PolygonMesh& mesh) {
             return to_python(to_json(compute_statistics(mesh)));
           }),
           "what `vorodg mesh --stats` says of the mesh: counts, h_avg, edge lengths, angles, "
           "area error, sides per cell")
      .def(
          "write",
          [](const MeshObject& o, const std::string& path, bool ascii) {
            write_vtu(path, o.mesh, {}, ascii ? VtuEncoding::ascii : VtuEncoding::binary_zlib);
          },
          py::arg("path"), py::arg("ascii") = false, "writes the mesh as .vtu (atomically)")
      .def("__repr__", [](const MeshObject& o) {
        return "<vorodg.Mesh " + std::string(family_name(o.family)) + ": " +
               std::to_string(o.mesh.num_cells()) + " cells, " +
               std::to_string(o.mesh.num_vertices()) + " vertices, domain " +
               o.mesh.domain().to_string() + ">";
      });
}

/// The ways to get a mesh besides arrays: generated as `vorodg mesh` does, or read from .vtu.
void bind_mesh_sources(py::module_& m) {
  const MeshSourceOptions defaults;
  const Rectangle box = Rectangle::parse(defaults.domain);
  m.def("generate_mesh", &generated, py::arg("family") = defaults.family,
        py::arg("domain") = std::array<double, 4>{box.x0(), box.y0(), box.x1(), box.y1()},
        py::arg("d") = defaults.d, py::arg("h") = defaults.h, py::arg("r") = defaults.r,
        py::arg("seed") = defaults.seed, py::arg("regularize") = defaults.regularize,
        py::arg("threads") = 1,
        "A mesh of a family, as `vorodg mesh --family F --domain x0,y0,x1,y1 --d D | --h H --r R "
        "--seed S --regularize X`: rcp and tri take d (the seeds' minimum distance), hex, "
        "perturbed-hex and quad take h. The same seed gives the same mesh for any thread count.");
  m.def(
      "read_mesh",
      [](const std::string& path, const Domain& domain) {
        const std::optional<Rectangle> box =
            domain ? std::optional<Rectangle>(rectangle(*domain)) : std::nullopt;
        PolygonMesh mesh = read_vtu(path, box ? &*box : nullptr);
        require_valid_mesh(mesh, "mesh " + path);
        return MeshObject{std::move(mesh), MeshFamily::file};
      },
      py::arg("path"), py::arg("domain") = py::none(),
      "A mesh from a .vtu file (its domain from the file's FieldData, else the bounding box, "
      "unless given); refused (ValueError) unless valid.");
}

}  // namespace

void bind_mesh(py::module_& m) {
  bind_mesh_class(m);
  bind_mesh_sources(m);
}

}  // namespace vorodg::python
