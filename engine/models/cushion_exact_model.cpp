#include "engine/models/cushion_exact_model.h"

namespace baize::engine {

void ExactCushionModel::validate(const SimulationParams& shot) const {
  physics::validateCushionParams(impactParams(model_, shot));
  physics::validateExactSolverOptions(solver_);
}

physics::BallVelocity ExactCushionModel::resolve(const SimulationParams& shot,
                                                 const physics::BallVelocity& incoming) const {
  return physics::solveCushionImpactExact(impactParams(model_, shot), incoming, solver_).after;
}

RigidCushionContact ExactCushionModel::rigidContact(const SimulationParams& shot) const {
  return {model_.cushion_friction, physics::contactSinTheta(impactParams(model_, shot))};
}

nlohmann::json ExactCushionModel::parametersJson() const {
  nlohmann::json out = {{"model", name()}};
  writeMathavan2010(model_, &out);
  out["tolerance"] = solver_.tolerance;
  return out;
}

const std::vector<std::string>& exactSolverKeys() {
  static const std::vector<std::string> keys = [] {
    std::vector<std::string> k = mathavan2010Keys();
    k.push_back("tolerance");
    return k;
  }();
  return keys;
}

physics::ExactSolverOptions readExactSolverOptions(const JsonReader* parameters,
                                                   physics::ExactSolverOptions defaults) {
  physics::ExactSolverOptions solver = defaults;
  if (parameters && parameters->has("tolerance"))
    solver.tolerance = parameters->finiteNumber("tolerance");
  return solver;
}

ModelEntry<CushionContactModel> exactCushionModel() {
  return {"exact", exactSolverKeys(), [](const ModelDefaults& defaults, const JsonReader* parameters) {
            return std::make_shared<const ExactCushionModel>(readMathavan2010(defaults, parameters),
                                                             readExactSolverOptions(parameters));
          }};
}

}  // namespace baize::engine
