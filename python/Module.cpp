// The Python module `vorodg`: its parts register themselves (Bindings.hpp), and C++ errors
// become Python exceptions with the program's messages.
#include "core/util/Errors.hpp"
#include "python/Bindings.hpp"

namespace vorodg::python {

void bind_errors(py::module_& m) {
  // Numerical breakdown (a singular system, an iteration that did not converge, an unstable
  // step) is not bad input: its own type, an ArithmeticError.
  static py::exception<NumericalError> numerical(m, "NumericalError", PyExc_ArithmeticError);
  py::register_exception_translator([](std::exception_ptr error) {
    try {
      if (error) std::rethrow_exception(error);
    } catch (const InputError& e) {
      PyErr_SetString(PyExc_ValueError, e.what());
    } catch (const NumericalError& e) {
      numerical(e.what());
    }
  });
}

py::object to_python(const nlohmann::json& value) {
  return py::module_::import("json").attr("loads")(value.dump());
}

nlohmann::json from_python(const py::handle& value) {
  const std::string text = py::str(py::module_::import("json").attr("dumps")(value));
  return nlohmann::json::parse(text);
}

}  // namespace vorodg::python

PYBIND11_MODULE(vorodg, m) {
  m.doc() =
      "vorodg: 2D elasticity on polygon meshes with reproducing-kernel elements, CG and DG "
      "formulations, verification studies and cohesive fracture (docs/python.md).";
  using namespace vorodg::python;
  bind_errors(m);
  bind_mesh(m);
  bind_solve(m);
  bind_study(m);
  bind_fracture(m);
  bind_statistics(m);
}
