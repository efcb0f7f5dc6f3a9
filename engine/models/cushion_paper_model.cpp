#include "engine/models/cushion_paper_model.h"

#include <stdexcept>
#include <string>

#include "physics/cushion_paper_solver.h"
#include "physics/value_text.h"

namespace baize::engine {
namespace {

// N as the paper ran it.
constexpr int kPaperSteps = 5000;

}  // namespace

void PaperCushionModel::validate(const SimulationParams& shot) const {
  physics::validateCushionParams(impactParams(model_, shot));
  if (steps_ < 1) physics::rejectValue("paper solver steps", steps_, "it must be >= 1");
}

physics::BallVelocity PaperCushionModel::resolve(const SimulationParams& shot,
                                                 const physics::BallVelocity& incoming) const {
  const physics::CushionParams params = impactParams(model_, shot);
  physics::PaperSolverOptions options;
  options.steps = steps_;
  const physics::BallVelocity after =
      physics::solveCushionImpactPaper(params, incoming, options).after;
  // The paper's Euler scheme is first order: with too few increments it can hand back more
  // energy than the ball brought, and the shot would go on from a state no impact makes.
  const double before_J = physics::kineticEnergy(params, incoming);
  const double after_J = physics::kineticEnergy(params, after);
  if (after_J > before_J * (1 + physics::kPaperEnergyGrowthAllowed)) {
    throw std::runtime_error(
        "physics.cushion.paper_steps = " + std::to_string(steps_) +
        ": the paper scheme made a cushion impact gain energy (" + physics::valueText(before_J) +
        " J in, " + physics::valueText(after_J) +
        " J out): the scheme's first-order error, which more increments usually shrink; the "
        "exact model (physics.cushion.model \"exact\") does not have it");
  }
  return after;
}

RigidCushionContact PaperCushionModel::rigidContact(const SimulationParams& shot) const {
  return {model_.cushion_friction, physics::contactSinTheta(impactParams(model_, shot))};
}

nlohmann::json PaperCushionModel::parametersJson() const {
  nlohmann::json out = {{"model", name()}};
  writeMathavan2010(model_, &out);
  out["paper_steps"] = steps_;
  return out;
}

ModelEntry<CushionContactModel> paperCushionModel() {
  std::vector<std::string> keys = mathavan2010Keys();
  keys.push_back("paper_steps");
  return {"paper", keys, [](const ModelDefaults& defaults, const JsonReader* parameters) {
            int steps = kPaperSteps;
            if (parameters && parameters->has("paper_steps"))
              steps = parameters->integer("paper_steps", 1, physics::kMaxPaperSteps);
            return std::make_shared<const PaperCushionModel>(readMathavan2010(defaults, parameters),
                                                             steps);
          }};
}

}  // namespace baize::engine
