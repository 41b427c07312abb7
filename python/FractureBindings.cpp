// Fracture and fragmentation from Python: one run of a fracture scene (the quasi-static path's
// curve and its interface states) or of a fragmentation scene (its fragments), run as the study
// runs it (the same files), and the crack-state measures: fragments of a crack pattern and the
// Hamming distance of two.
#include <pybind11/eigen.h>
#include <pybind11/numpy.h>
#include <pybind11/stl.h>

#include <filesystem>

#include "core/io/AtomicFile.hpp"
#include "core/util/Errors.hpp"
#include "dg/CohesiveFracture.hpp"
#include "dg/QuasiStaticPath.hpp"
#include "dynamics/ExplicitSimulation.hpp"
#include "fracture/CrackState.hpp"
#include "fracture/Fragments.hpp"
#include "python/Bindings.hpp"
#include "verification/api/SceneRuns.hpp"
#include "verification/api/SceneStudy.hpp"

namespace vorodg::python {
namespace {

namespace fs = std::filesystem;
using RunChoice = std::variant<int, std::string>;

/// Which run of which scene: a dict, a file or a shipped scene's name, and the part and run.
SceneRunChoice choice_of(const py::handle& scene, const std::string& output,
                         const std::optional<std::string>& variant, const RunChoice& run) {
  SceneRunChoice choice{"scene", "scene", variant, run, output};
  if (py::isinstance<py::dict>(scene)) {
    choice.text = from_python(scene).dump();
  } else {
    const fs::path file = resolve_scene(py::str(scene));
    choice.text = read_file(file);
    choice.source = file.string();
  }
  return choice;
}

/// The columns of a curve, one array each.
struct Curve {
  std::map<std::string, std::vector<double>> columns;
  void add(const std::string& name, double value) { columns[name].push_back(value); }
  py::dict arrays() const {
    py::dict out;
    for (const auto& [name, values] : columns)
      out[py::str(name)] =
          py::array_t<double>(static_cast<py::ssize_t>(values.size()), values.data());
    return out;
  }
};

/// The interface points of the last point of the path: per interface its mesh edge, and per
/// point (two per interface) its state (0 intact, 1 cohesive, 2 open) and largest opening.
struct Interfaces {
  std::vector<int> edge;
  std::vector<int> state;
  std::vector<double> max_opening;
  void take(const CohesiveFracture& model, const std::vector<InterfacePoint>& points) {
    edge.clear(), state.clear(), max_opening.clear();
    for (std::size_t p = 0; p < points.size(); ++p) {
      if (p % 2 == 0) edge.push_back(model.interfaces().face(static_cast<int>(p)).edge);
      state.push_back(static_cast<int>(points[p].state));
      max_opening.push_back(points[p].history.max_opening);
    }
  }
  py::dict arrays() const {
    py::dict out;
    const auto n = static_cast<py::ssize_t>(edge.size());
    out["edge"] = py::array_t<int>(n, edge.data());
    out["state"] = py::array_t<int>({n, py::ssize_t{2}}, state.data());
    out["max_opening"] = py::array_t<double>({n, py::ssize_t{2}}, max_opening.data());
    return out;
  }
};

py::dict fracture_path(const py::handle& scene, const std::string& output,
                       const std::optional<std::string>& variant, const RunChoice& run) {
  Curve curve;
  Interfaces interfaces;
  SceneRunResult r = fracture_scene_run(
      choice_of(scene, output, variant, run), [&](const CohesiveFracture& model, const PathPoint& p,
                                                  const std::vector<InterfacePoint>& points) {
        for (const auto& [name, value] : {std::pair{"step", double(p.step)},
                                          {"displacement", p.stroke},
                                          {"cmod", p.cmod},
                                          {"load", p.load},
                                          {"external_work", p.external_work},
                                          {"elastic_energy", p.energy.elastic},
                                          {"dissipated_energy", p.energy.dissipated},
                                          {"coupling_energy", p.energy.coupling},
                                          {"cohesive_energy", p.energy.cohesive},
                                          {"switched_energy", p.energy.switched},
                                          {"crack_length", p.energy.crack_length},
                                          {"inserted", double(p.inserted)},
                                          {"newton_iterations", double(p.iterations)}})
          curve.add(name, value);
        interfaces.take(model, points);
      });
  py::dict out;
  out["record"] = to_python(r.record);
  out["curve"] = curve.arrays();
  out["interfaces"] = interfaces.arrays();
  out["mesh"] = MeshObject{std::move(r.mesh), MeshFamily::file};
  return out;
}

/// What a Fragments object says, copied (it refers to the run's masses, gone after the run).
struct FragmentData {
  std::vector<int> cell_fragment, cells;
  Eigen::VectorXd mass;
  Eigen::Matrix2Xd centre, velocity;

  explicit FragmentData(const Fragments& pieces)
      : cell_fragment(pieces.cell_fragments()),
        cells(pieces.num_fragments()),
        mass(pieces.masses()),
        centre(pieces.centres()) {
    for (int f = 0; f < pieces.num_fragments(); ++f) cells[f] = pieces.num_cells(f);
  }

