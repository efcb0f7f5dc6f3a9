#include "python/scene_bindings.h"

#include <pybind11/numpy.h>
#include <pybind11/stl.h>

#include <cmath>
#include <limits>

#include "engine/play/random_shots.h"
#include "python/json_from_python.h"

namespace baize::python {
namespace {

namespace py = pybind11;

// How a scene built from Python values is named in messages (a file's are named by its path).
constexpr const char* kSceneSource = "Scene";
constexpr double kDegreesPerRadian = 180.0 / 3.14159265358979323846;
// The most random shots one call makes: beyond, a typo rather than a batch (10^8 shots are hours).
constexpr long long kMaxRandomShots = 100'000'000;

engine::Scene sceneFromValues(const py::object& table, const py::object& ball_set,
                              const py::object& shot, const py::object& balls,
                              const py::object& rack, const py::object& physics) {
  nlohmann::json document = nlohmann::json::object();
  const std::pair<const char*, const py::object*> keys[] = {
      {"table", &table}, {"ball_set", &ball_set}, {"balls", &balls},
      {"rack", &rack},   {"shot", &shot},         {"physics", &physics}};
  for (const auto& [key, value] : keys) {
    if (!value->is_none()) document[key] = jsonFromPython(*value, key);
  }
  return engine::sceneFromJson(document, kSceneSource);
}

// A random shot as the document a scene file would hold (heading in degrees): the scene is the one
// read from it, so that a pickled copy (the document again) is the same to the bit.
nlohmann::json documentOf(const engine::Scene& shot) {
  nlohmann::json balls = nlohmann::json::object();
  for (const engine::PlacedBall& ball : shot.balls)
    balls[ball.id] = {ball.position_m.x(), ball.position_m.y()};
  return {{"table", shot.table.name},
          {"ball_set", shot.ball_set.name},
          {"balls", balls},
          {"shot",
           {{"speed_mps", shot.shot.speed_mps},
            {"heading_deg", shot.shot.heading_rad * kDegreesPerRadian},
            {"side", shot.shot.side_offset},
            {"height", shot.shot.height_offset}}}};
}

// Shots drawn until `count` of them are scenes the reader accepts: the engine's generator may put a
// ball inside a corner pocket's capture circle, which a scene refuses (the ball would start
// pocketed); such shots are left out, the rest keep the generator's order.
std::vector<engine::Scene> randomShots(long long count, long long seed) {
  if (count < 0 || count > kMaxRandomShots) {
    throw py::value_error("count = " + std::to_string(count) + " is not allowed: it must lie in [0, " +
                          std::to_string(kMaxRandomShots) + "]");
  }
  if (seed < 0) {
    throw py::value_error("seed = " + std::to_string(seed) + " is not allowed: it must be >= 0");
  }
  std::vector<engine::Scene> scenes;
  long long drawn = count;
  std::size_t examined = 0;
  while (static_cast<long long>(scenes.size()) < count) {
    // The generator's first shots are the same whatever it is asked for: draw more, go on from
    // the first not yet examined.
    const std::vector<engine::Scene> shots =
        engine::randomSingleShots(static_cast<int>(drawn), static_cast<std::uint64_t>(seed));
    for (std::size_t i = examined; i < shots.size() && static_cast<long long>(scenes.size()) < count;
         examined = ++i) {
      try {
        scenes.push_back(engine::sceneFromJson(documentOf(shots[i]), "random shot " + std::to_string(i)));
      } catch (const std::invalid_argument&) {
        continue;  // a ball in a pocket: not a scene
      }
    }
    drawn += drawn / 8 + 16;
  }
  return scenes;
}

py::array_t<double> positionsOf(const engine::Scene& scene) {
  py::array_t<double> positions({static_cast<py::ssize_t>(scene.balls.size()), py::ssize_t{2}});
  auto view = positions.mutable_unchecked<2>();
  for (std::size_t i = 0; i < scene.balls.size(); ++i) {
    view(i, 0) = scene.balls[i].position_m.x();
    view(i, 1) = scene.balls[i].position_m.y();
  }
  return positions;
}

}  // namespace

std::shared_ptr<const engine::Scene> sceneArgument(py::handle argument, const std::string& name) {
  // A baize.Scene itself (not a subclass) holding its scene is read straight from pybind11's record
  // of the class, looked up once: the general cast below looks it up by the type's name each time.
  static const py::detail::type_info* const bound = py::detail::get_type_info(typeid(engine::Scene));
  if (Py_TYPE(argument.ptr()) == bound->type) {
    const py::detail::value_and_holder held =
        reinterpret_cast<py::detail::instance*>(argument.ptr())->get_value_and_holder(bound);
    if (held.holder_constructed()) return held.holder<std::shared_ptr<engine::Scene>>();
  }
  py::detail::make_caster<std::shared_ptr<engine::Scene>> scene;
  bool loaded = false;
  try {
    loaded = scene.load(argument, /*convert=*/false);
  } catch (const py::cast_error&) {
    // A Scene object whose __init__ never ran (Scene.__new__(Scene)): it holds no scene.
  }
  if (!loaded) {
    throw py::type_error(name + " is of type " + std::string(Py_TYPE(argument.ptr())->tp_name) +
                         (py::isinstance<engine::Scene>(argument) ? " holding no scene" : "") +
                         ", not a baize.Scene made by baize.Scene(...), load_scene or random_shots");
  }
  return py::detail::cast_op<std::shared_ptr<engine::Scene>>(scene);
}

void bindScene(py::module_& module) {
  // Held by shared_ptr: a Result keeps its scene for what it derives on first use (shot_run.h).
  py::class_<engine::Scene, std::shared_ptr<engine::Scene>>(module, "Scene",
                            "A table, a ball set, the balls and the cue's shot (docs/scenes.md).")
      .def(py::init(&sceneFromValues), py::arg("table"), py::arg("ball_set"), py::arg("shot"),
           py::arg("balls") = py::none(), py::arg("rack") = py::none(),
           py::arg("physics") = py::none(),
           "Builds a scene from plain values, the keys of a scene file: table and ball_set (a "
           "built-in name, a file path or a dict), shot (dict: speed_mps, aim_at or heading_deg, "
           "side, height, elevation_deg, cue_ball), balls ({id: (x, y)} in metres) and/or rack "
           "({'name': '9-ball'}), physics (dict of overrides). Bad values raise ValueError "
           "naming the key and the value, as a scene file's would; values of a type JSON has no "
           "place for raise TypeError.")
      .def_property_readonly(
          "ball_ids",
          [](const engine::Scene& s) {
            std::vector<std::string> ids;
            for (const engine::PlacedBall& b : s.balls) ids.push_back(b.id);
            return ids;
          },
          "the balls' ids, in the order of positions and of a Result's arrays")
      .def_property_readonly("positions", &positionsOf,
                             "the balls' starting positions, numpy array n x 2, metres")
      .def_property_readonly(
          "table", [](const engine::Scene& s) { return s.table.name; }, "the table's name")
      .def_property_readonly(
          "cue_ball", [](const engine::Scene& s) { return s.cue_ball; }, "the ball struck")
      .def(
          "to_json", [](const engine::Scene& s) { return s.document.dump(); },
          "The scene as a scene file's JSON text (self-contained).")
      .def(py::pickle([](const engine::Scene& s) { return py::make_tuple(s.source, s.document.dump()); },
                      [](const py::tuple& state) {
                        return engine::sceneFromJson(
                            nlohmann::json::parse(state[1].cast<std::string>()),
                            state[0].cast<std::string>());
                      }))
      .def("__repr__", [](const engine::Scene& s) {
        return "<baize.Scene " + s.source + ": " + std::to_string(s.balls.size()) + " balls on " +
               s.table.name + ">";
      });

  module.def("load_scene", &engine::loadScene, py::arg("path"),
             "Reads a scene file (docs/scenes.md). ValueError names the file, key and value.");
  module.def("random_shots", &randomShots, py::arg("count"),
             py::arg("seed") = static_cast<long long>(engine::kRandomSingleShotsSeed),
             "count seeded random single shots on the 9 ft table (the cue ball and the 1 ball "
             "anywhere, any direction, 0.5-4 m/s, any tip offset up to 0.45 R): the shots of "
             "'baize bench shots' for the default seed, with the heading read back from degrees, "
             "less any the scene reader refuses (a ball drawn inside a pocket's capture circle). "
             "The first count shots are the same whatever count is.");
}

}  // namespace baize::python
