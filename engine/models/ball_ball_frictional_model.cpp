#include "engine/models/ball_ball_frictional_model.h"

#include <nlohmann/json.hpp>

#include "engine/models/ball_ball_impact_params.h"

namespace baize::engine {
namespace {

using physics::BallBallFrictionLaw;

// Refuses `key` when it is given but does not go with the friction law chosen.
void requireLaw(const JsonReader& parameters, const char* key, bool applies, const char* law) {
  if (parameters.has(key) && !applies) {
    parameters.reject(
        key,
        std::string("it applies only to model \"frictional\" with friction_law \"") + law + "\"");
  }
}

void readNumber(const JsonReader& parameters, const char* key, double* target) {
  if (parameters.has(key)) *target = parameters.finiteNumber(key);
}

std::shared_ptr<const BallBallContactModel> make(const ModelDefaults& defaults,
                                                 const JsonReader* parameters) {
  physics::BallBallParams params;
  params.model = physics::BallBallModel::FrictionalInelastic;
  params.restitution = defaults.ball_ball_restitution;
  if (parameters) {
    const JsonReader& in = *parameters;
    if (in.has("friction_law")) {
      const std::string law = in.text("friction_law");
      if (law == "alciatore") {
        params.friction_law = BallBallFrictionLaw::AlciatoreFit;
      } else if (law == "constant") {
        params.friction_law = BallBallFrictionLaw::Constant;
      } else {
        in.reject("friction_law", "it must be \"alciatore\" or \"constant\"");
      }
    }
    const bool fit = params.friction_law == BallBallFrictionLaw::AlciatoreFit;
    for (const char* key : {"friction_fit_a", "friction_fit_b", "friction_fit_c_s_per_m"})
      requireLaw(in, key, fit, "alciatore");
    requireLaw(in, "constant_friction", !fit, "constant");
    readNumber(in, "restitution", &params.restitution);
    readNumber(in, "friction_fit_a", &params.friction_fit_a);
    readNumber(in, "friction_fit_b", &params.friction_fit_b);
    readNumber(in, "friction_fit_c_s_per_m", &params.friction_fit_c_s_per_m);
    readNumber(in, "constant_friction", &params.constant_friction);
  }
  return std::make_shared<const FrictionalBallBallModel>(params);
}

}  // namespace

FrictionalBallBallModel::FrictionalBallBallModel(const physics::BallBallParams& params)
    : params_(params) {
  params_.model = physics::BallBallModel::FrictionalInelastic;
}

void FrictionalBallBallModel::validate(const SimulationParams& shot) const {
  physics::validateBallBallParams(impactParams(params_, shot));
}

physics::BallBallImpactResult FrictionalBallBallModel::resolve(
    const SimulationParams& shot, const physics::BallVelocity& first,
    const physics::BallVelocity& second, const Eigen::Vector3d& normal) const {
  return physics::resolveBallBallImpact(impactParams(params_, shot), first, second, normal);
}

RigidBallContact FrictionalBallBallModel::rigidContact(const SimulationParams&,
                                                       double slip_speed_mps) const {
  return {params_.restitution, physics::ballBallFriction(params_, slip_speed_mps)};
}

nlohmann::json FrictionalBallBallModel::parametersJson() const {
  nlohmann::json out = {{"model", name()}, {"restitution", params_.restitution}};
  if (params_.friction_law == BallBallFrictionLaw::AlciatoreFit) {
    out["friction_law"] = "alciatore";
    out["friction_fit_a"] = params_.friction_fit_a;
    out["friction_fit_b"] = params_.friction_fit_b;
    out["friction_fit_c_s_per_m"] = params_.friction_fit_c_s_per_m;
  } else {
    out["friction_law"] = "constant";
    out["constant_friction"] = params_.constant_friction;
  }
  return out;
}

ModelEntry<BallBallContactModel> frictionalBallBallModel() {
  return {"frictional",
          {"restitution", "friction_law", "friction_fit_a", "friction_fit_b",
           "friction_fit_c_s_per_m", "constant_friction"},
          make};
}

}  // namespace baize::engine
