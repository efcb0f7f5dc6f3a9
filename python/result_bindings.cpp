#include "python/result_bindings.h"

#include <pybind11/numpy.h>
#include <pybind11/stl.h>

#include <cmath>
#include <memory>
#include <optional>

#include "engine/io/result_file.h"
#include "python/result_pickle.h"

namespace baize::python {
namespace {

namespace py = pybind11;

// An event as Python reads it: what the engine's Event holds, balls named by id.
struct PyEvent {
  double time_s = 0;
  std::string kind;                 // engine::eventKindName: "ball-ball", "cushion", ...
  std::vector<std::string> balls;   // one, or two for a ball-ball contact
  std::optional<int> cushion;       // a cushion or jaw contact: the cushion's or jaw's index
  std::optional<int> pocket;        // a pocket event: the pocket's index
};

PyEvent pyEventOf(const engine::Event& event, const std::vector<std::string>& ids) {
  PyEvent e;
  e.time_s = event.time_s;
  e.kind = engine::eventKindName(event.kind);
  e.balls.push_back(ids[event.ball]);
  if (event.other >= 0) e.balls.push_back(ids[event.other]);
  if (event.kind == engine::EventKind::Cushion || event.kind == engine::EventKind::Jaw)
    e.cushion = event.index;
  if (event.kind == engine::EventKind::Pocket) e.pocket = event.index;
  return e;
}

std::vector<PyEvent> eventsOf(const ShotRun& shot) {
  std::vector<PyEvent> events;
  events.reserve(shot.run.result.events.size());
  for (const engine::Event& event : shot.run.result.events)
    events.push_back(pyEventOf(event, shot.run.ball_ids));
  return events;
}

py::array_t<double> finalPositions(const ShotRun& shot) {
  const auto& balls = shot.run.result.final_balls;  // in ball_ids' order
  py::array_t<double> positions({static_cast<py::ssize_t>(balls.size()), py::ssize_t{2}});
  auto view = positions.mutable_unchecked<2>();
  for (std::size_t i = 0; i < balls.size(); ++i) {
    view(i, 0) = balls[i].state.position.x();
    view(i, 1) = balls[i].state.position.y();
  }
  return positions;
}

py::array_t<double> sample(ShotRun& shot, const py::array_t<double, py::array::forcecast>& times) {
  if (times.ndim() != 1) {
    throw py::value_error("times must be one-dimensional (a list or 1-D array of seconds); got " +
                          std::to_string(times.ndim()) + " dimensions");
  }
  const auto t = times.unchecked<1>();
  for (py::ssize_t k = 0; k < t.shape(0); ++k) {
    if (!(std::isfinite(t(k)) && t(k) >= 0)) {
      throw py::value_error("times[" + std::to_string(k) + "] = " + std::to_string(t(k)) +
                            " is not allowed: a time must be finite and >= 0 s");
    }
  }
  const auto& trajectories = recordedRunOf(shot).result.trajectories;
  const physics::ClothParams& cloth = clothOf(shot);
  py::array_t<double> positions(
      {static_cast<py::ssize_t>(trajectories.size()), t.shape(0), py::ssize_t{2}});
  auto view = positions.mutable_unchecked<3>();
  for (std::size_t i = 0; i < trajectories.size(); ++i) {
    for (py::ssize_t k = 0; k < t.shape(0); ++k) {
      const physics::BallState state = engine::sampleTrajectory(cloth, trajectories[i], t(k));
      view(i, k, 0) = state.position.x();
      view(i, k, 1) = state.position.y();
    }
  }
  return positions;
}

}  // namespace

py::object resultObject(ShotRun&& shot) {
  static const py::detail::type_info* const bound = py::detail::get_type_info(typeid(ShotRun));
  auto owned = std::make_unique<ShotRun>(std::move(shot));
  py::handle result = py::detail::type_caster_generic::cast(
      owned.get(), py::return_value_policy::take_ownership, py::handle(), bound, nullptr, nullptr,
      nullptr);
  if (!result) throw py::error_already_set();
  owned.release();  // the Python object owns it now
  return py::reinterpret_steal<py::object>(result);
}

void bindResult(py::module_& module) {
  py::class_<PyEvent>(module, "Event", "One event of a shot, in the order they happened.")
      .def_readonly("time", &PyEvent::time_s, "seconds from the cue's strike")
      .def_readonly("kind", &PyEvent::kind,
                    "'ball-ball', 'cushion', 'jaw', 'pocket' or 'state change'")
      .def_readonly("balls", &PyEvent::balls, "the ball ids involved (two for 'ball-ball')")
      .def_readonly("cushion", &PyEvent::cushion, "the cushion's (or jaw's) index, else None")
      .def_readonly("pocket", &PyEvent::pocket, "the pocket's index, else None")
      .def("__eq__", [](const PyEvent& a, const PyEvent& b) {
        return a.time_s == b.time_s && a.kind == b.kind && a.balls == b.balls &&
               a.cushion == b.cushion && a.pocket == b.pocket;
      })
      .def("__repr__", [](const PyEvent& e) {
        return "Event(time=" + py::repr(py::float_(e.time_s)).cast<std::string>() + ", kind='" +
               e.kind + "', balls=" + py::repr(py::cast(e.balls)).cast<std::string>() + ")";
      });

  py::class_<ShotRun>(module, "Result", "A simulated shot (baize.simulate, baize.simulate_many).")
      .def_property_readonly("events", &eventsOf, "the events, in time order (list of Event)")
      .def_property_readonly(
          "ball_ids", [](const ShotRun& s) { return s.run.ball_ids; },
          "the balls' ids; ball i of final_positions and sample() is ball_ids[i]")
      .def_property_readonly("final_positions", &finalPositions,
                             "where each ball stopped (or fell), numpy array n x 2, metres")
      .def_property_readonly(
          "pocketed",
          [](ShotRun& s) {
            std::vector<std::pair<std::string, int>> fallen;
            for (const engine::PocketedBall& b : outcomeOf(s).pocketed) fallen.emplace_back(b.ball, b.pocket);
            return fallen;
          },
          "the balls pocketed, in the order they fell: (ball id, pocket index) pairs")
      .def_property_readonly(
          "first_ball_hit", [](ShotRun& s) { return outcomeOf(s).first_hit; },
          "the first ball the cue ball touched, or None")
      .def_property_readonly(
          "foul", [](ShotRun& s) { return std::string(engine::foulName(outcomeOf(s).foul)); },
          "'none', or the foul the shot made")
      .def_property_readonly("beyond_model_range", &beyondModelRangeOf,
                    "indices into events of the cushion and jaw impacts faster than the scene's "
                    "physics.cushion.valid_normal_speed_mps (the cushion model's stated range)")
      .def_property_readonly(
          "end_time", [](const ShotRun& s) { return s.run.result.end_time_s; },
          "when the last ball stopped or fell, s")
      .def(py::pickle([](ShotRun& s) { return py::bytes(shotRunBytes(s)); },
                      [](const py::bytes& bytes) { return shotRunFromBytes(bytes); }))
      .def("sample", &sample, py::arg("times"),
           "Positions at the given times (s, >= 0) from the exact trajectories: numpy array "
           "n_balls x n_times x 2, metres. A pocketed ball stays where it fell.");
}

}  // namespace baize::python
