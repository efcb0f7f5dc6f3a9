#include "python/shot_batch.h"

#include <pybind11/stl.h>

#include <algorithm>
#include <atomic>
#include <optional>
#include <stdexcept>
#include <thread>

#include "python/result_bindings.h"
#include "python/scene_bindings.h"

namespace baize::python {
namespace {

namespace py = pybind11;

// More threads than this is a typo, not a machine (as baize batch --threads).
constexpr int kMaxThreads = 1024;

// A shot of a batch that failed: where it stands in the input and the engine's message.
struct ShotError {
  long index = 0;
  std::string kind;     // "ValueError" (the scene's input refused) or "RuntimeError"
  std::string message;
};

struct BatchEntry {
  std::optional<ShotRun> shot;
  ShotError error;
};

BatchEntry runEntry(const std::shared_ptr<const engine::Scene>& scene, long index) {
  BatchEntry entry;
  try {
    entry.shot = runShot(scene);
  } catch (const std::invalid_argument& refused) {
    entry.error = {index, "ValueError", refused.what()};
  } catch (const std::exception& failed) {
    entry.error = {index, "RuntimeError", failed.what()};
  }
  return entry;
}

int threadsFor(int asked, std::size_t shots) {
  if (asked < 0 || asked > kMaxThreads) {
    throw py::value_error("threads = " + std::to_string(asked) + " is not allowed: it must lie in [0, " +
                          std::to_string(kMaxThreads) + "] (0: every core)");
  }
  const int cores = std::max(1u, std::thread::hardware_concurrency());
  const int wanted = asked == 0 ? cores : asked;
  return static_cast<int>(std::max<std::size_t>(1, std::min<std::size_t>(wanted, shots)));
}

// Each thread takes the next shot not yet taken, so the threads stay busy whatever the shots cost;
// each shot's result goes to its own slot, so the order is the input's.
std::vector<BatchEntry> runAll(const std::vector<std::shared_ptr<const engine::Scene>>& scenes,
                               int threads) {
  std::vector<BatchEntry> entries(scenes.size());
  std::atomic<std::size_t> next{0};
  auto work = [&] {
    for (std::size_t i = next++; i < scenes.size(); i = next++)
      entries[i] = runEntry(scenes[i], static_cast<long>(i));
  };
  std::vector<std::thread> pool;
  for (int t = 1; t < threads; ++t) pool.emplace_back(work);
  work();
  for (std::thread& t : pool) t.join();
  return entries;
}

py::list simulateMany(const py::iterable& scenes_in, int threads, const std::string& on_error) {
  if (on_error != "raise" && on_error != "return") {
    throw py::value_error("on_error = '" + on_error + "' is not allowed: it must be 'raise' or 'return'");
  }
  std::vector<std::shared_ptr<const engine::Scene>> scenes;
  for (const py::handle item : scenes_in)
    scenes.push_back(sceneArgument(item, "scenes[" + std::to_string(scenes.size()) + "]"));
  const int used = threadsFor(threads, scenes.size());
  std::vector<BatchEntry> entries;
  {
    const py::gil_scoped_release released;
    entries = runAll(scenes, used);
  }
  py::list results;
  py::list errors;
  for (BatchEntry& entry : entries) {
    if (entry.shot) {
      results.append(resultObject(std::move(*entry.shot)));
    } else {
      py::object error = py::cast(entry.error);
      results.append(error);
      errors.append(error);
    }
  }
  if (on_error == "raise" && !errors.empty()) {
    const ShotError& first = errors[0].cast<const ShotError&>();
    py::object batch_error = py::module_::import("baize").attr("BatchError")(
        std::to_string(errors.size()) + " of " + std::to_string(entries.size()) +
            " shots failed; the first, shot " + std::to_string(first.index) + ": " + first.message,
        results, errors);
    PyErr_SetObject(batch_error.get_type().ptr(), batch_error.ptr());
    throw py::error_already_set();
  }
  return results;
}

}  // namespace

void bindShotBatch(py::module_& module) {
  py::class_<ShotError>(module, "ShotError",
                        "A shot of simulate_many that failed: its index in the input, the kind of "
                        "error one by one would raise, and the message.")
      .def(py::init([](long index, std::string kind, std::string message) {
             return ShotError{index, std::move(kind), std::move(message)};
           }),
           py::arg("index"), py::arg("kind"), py::arg("message"))
      .def_readonly("index", &ShotError::index)
      .def_readonly("kind", &ShotError::kind)
      .def_readonly("message", &ShotError::message)
      .def(py::pickle(
          [](const ShotError& e) { return py::make_tuple(e.index, e.kind, e.message); },
          [](const py::tuple& t) {
            return ShotError{t[0].cast<long>(), t[1].cast<std::string>(), t[2].cast<std::string>()};
          }))
      .def("__repr__", [](const ShotError& e) {
        return "ShotError(index=" + std::to_string(e.index) + ", kind='" + e.kind +
               "', message=" + py::repr(py::str(e.message)).cast<std::string>() + ")";
      });

  module.def("simulate_many", &simulateMany, py::arg("scenes"), py::arg("threads") = 0,
             py::arg("on_error") = "raise",
             "Simulates every scene on `threads` threads (0: every core) with the GIL released. "
             "Returns the Results in the input's order, each the same to the bit as simulate() "
             "gives. A failed shot becomes a ShotError (index, kind, message) at its place: with "
             "on_error='raise' (default) BatchError is raised after every shot has run, carrying "
             "the whole list (.results) and the failures (.errors); with on_error='return' the "
             "list is returned.");
}

}  // namespace baize::python
