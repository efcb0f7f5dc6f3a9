// baize.simulate is a plain CPython function (METH_FASTCALL), not a pybind11 binding:
// pybind11's general dispatcher (overloads, keywords, conversions, its own bookkeeping) costs as
// much per call as the rest of the binding together, a few percent of a typical shot. What is left
// is measured against the same shot in C++ by tools/bench_python.py.
#include "python/simulate_function.h"

#include <pybind11/stl.h>

#include <chrono>
#include <memory>
#include <string>
#include <vector>

#include "python/result_bindings.h"
#include "python/scene_bindings.h"
#include "python/shot_run.h"

namespace baize::python {
namespace {

namespace py = pybind11;

// The one argument, by position or as scene=...: METH_FASTCALL puts keyword values after the
// positional ones in `arguments`, their names in `keywords`.
PyObject* theSceneArgument(PyObject* const* arguments, Py_ssize_t positional, PyObject* keywords) {
  const Py_ssize_t named = keywords == nullptr ? 0 : PyTuple_GET_SIZE(keywords);
  if (positional == 1 && named == 0) return arguments[0];
  if (positional == 0 && named == 1 &&
      PyUnicode_CompareWithASCIIString(PyTuple_GET_ITEM(keywords, 0), "scene") == 0) {
    return arguments[0];
  }
  for (Py_ssize_t k = 0; k < named; ++k) {
    const std::string name = py::str(PyTuple_GET_ITEM(keywords, k)).cast<std::string>();
    if (name != "scene") throw py::type_error("simulate() has no argument '" + name + "': it takes scene");
  }
  throw py::type_error("simulate() takes one argument, scene; got " + std::to_string(positional) +
                       " by position and " + std::to_string(named) + " by name");
}

// Whether a Python thread other than this one exists, which could run while this one simulates.
bool otherPythonThreads() {
  PyThreadState* self = PyThreadState_Get();
  PyThreadState* first = PyInterpreterState_ThreadHead(PyThreadState_GetInterpreter(self));
  return first != self || PyThreadState_Next(first) != nullptr;
}

// Releasing and taking back the GIL is a cost of its own; it buys something only when another
// Python thread can run meanwhile. (A thread that first enters Python during the shot waits for
// its end, as it would behind any Python code.)
ShotRun runReleasingTheGilWhenWorthIt(std::shared_ptr<const engine::Scene> scene) {
  if (!otherPythonThreads()) return runShot(std::move(scene));
  const py::gil_scoped_release released;
  return runShot(std::move(scene));
}

PyObject* simulate(PyObject* /*module*/, PyObject* const* arguments, Py_ssize_t positional,
                   PyObject* keywords) noexcept {
  try {
    PyObject* scene = theSceneArgument(arguments, positional, keywords);
    return resultObject(runReleasingTheGilWhenWorthIt(sceneArgument(scene, "scene"))).release().ptr();
  } catch (...) {
    // The exceptions as a pybind11 binding raises them: std::invalid_argument a ValueError, ...
    py::detail::translate_exception(std::current_exception());
    return nullptr;
  }
}

PyMethodDef simulate_method = {
    "simulate", reinterpret_cast<PyCFunction>(reinterpret_cast<void (*)()>(&simulate)),
    METH_FASTCALL | METH_KEYWORDS,
    "simulate(scene)\n--\n\n"
    "Strikes the cue ball and simulates until every ball is at rest or pocketed. Returns a "
    "Result. A shot the engine cannot finish raises ValueError (bad input) or RuntimeError."};

// The wall time of each of `repeats` runs of the shot in C++ alone, ns: engine::runScene recording
// the trajectories as simulate() does (or not, as `baize bench shots` times it), the result freed
// as the Python loop frees it. The reference of tools/bench_python.py's ratios.
std::vector<double> nativeRunTimes(const engine::Scene& scene, int repeats, bool record_trajectories) {
  if (repeats < 1) throw py::value_error("repeats = " + std::to_string(repeats) + " must be >= 1");
  const py::gil_scoped_release released;
  std::vector<double> times_ns;
  for (int k = 0; k < repeats; ++k) {
    const auto start = std::chrono::steady_clock::now();
    { const engine::SceneRun run = engine::runScene(scene, record_trajectories); }
    const auto stop = std::chrono::steady_clock::now();
    times_ns.push_back(std::chrono::duration<double, std::nano>(stop - start).count());
  }
  return times_ns;
}

// `repeats` empty intervals of the same clock, ns: what reading it costs, taken off the times above.
std::vector<double> nativeClockTimes(int repeats) {
  if (repeats < 1) throw py::value_error("repeats = " + std::to_string(repeats) + " must be >= 1");
  std::vector<double> times_ns;
  for (int k = 0; k < repeats; ++k) {
    const auto start = std::chrono::steady_clock::now();
    const auto stop = std::chrono::steady_clock::now();
    times_ns.push_back(std::chrono::duration<double, std::nano>(stop - start).count());
  }
  return times_ns;
}

}  // namespace

void bindSimulate(py::module_& module) {
  PyObject* function = PyCFunction_NewEx(&simulate_method, module.ptr(), module.attr("__name__").ptr());
  if (function == nullptr) throw py::error_already_set();
  module.add_object("simulate", py::reinterpret_steal<py::object>(function));
  module.def("_native_run_times_ns", &nativeRunTimes, py::arg("scene"), py::arg("repeats"),
             py::arg("record_trajectories") = true,
             "For benchmarks: the wall time of each of `repeats` runs of the shot in C++, ns.");
  module.def("_native_clock_ns", &nativeClockTimes, py::arg("repeats"),
             "For benchmarks: `repeats` empty intervals of the clock _native_run_times_ns reads, ns.");
}

}  // namespace baize::python
