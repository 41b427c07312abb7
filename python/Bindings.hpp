#pragma once
// The Python module `vorodg` (docs/python.md): thin bindings over the C++ library, one file per
// part (meshes, solves, studies, fracture), each registering its functions here. Nothing is
// computed twice: every call goes to the objects the program uses, and every check and message
// is the program's.
#include <pybind11/pybind11.h>

#include <nlohmann/json.hpp>

#include "core/meshgen/MeshFamily.hpp"

namespace vorodg::python {

namespace py = pybind11;

/// vorodg.Mesh: a mesh and where it came from, which records name (a generated family; a mesh
/// read or built from arrays is a `file` mesh, as `vorodg solve --mesh` records it).
struct MeshObject {
  PolygonMesh mesh;
  MeshFamily family = MeshFamily::file;
};

/// InputError -> ValueError (the program's one-line message), NumericalError -> its own type.
void bind_errors(py::module_& m);
/// Mesh, generate_mesh, read_mesh.
void bind_mesh(py::module_& m);
/// solve, settings.
void bind_solve(py::module_& m);
/// run (a scene), scene_keys.
void bind_study(py::module_& m);
/// fracture_path, fragmentation_run, fragments, hamming.
void bind_fracture(py::module_& m);
/// vorodg.statistics: the estimators of statistical convergence (empirical CDFs, distances,
/// intervals, the sample-size planner).
void bind_statistics(py::module_& m);

/// A JSON value as Python objects (dict, list, float, int, str, bool, None), through Python's
/// json module: numbers round-trip exactly (the JSON writer prints 17 significant digits).
py::object to_python(const nlohmann::json& value);
/// A Python dict (of JSON-able values) as JSON, through Python's json module.
nlohmann::json from_python(const py::handle& value);

}  // namespace vorodg::python