  py::dict arrays() const {
    using Rows = Eigen::Matrix<double, Eigen::Dynamic, 2, Eigen::RowMajor>;
    py::dict out;
    out["cell_fragment"] =
        py::array_t<int>(static_cast<py::ssize_t>(cell_fragment.size()), cell_fragment.data());
    out["mass"] = mass;
    out["centre"] = Rows(centre.transpose());
    out["cells"] = py::array_t<int>(static_cast<py::ssize_t>(cells.size()), cells.data());
    if (velocity.cols() > 0) out["velocity"] = Rows(velocity.transpose());
    return out;
  }
};

py::dict fragmentation_run(const py::handle& scene, const std::string& output,
                           const std::optional<std::string>& variant, const RunChoice& run,
                           bool force) {
  const SceneRunChoice choice = choice_of(scene, output, variant, run);
  std::optional<FragmentData> fragments;
  std::vector<int> broken;
  std::optional<SceneRunResult> r;
  {
    py::gil_scoped_release unlocked;
    r = fragmentation_scene_run(choice, force, [&](const ExplicitSimulation& model) {
      const CrackState state = model.cracks->broken_state();
      const Fragments pieces(state, model.mass.pair_masses());
      fragments.emplace(pieces);
      fragments->velocity = pieces.velocities(model.run->dofs(), model.run->velocity());
      broken.assign(state.flags().begin(), state.flags().end());
    });
  }
  py::dict out;
  out["record"] = to_python(r->record);
  out["fragments"] = fragments->arrays();
  out["broken"] = py::array_t<int>(static_cast<py::ssize_t>(broken.size()), broken.data());
  out["mesh"] = MeshObject{std::move(r->mesh), MeshFamily::file};
  return out;
}

using Flags = py::array_t<int, py::array::c_style | py::array::forcecast>;

/// Per mesh edge, 0 or 1, from as many booleans or integers (a list or an array).
std::vector<char> edge_flags(const PolygonMesh& mesh, const Flags& flags, const char* what) {
  if (flags.ndim() != 1 || flags.size() != mesh.num_edges())
    throw InputError(std::string(what) + ": " + std::to_string(flags.size()) +
                     " values, expected one per mesh edge (" + std::to_string(mesh.num_edges()) +
                     ")");
  std::vector<char> out(flags.size());
  for (py::ssize_t e = 0; e < flags.size(); ++e) out[e] = flags.data()[e] != 0;
  return out;
}

}  // namespace

void bind_fracture(py::module_& m) {
  m.def("fracture_path", &fracture_path, py::arg("scene"), py::arg("output"),
        py::arg("variant") = py::none(), py::arg("run") = 0,
        "One run of a fracture scene (a file, a shipped name or a dict; variant= its label; "
        "run= its place among the mesh runs, or its id 'rcp-L0-R1'), as the study runs it, "
        "writing its curve, cracks and frames under output. Returns a dict: record (its "
        "results.jsonl line), curve (arrays per column: step, displacement, cmod, load, "
        "energies, crack_length, inserted, newton_iterations), interfaces at the last point "
        "(edge per interface; state 0 intact, 1 cohesive, 2 open and max_opening per Gauss "
        "point, shape (interfaces, 2)) and mesh.");
  m.def("fragmentation_run", &fragmentation_run, py::arg("scene"), py::arg("output"),
        py::arg("variant") = py::none(), py::arg("run") = 0, py::arg("force") = false,
        "One run of a fragmentation scene (as fracture_path), as the study runs it. Returns a "
        "dict: record, fragments at the end (cell_fragment per cell; mass, centre (k, 2) in the "
        "reference configuration, velocity (k, 2), cells per fragment), broken (per mesh edge, "
        "1 where fully broken) and mesh.");
  m.def(
      "fragments",
      [](const MeshObject& mesh, const Flags& cracked, double density) {
        const CrackState state(mesh.mesh, edge_flags(mesh.mesh, cracked, "cracked"));
        return FragmentData(Fragments(state, density)).arrays();
      },
      py::arg("mesh"), py::arg("cracked"), py::arg("density") = 1.0,
      "The fragments a crack pattern (per mesh edge, true where cracked) cuts the mesh into: "
      "cell_fragment, mass (density x area), centre (k, 2), cells per fragment.");
  m.def(
      "hamming",
      [](const MeshObject& mesh, const Flags& a, const Flags& b) {
        return CrackState::hamming(CrackState(mesh.mesh, edge_flags(mesh.mesh, a, "a")),
                                   CrackState(mesh.mesh, edge_flags(mesh.mesh, b, "b")));
      },
      py::arg("mesh"), py::arg("a"), py::arg("b"),
      "The Hamming distance of two crack patterns on one mesh: the interior edges cracked in one "
      "and not the other.");
}

}  // namespace vorodg::python
