// Cushion model "tabulated", the default: the Mathavan 2010 model, with the impacts of rolling
// balls answered from the parameter set's table of exact solutions
// (physics/cushion_rolling_surface.h) and every other impact solved by the exact solver at
// physics::kTabulatedFallbackTolerance, per step (physics::tabulatedFallbackOptions), all within
// physics::kTabulatedPathPromise (1e-6 V0) of the converged solution.
#pragma once

#include "engine/models/cushion_exact_model.h"

namespace baize::engine {

class TabulatedCushionModel final : public ExactCushionModel {
 public:
  using ExactCushionModel::ExactCushionModel;

  const char* name() const override { return "tabulated"; }
  physics::BallVelocity resolve(const SimulationParams& shot,
                                const physics::BallVelocity& incoming) const override;
};

// The registration: the keys of "exact"; tolerance is the exact solver's, for the impacts the
// table does not answer (default physics::kTabulatedFallbackTolerance; the error share and the
// step control are always physics::kTabulatedFallbackErrorShare and
// physics::kTabulatedFallbackStepControl).
ModelEntry<CushionContactModel> tabulatedCushionModel();

}  // namespace baize::engine
