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

}  // namespace

ShotRun runShot(std::shared_ptr<const engine::Scene> scene) {
  ShotRun shot;
  shot.run = engine::runScene(*scene, /*record_trajectories=*/true);
  shot.scene = std::move(scene);
  return shot;
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
