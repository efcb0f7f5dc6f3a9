// Ball-ball model "frictional": Alciatore's frictional inelastic impact, one algebraic step, with
// his fitted friction law or a constant (physics/ball_ball_impact.h, FrictionalInelastic).
#pragma once

#include "engine/models/model_registry.h"
#include "physics/ball_ball_impact.h"

namespace baize::engine {

class FrictionalBallBallModel final : public BallBallContactModel {
 public:
  // Only `params`' restitution and friction law with its coefficients count; the ball and cloth
  // come from the shot.
  explicit FrictionalBallBallModel(const physics::BallBallParams& params);

  const char* name() const override { return "frictional"; }
  void validate(const SimulationParams& shot) const override;
  physics::BallBallImpactResult resolve(const SimulationParams& shot,
                                        const physics::BallVelocity& first,
                                        const physics::BallVelocity& second,
                                        const Eigen::Vector3d& normal) const override;
  RigidBallContact rigidContact(const SimulationParams& shot, double slip_speed_mps) const override;
  nlohmann::json parametersJson() const override;

 private:
  physics::BallBallParams params_;
};

// The registration: keys restitution, friction_law ("alciatore" or "constant"), friction_fit_a,
// friction_fit_b, friction_fit_c_s_per_m (with "alciatore"), constant_friction (with "constant").
ModelEntry<BallBallContactModel> frictionalBallBallModel();

}  // namespace baize::engine
