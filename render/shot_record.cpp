#include "render/shot_record.h"

#include <stdexcept>

#include "engine/io/json_reader.h"
#include "physics/value_text.h"

namespace baize::render {
namespace {

// The renderer samples positions from the trajectories: the events' states are not kept.
std::vector<engine::Event> withoutStates(std::vector<engine::Event> events) {
  for (engine::Event& e : events) {
    e.before.clear();
    e.after.clear();
  }
  return events;
}

// A result without trajectories is drawn from its scene simulated again; the run must be the
// result's shot, or the picture would show another one.
engine::SceneRun runAgain(const engine::ShotResult& result, const std::string& source) {
  engine::Scene scene = result.scene;
  scene.overrides =
      engine::readPhysicsOverrides(engine::JsonReader(result.physics, source, "physics"));
  const engine::SceneRun run = engine::runScene(scene, /*record_trajectories=*/true);
  bool same = run.result.end_time_s == result.end_time_s;
  for (std::size_t i = 0; same && i < result.final_positions_m.size(); ++i) {
    const engine::BallRecord& ball = run.result.final_balls.at(i);
    const auto& said = result.final_positions_m[i];
    same = ball.pocketed ? !said : said && *said == ball.state.position;
  }
  if (!same) {
    throw std::invalid_argument(
        source +
        ": the result holds no trajectories and its scene, simulated again, is not its "
        "shot (it ends at " +
        physics::valueText(run.result.end_time_s) + " s, not " +
        physics::valueText(result.end_time_s) +
        " s, or leaves a ball elsewhere): the result was written by other physics; write it "
        "again with its trajectories (baize simulate --json)");
  }
  return run;
}

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
  record.events = withoutStates(run.result.events);
  record.end_time_s = run.result.end_time_s;
  return record;
}

ShotRecord shotRecordOf(const engine::ShotResult& result, const std::string& source) {
  ShotRecord record;
  record.table = result.scene.table;
  record.ball_set = result.scene.ball_set;
  record.cloth = result.params.cloth;  // the cloth the shot ran with, as the result says
  record.ball_ids = result.ballIds();
  record.end_time_s = result.end_time_s;
  if (result.trajectories) {
    record.trajectories = *result.trajectories;
    if (result.events) record.events = withoutStates(*result.events);
    return record;
  }
  const engine::SceneRun run = runAgain(result, source);
  record.trajectories = run.result.trajectories;
  record.events = withoutStates(run.result.events);
  return record;
}

ShotRecord loadShotRecord(const std::string& path) {
  const nlohmann::json document = engine::JsonReader::parseFile(path);
  // A document that says it is a result, or one with a result's trajectories (written before the
  // format was versioned), is read as a result: the refusal then says what a result must hold.
  if (engine::isResultDocument(document) ||
      (document.is_object() && document.contains("trajectories"))) {
    return shotRecordOf(engine::resultFromJson(document, path), path);
  }
  const engine::Scene scene = engine::sceneFromJson(document, path);
  return shotRecordOf(scene, engine::runScene(scene, /*record_trajectories=*/true));
}

}  // namespace baize::render
