// The interface every cushion contact model implements: the event loop, the cushion impact worker
// and the baselines resolve a ball's hit on a cushion or jaw through it, in the frame of the
// contact normal (the local cushion frame of physics/cushion_model.h). The models themselves, their
// registry by name and the reading of their parameters from JSON live one layer up, in
// engine/models/ (which may use engine/io's JSON reader; this layer may not).
#pragma once

#include <nlohmann/json_fwd.hpp>

#include "physics/cushion_model.h"

namespace baize::engine {

struct SimulationParams;  // engine/sim/simulation_params.h

// What a rigid-body engine can take of a cushion model (the Box2D baseline's calibration): the
// sliding friction at the contact and sin(theta) of the contact point above the ball's centre.
struct RigidCushionContact {
  double friction = 0;
  double contact_sin_theta = 0;
};

// A constant object: its parameters are fixed when it is made, so one instance is shared by every
// shot, thread and copy of SimulationParams that chose it. The ball's mass and radius and the
// cloth's friction come from the shot (SimulationParams::ball, ::cloth), never from the model.
class CushionContactModel {
 public:
  virtual ~CushionContactModel() = default;

  // As scene files and the CLI spell it ("exact", "paper", "simple").
  virtual const char* name() const = 0;

  // Throws std::invalid_argument naming the value unless the model's parameters, with the shot's
  // ball and cloth, are valid.
  virtual void validate(const SimulationParams& shot) const = 0;

  // The ball's velocities just after the impact, local cushion frame. `incoming` must move into
  // the cushion (v.y > 0). May throw std::runtime_error when the model cannot give an answer.
  virtual physics::BallVelocity resolve(const SimulationParams& shot,
                                        const physics::BallVelocity& incoming) const = 0;

  // Whether an impact costs enough to hand it to the cushion impact worker ahead of time (false
  // for a closed-form rule: handing it over costs more than solving it).
  virtual bool worthSolvingAhead() const = 0;

  virtual RigidCushionContact rigidContact(const SimulationParams& shot) const = 0;

  // The model's parameters in the scene format's keys and units, "model" included: the
  // "physics.cushion" object a scene could give to choose this model with these parameters.
  virtual nlohmann::json parametersJson() const = 0;
};

}  // namespace baize::engine
