// The Python module `unidyn._unidyn` (pybind11): PythonModel's methods with numpy arrays in and
// out, the interpreter's lock released while they work, and unidyn's errors as Python exceptions —
// ModelError (a ValueError) with .file, .line, .column; bad input as ValueError; a failure as
// RuntimeError. python/unidyn/__init__.py wraps it in the documented API.
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <chrono>

#include "python_model.hpp"
#include "unidyn/integrate/simulation.hpp"
#include "unidyn/rotation/errors.hpp"

namespace py = pybind11;
using unidyn::python::PythonModel;
using unidyn::python::RunRequest;
using Settings = std::vector<std::pair<std::string, double>>;

namespace {

using Array = py::array_t<double, py::array::c_style | py::array::forcecast>;

// A run request from the keyword arguments (None: the model's own).
RunRequest request(std::optional<double> t_end, std::optional<double> output_step,
                   std::optional<std::string> method, std::optional<double> rtol,
                   const Settings& set, bool poses) {
  RunRequest r;
  r.t_end = t_end.value_or(0.0);
  r.output_step = output_step.value_or(0.0);
  r.rtol = rtol.value_or(0.0);
  r.method = method.value_or("");
  r.set = set;
  r.poses = poses;
  // the command line refuses 0 and negative values; so does this
  for (const auto& [name, value] :
       {std::pair{"t_end", t_end}, std::pair{"output_step", output_step},
        std::pair{"rtol", rtol}}) {
    if (value && !(*value > 0)) {
      throw std::invalid_argument(std::string(name) + " must be positive");
    }
  }
  return r;
}

// q̈ (and λ) at one state (1-D q, q̇) or at each row of 2-D ones.
py::tuple rhs(const PythonModel& model, const Array& q, const Array& qdot, double t,
              const Settings& set) {
  const auto n = static_cast<py::ssize_t>(model.coordinate_count());
  const auto m = static_cast<py::ssize_t>(model.constraint_count());
  if (q.ndim() != qdot.ndim() || q.ndim() < 1 || q.ndim() > 2 || q.shape(q.ndim() - 1) != n ||
      qdot.shape(qdot.ndim() - 1) != n || (q.ndim() == 2 && q.shape(0) != qdot.shape(0))) {
    throw std::invalid_argument("rhs: q and qd must both be of " + std::to_string(n) +
                                " values, or both (count, " + std::to_string(n) + ") arrays");
  }
  const bool batch = q.ndim() == 2;
  const py::ssize_t count = batch ? q.shape(0) : 1;
  Array qddot = batch ? Array({count, n}) : Array(n);
  Array lambda = batch ? Array({count, m}) : Array(m);
  const double* q_data = q.data();
  const double* qdot_data = qdot.data();
  double* qddot_data = qddot.mutable_data();
  double* lambda_data = lambda.mutable_data();
  {
    py::gil_scoped_release unlocked;
    model.rhs(q_data, qdot_data, static_cast<std::size_t>(count), t, set, qddot_data, lambda_data);
  }
  return py::make_tuple(qddot, lambda);
}

}  // namespace

