// The interface every ball-ball contact model implements: the event loop and the baselines resolve
// a collision of two balls through it. As for cushion models (engine/sim/cushion_contact_model.h),
// the models, their registry and their JSON reading live in engine/models/.
#pragma once

#include <Eigen/Core>
#include <nlohmann/json_fwd.hpp>

#include "physics/ball_ball_impact.h"

namespace baize::engine {

struct SimulationParams;  // engine/sim/simulation_params.h

// What a rigid-body engine can take of a ball-ball model (the Box2D baseline): a restitution and
// a friction coefficient.
struct RigidBallContact {
  double restitution = 0;
  double friction = 0;
};

// A constant object shared by every shot that chose it; the ball's mass and radius and the
// cloth's friction come from the shot (SimulationParams::ball, ::cloth).
class BallBallContactModel {
 public:
  virtual ~BallBallContactModel() = default;

  // As scene files spell it ("frictional", "mathavan2014").
  virtual const char* name() const = 0;

  // Throws std::invalid_argument naming the value unless the model's parameters, with the shot's
  // ball and cloth, are valid.
  virtual void validate(const SimulationParams& shot) const = 0;

  // Both balls just after the impact, world frame; `normal` is the unit vector from the first
  // ball's centre to the second's.
  virtual physics::BallBallImpactResult resolve(const SimulationParams& shot,
                                                const physics::BallVelocity& first,
                                                const physics::BallVelocity& second,
                                                const Eigen::Vector3d& normal) const = 0;

  // The model reduced to constants, its friction taken at `slip_speed_mps`.
  virtual RigidBallContact rigidContact(const SimulationParams& shot,
                                        double slip_speed_mps) const = 0;

  // The "physics.ball_ball" object a scene could give to choose this model with these parameters.
  virtual nlohmann::json parametersJson() const = 0;
};

}  // namespace baize::engine
