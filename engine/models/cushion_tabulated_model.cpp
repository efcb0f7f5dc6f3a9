#include "engine/models/cushion_tabulated_model.h"

#include "physics/cushion_tabulated_solver.h"

namespace baize::engine {

physics::BallVelocity TabulatedCushionModel::resolve(const SimulationParams& shot,
                                                     const physics::BallVelocity& incoming) const {
  return physics::solveCushionImpactTabulated(impactParams(model(), shot), incoming, solver())
      .after;
}

ModelEntry<CushionContactModel> tabulatedCushionModel() {
  return {"tabulated", exactSolverKeys(),
          [](const ModelDefaults& defaults, const JsonReader* parameters) {
            return std::make_shared<const TabulatedCushionModel>(
                readMathavan2010(defaults, parameters),
                readExactSolverOptions(parameters, physics::tabulatedFallbackOptions()));
          }};
}

}  // namespace baize::engine