PYBIND11_MODULE(_unidyn, module) {
  module.doc() = "unidyn's compiled core; use the package `unidyn` (python/unidyn/__init__.py)";

  // unidyn.ModelError: file:line:column and what was expected
  static py::exception<unidyn::ModelError> model_error(module, "ModelError", PyExc_ValueError);
  py::register_exception_translator([](std::exception_ptr p) {
    try {
      if (p) std::rethrow_exception(p);
    } catch (const unidyn::ModelError& e) {
      const auto type = py::reinterpret_borrow<py::object>(model_error.ptr());
      py::object error = type(py::str(e.what()));
      error.attr("file") = e.where().file;
      error.attr("line") = e.where().line;
      error.attr("column") = e.where().column;
      PyErr_SetObject(model_error.ptr(), error.ptr());
    } catch (const unidyn::SingularConfiguration& e) {
      PyErr_SetString(PyExc_ValueError, e.what());
    }
  });

  py::class_<PythonModel, std::shared_ptr<PythonModel>>(module, "Model")
      .def(py::init([](const std::string& source, bool limits) {
             py::gil_scoped_release unlocked;
             return std::make_shared<PythonModel>(source, limits);
           }),
           py::arg("source"), py::arg("limits") = false)
      .def_property_readonly("name", [](const PythonModel& m) { return m.system().name; })
      .def_property_readonly("reference", [](const PythonModel& m) { return m.system().reference; })
      .def_property_readonly("path", &PythonModel::path)
      .def_property_readonly("text", &PythonModel::text)
      .def_property_readonly("parameters", &PythonModel::parameters)
      .def_property_readonly("coordinates",
                             [](const PythonModel& m) {
                               std::vector<std::string> names;
                               for (const auto& q : m.system().coordinates())
                                 names.push_back(q.name);
                               return names;
                             })
      .def_property_readonly(
          "columns", [](const PythonModel& m) { return unidyn::simulation_columns(m.system()); })
      .def_property_readonly("constraints",
                             [](const PythonModel& m) {
                               std::vector<std::string> names;
                               for (const auto& c : m.system().constraints) names.push_back(c.name);
                               return names;
                             })
      .def(
          "derive",
          [](const PythonModel& m, const std::string& method, const std::string& format,
             const std::string& form) {
            py::gil_scoped_release unlocked;
            return m.derive(method, format, form);
          },
          py::arg("method") = "lagrange", py::arg("format") = "text", py::arg("form") = "textbook")
      .def(
          "_simulate",
          [](const PythonModel& m, std::optional<double> t_end, std::optional<double> output_step,
             std::optional<std::string> method, std::optional<double> rtol, const Settings& set,
             bool poses) {
            RunRequest r = request(t_end, output_step, method, rtol, set, poses);
            // Ctrl-C: the interpreter's handler only notes it; asked for here, with the lock
            // taken back at most every 50 ms, it ends the run and raises KeyboardInterrupt
            bool interrupted = false;
            auto asked = std::chrono::steady_clock::now();
            r.interrupted = [&] {
              const auto now = std::chrono::steady_clock::now();
              if (interrupted || now - asked < std::chrono::milliseconds(50)) return interrupted;
              asked = now;
              py::gil_scoped_acquire held;
              interrupted = PyErr_CheckSignals() != 0;
              return interrupted;
            };
            unidyn::python::RunResult result;
            {
              py::gil_scoped_release unlocked;
              result = m.simulate(r);
            }
            if (interrupted) throw py::error_already_set();
            const auto columns = static_cast<py::ssize_t>(result.columns.size());
            Array values({static_cast<py::ssize_t>(result.rows), columns});
            std::copy(result.values.begin(), result.values.end(), values.mutable_data());
            return py::make_tuple(result.columns, values, result.summary, result.events, result.ok,
                                  result.message);
          },
          py::arg("t_end"), py::arg("output_step"), py::arg("method"), py::arg("rtol"),
          py::arg("set"), py::arg("poses"))
      .def("rhs", &rhs, py::arg("q"), py::arg("qd"), py::arg("t") = 0.0,
           py::arg("set") = Settings{})
      .def(
          "_analysis",
          [](const PythonModel& m, const std::string& command, const std::vector<std::string>& at,
             const Settings& set, std::size_t starts, const std::vector<std::string>& cyclic,
             std::optional<double> period) {
            py::gil_scoped_release unlocked;
            return m.analysis_json(command, at, set, starts, cyclic, period);
          },
          py::arg("command"), py::arg("at"), py::arg("set"), py::arg("starts"), py::arg("cyclic"),
          py::arg("period") = std::nullopt)
      .def(
          "_report",
          [](const PythonModel& m, const std::string& path, std::optional<double> t_end,
             std::optional<double> output_step, std::optional<std::string> method,
             std::optional<double> rtol, const Settings& set) {
            const RunRequest r = request(t_end, output_step, method, rtol, set, false);
            py::gil_scoped_release unlocked;
            return m.report(path, r);
          },
          py::arg("path"), py::arg("t_end"), py::arg("output_step"), py::arg("method"),
          py::arg("rtol"), py::arg("set"));
}
