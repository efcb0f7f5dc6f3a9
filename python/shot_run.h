// One simulated shot as the Python package keeps it: the engine's run of a scene, and what is
// derived from it (the outcome, the cloth, the impacts beyond the cushion model's range) made on
// first use, so that baize.simulate costs what the engine's run costs (tools/bench_python.py).
#pragma once

#include <memory>
#include <optional>
#include <vector>

#include "engine/io/scene.h"
#include "engine/play/shot_outcome.h"
#include "physics/cloth_motion.h"

namespace baize::python {

struct ShotRun {
  // The scene that ran, shared with its Python Scene (scenes do not change once made); null for a
  // result unpickled, whose derived parts are all filled in.
  std::shared_ptr<const engine::Scene> scene;
  // The engine's run. Its trajectories (for sample(), pictures and pickling) are recorded only
  // when first asked for (recordedRunOf): most results are never sampled.
  engine::SceneRun run;
  bool trajectories_recorded = false;
  // Derived on first use. A result is read under the GIL, so one thread at a time fills them.
  std::optional<engine::ShotOutcome> outcome;
  std::optional<physics::ClothParams> cloth;  // the cloth the balls moved on, for sample()
  // Event indices of the impacts beyond the cushion model's range (engine/play/model_range.h).
  std::optional<std::vector<long>> beyond_model_range;
};

// Strikes and simulates the scene to rest, as `baize bench shots` times it (no trajectories).
// Needs no Python (callable with the GIL released); throws what engine::runScene throws.
ShotRun runShot(std::shared_ptr<const engine::Scene> scene);

// The run with the balls' trajectories. The first time, the shot runs again recording them: the
// engine gives the same input the same output bit for bit, so the recorded run is the first one
// (checked: the same events and final states; a difference throws std::logic_error).
const engine::SceneRun& recordedRunOf(ShotRun& shot);

// The derived parts, made from the scene and the run the first time they are asked for.
const engine::ShotOutcome& outcomeOf(ShotRun& shot);
const physics::ClothParams& clothOf(ShotRun& shot);
const std::vector<long>& beyondModelRangeOf(ShotRun& shot);

}  // namespace baize::python
