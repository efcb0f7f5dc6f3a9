// Cushion model "paper": Mathavan 2010 integrated by the paper's own Euler scheme in N increments
// (physics/cushion_paper_solver.h).
#pragma once

#include "engine/models/cushion_mathavan2010.h"
#include "engine/models/model_registry.h"

namespace baize::engine {

class PaperCushionModel final : public CushionContactModel {
 public:
  PaperCushionModel(const Mathavan2010Cushion& model, int steps) : model_(model), steps_(steps) {}

  const char* name() const override { return "paper"; }
  // Also refuses a step count below 1.
  void validate(const SimulationParams& shot) const override;
  // Throws std::runtime_error when the scheme hands back more energy than the ball brought (its
  // first-order error with too few increments).
  physics::BallVelocity resolve(const SimulationParams& shot,
                                const physics::BallVelocity& incoming) const override;
  bool worthSolvingAhead() const override { return true; }
  RigidCushionContact rigidContact(const SimulationParams& shot) const override;
  nlohmann::json parametersJson() const override;

 private:
  Mathavan2010Cushion model_;
  int steps_;  // N, as in the paper
};

// The registration: keys restitution, friction, contact_height_m, paper_steps (N, default the
// paper's 5000).
ModelEntry<CushionContactModel> paperCushionModel();

}  // namespace baize::engine
