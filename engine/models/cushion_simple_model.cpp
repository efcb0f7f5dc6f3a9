#include "engine/models/cushion_simple_model.h"

namespace baize::engine {

void SimpleCushionModel::validate(const SimulationParams&) const {
  physics::validateSimpleCushionParams(params_);
}

physics::BallVelocity SimpleCushionModel::resolve(const SimulationParams&,
                                                  const physics::BallVelocity& incoming) const {
  return physics::simpleCushionRebound(params_, incoming);
}

RigidCushionContact SimpleCushionModel::rigidContact(const SimulationParams&) const { return {}; }

nlohmann::json SimpleCushionModel::parametersJson() const {
  return {{"model", name()}, {"simple_restitution", params_.restitution}};
}

ModelEntry<CushionContactModel> simpleCushionModel() {
  return {"simple", {"simple_restitution"}, [](const ModelDefaults&, const JsonReader* parameters) {
            physics::SimpleCushionParams params;
            if (parameters && parameters->has("simple_restitution"))
              params.restitution = parameters->finiteNumber("simple_restitution");
            return std::make_shared<const SimpleCushionModel>(params);
          }};
}

}  // namespace baize::engine
