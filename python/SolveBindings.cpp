// vorodg.solve: one problem on one mesh with the settings of the one schema
// (verification/solve/SettingsSchema), named as `vorodg solve`'s options are (--max-iter is
// max_iter=), checked by the same code with the same messages; and vorodg.settings(), the schema.
#include <pybind11/eigen.h>
#include <pybind11/numpy.h>
#include <pybind11/stl.h>

#include <cmath>

#include "core/mesh/MeshValidator.hpp"
#include "core/util/BlasInfo.hpp"
#include "core/util/Errors.hpp"
#include "core/util/Format.hpp"
#include "python/Bindings.hpp"
#include "verification/api/SolveOptions.hpp"
#include "verification/solve/RunRecord.hpp"
#include "verification/solve/SettingsSchema.hpp"

namespace vorodg::python {
namespace {

/// The keyword of a setting: its option without the dashes, '-' as '_' (--max-iter: max_iter).
std::string keyword(const SettingSpec& spec) {
  std::string name = spec.flag.substr(2);
  for (char& c : name)
    if (c == '-') c = '_';
  return name;
}

const SettingSpec& spec_of_keyword(const std::string& name) {
  std::string known;
  for (const SettingSpec& spec : setting_specs()) {
    if (spec.flag.empty()) continue;
    if (keyword(spec) == name) return spec;
    known += (known.empty() ? "" : ", ") + keyword(spec);
  }
  throw InputError("setting '" + name + "': unknown; expected one of " + known);
}

/// Sets one keyword as its option would: numbers finite, integers whole, flags True or False,
/// choices by name (checked with the rest by checked_settings).
void set_keyword(SettingOptions& o, const std::string& name, const py::handle& value) {
  const SettingSpec& spec = spec_of_keyword(name);
  const std::string given = py::str(py::repr(value));
  auto refuse = [&](const std::string& expected) {
    throw InputError(spec.flag + " " + given + ": expected " + expected);
  };
  switch (spec.kind) {
    case SettingKind::flag:
      if (!py::isinstance<py::bool_>(value)) refuse("True or False");
      spec.set(o.settings, (value.cast<bool>() != spec.flag_negates) ? 1.0 : 0.0);
      return;
    case SettingKind::integer:
      if (py::isinstance<py::bool_>(value) || !py::isinstance<py::int_>(value))
        refuse("an integer");
      spec.set(o.settings, value.cast<double>());
      return;
    case SettingKind::number: {
      if (py::isinstance<py::bool_>(value) ||
          !(py::isinstance<py::int_>(value) || py::isinstance<py::float_>(value)))
        refuse("a finite number");
      const double x = value.cast<double>();
      if (!std::isfinite(x)) refuse("a finite number");
      spec.set(o.settings, x);
      return;
    }
    case SettingKind::choice:
      if (!py::isinstance<py::str>(value)) refuse(spec.range);
      o.choice_texts[spec.name] = value.cast<std::string>();
      return;
  }
}

SolveSettings settings_from(const py::kwargs& kwargs) {
  SettingOptions o;
  o.settings.element.threads = default_solve_threads();
  for (const auto& [name, value] : kwargs) set_keyword(o, py::str(name), value);
  return checked_settings(o);
}

/// (rows, columns) row-major copy of an Eigen matrix stored column by column as (columns, rows).
template <int Rows>
py::array_t<double> transposed(const Eigen::Matrix<double, Rows, Eigen::Dynamic>& columns) {
  py::array_t<double> out({static_cast<py::ssize_t>(columns.cols()), py::ssize_t{Rows}});
  auto a = out.mutable_unchecked<2>();
  for (Eigen::Index j = 0; j < columns.cols(); ++j)
    for (int i = 0; i < Rows; ++i) a(j, i) = columns(i, j);
  return out;
}

py::dict solve(const MeshObject& object, const py::kwargs& kwargs) {
  const PolygonMesh& mesh = object.mesh;
  const SolveSettings settings = settings_from(kwargs);
  require_valid_mesh(mesh, "mesh");
  SolveResult r;
  {
    py::gil_scoped_release unlocked;  // other Python threads run meanwhile
    const ScopedBlasThreads blas(settings.element.threads);
    r = run_solve(mesh, settings);
  }
  require_converged(r, settings);
  const RunMetrics metrics = run_metrics(mesh, r);
  py::dict out;
  out["displacement"] = transposed<2>(r.vertex_displacement);
  out["cell_offsets"] =
      py::array_t<int>(static_cast<py::ssize_t>(r.cell_offsets.size()), r.cell_offsets.data());
  out["cell_displacements"] = r.cell_dof_values;
  Eigen::Matrix3Xd stress(3, mesh.num_cells());
  for (int c = 0; c < mesh.num_cells(); ++c) stress.col(c) = r.cell_mean_stress[c];
  out["cell_stress"] = transposed<3>(stress);
  out["l2_error"] = r.errors_measured ? py::object(py::float_(r.l2_error)) : py::none();
  out["energy_error"] = r.errors_measured ? py::object(py::float_(r.energy_error)) : py::none();
  out["seconds"] = py::cast(std::map<std::string, double>(r.seconds.begin(), r.seconds.end()));
  out["record"] = to_python(solve_record(metrics, settings, object.family));
  return out;
}

py::list schema() {
  py::list out;
  for (const SettingSpec& spec : setting_specs()) {
    if (spec.flag.empty()) continue;
    py::dict s;
    s["name"] = keyword(spec);
    s["option"] = spec.flag;
    s["kind"] = spec.kind == SettingKind::number    ? "number"
                : spec.kind == SettingKind::integer ? "integer"
                : spec.kind == SettingKind::flag    ? "flag"
                                                    : "choice";
    s["default"] = spec.fallback;
    s["range"] = spec.range;
    s["doc"] = spec.doc;
    out.append(s);
  }
  return out;
}

}  // namespace

void bind_solve(py::module_& m) {
  m.def("solve", &solve, py::arg("mesh"),
        "Solves a problem on a mesh, as `vorodg solve` does, with its settings as keywords "
        "(problem='beam', formulation='cg', E=1, nu=0.3, kp=..., max_iter=..., no_errors=True, "
        "...: vorodg.settings() lists them with defaults and ranges). Returns a dict: "
        "displacement (vertices, 2; DG: each vertex's first cell copy), cell_offsets and "
        "cell_displacements (every cell's own vertex DOFs), cell_stress (cells, 3: sxx, syy, "
        "sxy), l2_error and energy_error (relative; None with no_errors), seconds (per stage) "
        "and record (what `vorodg solve --metrics` writes). Raises ValueError for a bad setting "
        "or mesh, vorodg.NumericalError where the solve breaks down.");
  m.def("settings", &schema,
        "Every setting of vorodg.solve: name (the keyword), option (of `vorodg solve`), kind, "
        "default, range and doc.");
}

}  // namespace vorodg::python
