// The constant parameters of a shot: the balls, the cloth, the cushion and ball-ball models, and
// the event budget.
#pragma once

#include <memory>

#include "engine/sim/ball_ball_contact_model.h"
#include "engine/sim/ball_properties.h"
#include "engine/sim/cushion_contact_model.h"
#include "physics/cloth_motion.h"

namespace baize::engine {

// Constants of a shot. The models are chosen by name from the registry in engine/models/
// (poolSimulationParams there gives the pool defaults); they are constant and shared, so copying
// SimulationParams copies two pointers, never a model.
struct SimulationParams {
  BallProperties ball;
  // The cloth. Its radius_m is the physics struct's copy of ball.radius_m (physics/ is pure and
  // takes it there); simulate() refuses the two differing.
  physics::ClothParams cloth = physics::poolCloth();
  std::shared_ptr<const CushionContactModel> cushion;     // every cushion and jaw hit
  std::shared_ptr<const BallBallContactModel> ball_ball;  // every ball-ball collision
  long max_events = 100000;          // a shot needing more stops with an error saying so
  bool record_trajectories = false;  // fill SimulationResult::trajectories (costs memory only)
};

}  // namespace baize::engine
