#include "engine/models/ball_ball_mathavan2014_model.h"

#include <nlohmann/json.hpp>

#include "engine/models/ball_ball_impact_params.h"

namespace baize::engine {

Mathavan2014BallBallModel::Mathavan2014BallBallModel(const physics::BallBallParams& params)
    : params_(params) {
  params_.model = physics::BallBallModel::Mathavan2014;
}

void Mathavan2014BallBallModel::validate(const SimulationParams& shot) const {
  physics::validateBallBallParams(impactParams(params_, shot));
}

physics::BallBallImpactResult Mathavan2014BallBallModel::resolve(
    const SimulationParams& shot, const physics::BallVelocity& first,
    const physics::BallVelocity& second, const Eigen::Vector3d& normal) const {
  return physics::resolveBallBallImpact(impactParams(params_, shot), first, second, normal);
}

RigidBallContact Mathavan2014BallBallModel::rigidContact(const SimulationParams&, double) const {
  return {params_.restitution, params_.ball_friction};
}

nlohmann::json Mathavan2014BallBallModel::parametersJson() const {
  return {{"model", name()},
          {"restitution", params_.restitution},
          {"ball_friction", params_.ball_friction},
          {"tolerance", params_.tolerance}};
}

ModelEntry<BallBallContactModel> mathavan2014BallBallModel() {
  return {"mathavan2014",
          {"restitution", "ball_friction", "tolerance"},
          [](const ModelDefaults& defaults, const JsonReader* parameters) {
            physics::BallBallParams params;
            params.restitution = defaults.ball_ball_restitution;
            if (parameters) {
              for (auto [key, target] : {std::pair{"restitution", &params.restitution},
                                         std::pair{"ball_friction", &params.ball_friction},
                                         std::pair{"tolerance", &params.tolerance}}) {
                if (parameters->has(key)) *target = parameters->finiteNumber(key);
              }
            }
            return std::make_shared<const Mathavan2014BallBallModel>(params);
          }};
}

}  // namespace baize::engine
