#include "python/shot_run.h"

#include <stdexcept>

#include "engine/play/model_range.h"

namespace baize::python {
namespace {

// A result without its scene has every derived part filled in when it is unpickled; reaching here
// without one is a fault of this file, not of the caller's input.
const engine::Scene& sceneOf(const ShotRun& shot) {
  if (!shot.scene) throw std::logic_error("a baize.Result without its scene lacks a derived part");
  return *shot.scene;
}

bool sameState(const physics::BallState& a, const physics::BallState& b) {
  return a.position == b.position && a.velocity == b.velocity &&
         a.angular_velocity == b.angular_velocity;
}

// Whether two runs of one scene agree on everything a result shows: the events' times and kinds,
// the final states and the end.
bool sameRun(const engine::SimulationResult& a, const engine::SimulationResult& b) {
  if (a.events.size() != b.events.size() || a.final_balls.size() != b.final_balls.size() ||
      a.end_time_s != b.end_time_s) {
    return false;
  }
  for (std::size_t i = 0; i < a.events.size(); ++i) {
    if (a.events[i].time_s != b.events[i].time_s || a.events[i].kind != b.events[i].kind)
      return false;
  }
  for (std::size_t i = 0; i < a.final_balls.size(); ++i) {
    if (!sameState(a.final_balls[i].state, b.final_balls[i].state) ||
        a.final_balls[i].pocketed != b.final_balls[i].pocketed) {
      return false;
    }
  }
  return true;
}

}  // namespace

ShotRun runShot(std::shared_ptr<const engine::Scene> scene) {
  ShotRun shot;
  shot.run = engine::runScene(*scene, /*record_trajectories=*/false);
  shot.scene = std::move(scene);
  return shot;
}

const engine::SceneRun& recordedRunOf(ShotRun& shot) {
  if (shot.trajectories_recorded) return shot.run;
  engine::SceneRun recorded = engine::runScene(sceneOf(shot), /*record_trajectories=*/true);
  if (!sameRun(recorded.result, shot.run.result))
    throw std::logic_error("the shot ran differently a second time: the engine is not deterministic");
  shot.run = std::move(recorded);
  shot.trajectories_recorded = true;
  return shot.run;
}

const engine::ShotOutcome& outcomeOf(ShotRun& shot) {
  if (!shot.outcome) shot.outcome = engine::shotOutcome(shot.run, sceneOf(shot).cue_ball);
  return *shot.outcome;
}

const physics::ClothParams& clothOf(ShotRun& shot) {
  if (!shot.cloth) shot.cloth = engine::simulationParamsFor(sceneOf(shot)).cloth;
  return *shot.cloth;
}

const std::vector<long>& beyondModelRangeOf(ShotRun& shot) {
  if (!shot.beyond_model_range)
    shot.beyond_model_range = engine::impactsBeyondModelRange(sceneOf(shot), shot.run);
  return *shot.beyond_model_range;
}

}  // namespace baize::python
