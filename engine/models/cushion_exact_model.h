// Cushion model "exact": Mathavan 2010 solved by the event-located solver
// (physics/cushion_exact_solver.h).
#pragma once

#include "engine/models/cushion_mathavan2010.h"
#include "engine/models/model_registry.h"
#include "physics/cushion_exact_solver.h"

namespace baize::engine {

class ExactCushionModel : public CushionContactModel {
 public:
  ExactCushionModel(const Mathavan2010Cushion& model, const physics::ExactSolverOptions& solver)
      : model_(model), solver_(solver) {}

  const char* name() const override { return "exact"; }
  void validate(const SimulationParams& shot) const override;
  physics::BallVelocity resolve(const SimulationParams& shot,
                                const physics::BallVelocity& incoming) const override;
  bool worthSolvingAhead() const override { return true; }
  RigidCushionContact rigidContact(const SimulationParams& shot) const override;
  nlohmann::json parametersJson() const override;

 protected:
  const Mathavan2010Cushion& model() const { return model_; }
  const physics::ExactSolverOptions& solver() const { return solver_; }

 private:
  Mathavan2010Cushion model_;
  physics::ExactSolverOptions solver_;
};

// The registration: keys restitution, friction, contact_height_m, tolerance (the solver's).
ModelEntry<CushionContactModel> exactCushionModel();

// The keys of the models solved by the exact solver, and their reading into one of them (from
// `defaults` where a key is not given).
const std::vector<std::string>& exactSolverKeys();
physics::ExactSolverOptions readExactSolverOptions(const JsonReader* parameters,
                                                   physics::ExactSolverOptions defaults = {});

}  // namespace baize::engine
