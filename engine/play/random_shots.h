// The benches' seeded random single shots, and the cushion impacts they and scenes give the cushion
// model: `baize bench shots` times the shots, `baize bench cushion --from-shots` and `--from-scene`
// score the solvers on their impacts (the impacts play produces, besides the bench's drawn sets).
#pragma once

#include <cstdint>
#include <vector>

#include "engine/io/scene.h"
#include "physics/cushion_model.h"

namespace baize::engine {

// A scene on the 9 ft pool table with the pool ball set and "cue" as its cue ball, no balls placed:
// what the benches' random shots start from.
engine::Scene nineFootPoolScene();

// A seeded set of single shots on the 9 ft table: the cue ball and one object ball anywhere, the
// cue ball struck at 0.5-4 m/s in any direction with any tip offset (up to 0.45 R). The first
// `count` shots are the same whatever `count` is; another `seed` gives another set.
inline constexpr std::uint64_t kRandomSingleShotsSeed = 20261121;
std::vector<engine::Scene> randomSingleShots(int count,
                                             std::uint64_t seed = kRandomSingleShotsSeed);

// Every cushion and jaw impact of the shots, in order, as the cushion model met it: the incoming
// ball in the contact's local frame (contacts not moving into the cushion, which are no impact,
// left out). The shots run with their scenes' physics and must share one table and ball set;
// `params` is set to their cushion's. A shot that fails throws std::runtime_error naming it.
std::vector<physics::BallVelocity> cushionImpactsOf(const std::vector<engine::Scene>& shots,
                                                    physics::CushionParams* params);

// The same for one scene's shot (a break, say), with its own physics: `params` is set to its
// cushion's, its physics.cushion overrides included. Throws std::invalid_argument naming the model
// when the scene's cushion model is not one of the Mathavan 2010 model's solvers (exact,
// tabulated, paper), and what the simulation throws when the shot fails.
std::vector<physics::BallVelocity> cushionImpactsOfScene(const engine::Scene& scene,
                                                         physics::CushionParams* params);

}  // namespace baize::engine
