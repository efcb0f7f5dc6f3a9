#include "render/shot_record.h"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <iterator>
#include <stdexcept>

#include "engine/io/json_reader.h"
#include "physics/cloth_motion.h"
#include "physics/value_text.h"

namespace baize::render {
namespace {

// A ball's recorded position may lie this far beyond the table's bed and still be on the table
// (on a cushion's nose, in a pocket's mouth or capture circle), m; farther is not a result of it.
constexpr double kBeyondBed_m = 0.5;
// A result's end_time_s and the instant its pieces say the last ball stops or falls may differ by
// this much, s: the event loop adds the state changes' durations to the clock one by one and the
// check here sums them first, which rounds differently by ulps; a microsecond is far above that
// and far below a frame.
constexpr double kEndTimeSlack_s = 1e-6;
// The keys a result of `baize simulate --json` has.
const char* const kResultKeys[] = {
    "scene",       "scene_path", "table",   "end_time_s", "first_ball_hit", "pocketed",    "foul",
    "predictions", "samples",    "physics", "events",     "final",          "trajectories"};

[[noreturn]] void reject(const std::string& source, const std::string& key,
                         const std::string& what) {
  throw std::invalid_argument(source + ": " + key + ": " + what);
}

// A value as a message quotes it (engine::JsonReader::quoted: cut, bytes that are not UTF-8
// replaced).
std::string quoted(const nlohmann::json& value) { return engine::JsonReader::quoted(value); }

const nlohmann::json& member(const nlohmann::json& object, const char* key,
                             const std::string& source, const std::string& path) {
  if (!object.is_object() || !object.contains(key)) {
    reject(source, path + key, "missing (a result of 'baize simulate --json' has it)");
  }
  return object.at(key);
}

double number(const nlohmann::json& object, const char* key, const std::string& source,
              const std::string& path) {
  const nlohmann::json& value = member(object, key, source, path);
  if (!value.is_number() || !std::isfinite(value.get<double>())) {
    reject(source, path + key, "value " + quoted(value) + " is not allowed: it must be a number");
  }
  return value.get<double>();
}

template <int N>
Eigen::Matrix<double, N, 1> vector(const nlohmann::json& object, const char* key,
                                   const std::string& source, const std::string& path) {
  const nlohmann::json& value = member(object, key, source, path);
  Eigen::Matrix<double, N, 1> v;
  bool valid = value.is_array() && value.size() == N;
  for (int i = 0; valid && i < N; ++i) {
    valid = value[i].is_number() && std::isfinite(value[i].get<double>());
    if (valid) v[i] = value[i].get<double>();
  }
  if (!valid) {
    reject(source, path + key,
           "value " + quoted(value) + " is not allowed: it must be " + std::to_string(N) +
               " finite numbers");
  }
  return v;
}

engine::EventKind eventKindNamed(const std::string& name, const std::string& source,
                                 const std::string& path) {
  for (engine::EventKind kind :
       {engine::EventKind::StateChange, engine::EventKind::BallBall, engine::EventKind::Cushion,
        engine::EventKind::Jaw, engine::EventKind::Pocket}) {
    if (name == engine::eventKindName(kind)) return kind;
  }
  reject(source, path, "event type '" + name + "' is not one the event loop writes");
}

// The project's strict parse: a key given twice is refused as in scenes.
nlohmann::json readJson(const std::string& path) { return engine::JsonReader::parseFile(path); }

}  // namespace

ShotRecord shotRecordOf(const engine::Scene& scene, const engine::SceneRun& run) {
  if (run.result.trajectories.size() != run.ball_ids.size()) {
    throw std::invalid_argument(scene.source +
                                ": the run has no trajectories (run it with record_trajectories)");
  }
  ShotRecord record;
  record.table = scene.table;
  record.ball_set = scene.ball_set;
  record.cloth = engine::simulationParamsFor(scene).cloth;
  record.ball_ids = run.ball_ids;
  record.trajectories = run.result.trajectories;
  record.events = run.result.events;
  for (engine::Event& e : record.events) {
    e.before.clear();  // the renderer samples positions from the trajectories
    e.after.clear();
  }
  record.end_time_s = run.result.end_time_s;
  return record;
}

ShotRecord shotRecordFromResultJson(const nlohmann::json& result, const std::string& source) {
  std::string scene_path;
  if (result.is_object() && result.contains("scene_path") && result["scene_path"].is_string()) {
    scene_path = result["scene_path"].get<std::string>();
  } else {
    const nlohmann::json& scene = member(result, "scene", source, "");
    if (!scene.is_string()) reject(source, "scene", "value " + quoted(scene) + " is not a path");
    scene_path = scene.get<std::string>();
  }
  for (const auto& item : result.items()) {
    if (std::find(std::begin(kResultKeys), std::end(kResultKeys), item.key()) ==
        std::end(kResultKeys)) {
      reject(source, item.key(),
             "an unknown key is not allowed in a result of 'baize simulate --json'");
    }
  }
  const engine::Scene scene = [&] {
    try {
      return engine::loadScene(scene_path);
    } catch (const std::invalid_argument& e) {
      throw std::invalid_argument(source + ": the result's scene: " + e.what());
    }
  }();
  if (result.contains("table") &&
      !(result["table"].is_string() && result["table"].get<std::string>() == scene.table.name)) {
    reject(source, "table",
           "value " + quoted(result["table"]) + " is not allowed: the scene '" + scene_path +
               "' is on table '" + scene.table.name + "'");
  }
  ShotRecord record;
  record.table = scene.table;
  record.ball_set = scene.ball_set;
  // The cloth the shot ran with, which draws its paths: the result's own "physics" (the scene file
  // may have changed since), read and checked as a scene's.
  engine::SimulationParams params = engine::simulationParamsFor(scene);
  if (result.contains("physics")) {
    const engine::PhysicsOverrides ran =
        engine::readPhysicsOverrides(engine::JsonReader(result.at("physics"), source, "physics"));
    engine::applyPhysicsOverrides(ran, engine::modelDefaultsFor(scene), &params);
    physics::CueStrikeParams cue = engine::cueStrikeParamsFor(scene);
    engine::applyPhysicsOverrides(ran, &cue);
    engine::validateScenePhysics(params, cue, source,
                                 [] { return std::string("the physics the result was run with"); });
  }
  record.cloth = params.cloth;
  record.end_time_s = number(result, "end_time_s", source, "");
  if (record.end_time_s < 0) reject(source, "end_time_s", "it must be >= 0");

  const nlohmann::json& final_balls = member(result, "final", source, "");
  const nlohmann::json& trajectories = member(result, "trajectories", source, "");
  if (!final_balls.is_array() || final_balls.size() != scene.balls.size()) {
    reject(source, "final",
           "it must list the " + std::to_string(scene.balls.size()) + " balls of scene '" +
               scene_path + "'");
  }
  for (std::size_t i = 0; i < final_balls.size(); ++i) {
    const std::string path = "final[" + std::to_string(i) + "].";
    const nlohmann::json& id = member(final_balls[i], "id", source, path);
    if (!id.is_string() || !scene.ball_set.contains(id.get<std::string>())) {
      reject(source, path + "id", "value " + quoted(id) + " is not a ball of the scene's set");
    }
    record.ball_ids.push_back(id.get<std::string>());
    const std::string pieces_path = "trajectories." + id.get<std::string>();
    const nlohmann::json& pieces =
        member(trajectories, id.get_ref<const std::string&>().c_str(), source, "trajectories.");
    if (!pieces.is_array() || pieces.empty()) {
      reject(source, pieces_path, "it must be a non-empty list of pieces");
    }
    engine::Trajectory trajectory;
    for (std::size_t k = 0; k < pieces.size(); ++k) {
      const std::string p = pieces_path + "[" + std::to_string(k) + "].";
      engine::TrajectoryPiece piece;
      piece.start_time_s = number(pieces[k], "start_time_s", source, p);
      piece.state.position = vector<2>(pieces[k], "position_m", source, p);
      if (std::abs(piece.state.position.x()) > scene.table.length_m / 2 + kBeyondBed_m ||
          std::abs(piece.state.position.y()) > scene.table.width_m / 2 + kBeyondBed_m) {
        reject(source, p + "position_m",
               "value " + quoted(pieces[k]["position_m"]) +
                   " is not allowed: it is off the table (beyond its bed by more than 0.5 m)");
      }
      if (piece.start_time_s > record.end_time_s) {
        reject(source, p + "start_time_s", "it must not be after end_time_s");
      }
      piece.state.velocity = vector<3>(pieces[k], "velocity_mps", source, p);
      piece.state.angular_velocity = vector<3>(pieces[k], "angular_velocity_radps", source, p);
      const nlohmann::json& pocketed = member(pieces[k], "pocketed", source, p);
      if (!pocketed.is_boolean()) reject(source, p + "pocketed", "it must be true or false");
      piece.pocketed = pocketed.get<bool>();
      if (!trajectory.empty() && piece.start_time_s < trajectory.back().start_time_s) {
        reject(source, p + "start_time_s", "pieces must be in time order");
      }
      try {
        physics::validateBallState(piece.state);
      } catch (const std::invalid_argument& e) {
        reject(source, p, e.what());
      }
      trajectory.push_back(piece);
    }
    record.trajectories.push_back(trajectory);
  }
  if (!trajectories.is_object() || trajectories.size() != record.ball_ids.size()) {
    reject(source, "trajectories",
           "it must hold exactly the balls listed in \"final\" (a trajectory each)");
  }
  // The shot ends when its last ball stops or falls, which the last piece of each path fixes: an
  // end_time_s beyond it would have pictures and frames drawn long after everything stood still,
  // one before it would cut the shot short.
  double last_stop_s = 0;
  for (const engine::Trajectory& trajectory : record.trajectories) {
    const engine::TrajectoryPiece& last = trajectory.back();
    const double moving_s = last.pocketed ? 0 : physics::timeToRest(record.cloth, last.state);
    last_stop_s = std::max(last_stop_s, last.start_time_s + moving_s);
  }
  if (!(std::abs(record.end_time_s - last_stop_s) <= kEndTimeSlack_s)) {
    reject(source, "end_time_s",
           "value " + quoted(result["end_time_s"]) +
               " is not allowed: it must be when the last ball stops or falls, " +
               physics::valueText(last_stop_s) +
               " s after the strike by the last piece of each trajectory");
  }

  const auto index_of = [&](const nlohmann::json& id, const std::string& path) {
    for (std::size_t i = 0; i < record.ball_ids.size(); ++i) {
      if (id.is_string() && id.get<std::string>() == record.ball_ids[i]) return static_cast<int>(i);
    }
    reject(source, path, "value " + quoted(id) + " is not a ball of this result");
  };
  if (result.contains("events")) {
    const nlohmann::json& events = result["events"];
    if (!events.is_array()) reject(source, "events", "it must be a list");
    for (std::size_t k = 0; k < events.size(); ++k) {
      const std::string p = "events[" + std::to_string(k) + "].";
      engine::Event e;
      e.time_s = number(events[k], "time_s", source, p);
      const nlohmann::json& type = member(events[k], "type", source, p);
      if (!type.is_string()) reject(source, p + "type", "it must be a string");
      e.kind = eventKindNamed(type.get<std::string>(), source, p + "type");
      e.ball = index_of(member(events[k], "ball", source, p), p + "ball");
      if (events[k].contains("other")) e.other = index_of(events[k]["other"], p + "other");
      if (events[k].contains("index")) {
        e.index = static_cast<int>(number(events[k], "index", source, p));
      }
      record.events.push_back(e);
    }
  }
  return record;
}

ShotRecord loadShotRecord(const std::string& path) {
  const nlohmann::json document = readJson(path);
  if (document.is_object() && document.contains("trajectories")) {
    return shotRecordFromResultJson(document, path);
  }
  const engine::Scene scene = engine::sceneFromJson(document, path);
  return shotRecordOf(scene, engine::runScene(scene, /*record_trajectories=*/true));
}

}  // namespace baize::render
