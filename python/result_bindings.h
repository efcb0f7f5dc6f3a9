// baize.Result: one simulated shot as Python sees it (its events, where the balls stopped, what it
// pocketed, its first ball hit and foul, and positions sampled from its exact trajectories).
#pragma once

#include <pybind11/pybind11.h>

#include <string>
#include <vector>

#include "engine/io/scene.h"
#include "engine/play/shot_outcome.h"
#include "physics/cloth_motion.h"

namespace baize::python {

struct ShotRun {
  engine::SceneRun run;  // with its trajectories, for sample()
  engine::ShotOutcome outcome;
  physics::ClothParams cloth;  // the cloth the balls moved on, for sample()
  // Event indices of the impacts beyond the cushion model's range (engine/play/model_range.h).
  std::vector<long> beyond_model_range;
};

// Strikes and simulates the scene to rest, recording trajectories. Needs no Python (callable with
// the GIL released); throws what engine::runScene throws.
ShotRun runShot(const engine::Scene& scene);

// Registers baize.Event and baize.Result.
void bindResult(pybind11::module_& module);

}  // namespace baize::python
