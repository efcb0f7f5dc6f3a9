// Cushion model "simple": v_y' = -e v_y, the rest kept (physics/cushion_simple_model.h).
#pragma once

#include "engine/models/model_registry.h"
#include "physics/cushion_simple_model.h"

namespace baize::engine {

class SimpleCushionModel final : public CushionContactModel {
 public:
  explicit SimpleCushionModel(const physics::SimpleCushionParams& params) : params_(params) {}

  const char* name() const override { return "simple"; }
  void validate(const SimulationParams& shot) const override;
  physics::BallVelocity resolve(const SimulationParams& shot,
                                const physics::BallVelocity& incoming) const override;
  // Closed form: cheaper than handing an impact over.
  bool worthSolvingAhead() const override { return false; }
  // No friction, the contact at the centre's height.
  RigidCushionContact rigidContact(const SimulationParams& shot) const override;
  nlohmann::json parametersJson() const override;

 private:
  physics::SimpleCushionParams params_;
};

// The registration: key simple_restitution (e).
ModelEntry<CushionContactModel> simpleCushionModel();

}  // namespace baize::engine
