// The physics parameters of one ball-ball impact: a model's own (restitution, friction law, ...)
// with the shot's ball and cloth filled in. Shared by the two ball-ball models.
#pragma once

#include "engine/sim/simulation_params.h"
#include "physics/ball_ball_impact.h"

namespace baize::engine {

// A few doubles copied on the stack per impact: nothing next to the impact's own arithmetic, and
// it keeps the ball's mass and radius in one place (SimulationParams::ball).
inline physics::BallBallParams impactParams(const physics::BallBallParams& model,
                                            const SimulationParams& shot) {
  physics::BallBallParams params = model;
  params.radius_m = shot.ball.radius_m;
  params.mass1_kg = params.mass2_kg = shot.ball.mass_kg;
  params.cloth_friction = shot.cloth.sliding_friction;  // one cloth
  return params;
}

}  // namespace baize::engine
