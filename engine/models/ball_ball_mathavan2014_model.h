// Ball-ball model "mathavan2014": Mathavan, Jackson & Parkin 2014, integrated in the normal
// impulse with friction at the ball-ball and cloth contacts (physics/ball_ball_impact.h).
#pragma once

#include "engine/models/model_registry.h"
#include "physics/ball_ball_impact.h"

namespace baize::engine {

class Mathavan2014BallBallModel final : public BallBallContactModel {
 public:
  // Only `params`' restitution, ball friction and tolerance count; the ball and cloth come from
  // the shot.
  explicit Mathavan2014BallBallModel(const physics::BallBallParams& params);

  const char* name() const override { return "mathavan2014"; }
  void validate(const SimulationParams& shot) const override;
  physics::BallBallImpactResult resolve(const SimulationParams& shot,
                                        const physics::BallVelocity& first,
                                        const physics::BallVelocity& second,
                                        const Eigen::Vector3d& normal) const override;
  // The ball-on-ball friction mu_b, whatever the slip.
  RigidBallContact rigidContact(const SimulationParams& shot, double slip_speed_mps) const override;
  nlohmann::json parametersJson() const override;

 private:
  physics::BallBallParams params_;
};

// The registration: keys restitution, ball_friction (mu_b), tolerance (the integration's).
ModelEntry<BallBallContactModel> mathavan2014BallBallModel();

}  // namespace baize::engine
