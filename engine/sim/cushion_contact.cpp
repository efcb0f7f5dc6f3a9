#include "engine/sim/cushion_contact.h"

#include <stdexcept>
#include <string>

#include "engine/sim/shot_simulator.h"
#include "physics/cushion_exact_solver.h"
#include "physics/cushion_paper_solver.h"
#include "physics/cushion_simple_model.h"
#include "physics/value_text.h"

namespace baize::engine {
namespace {

// The energy a paper-scheme impact may gain, relative: rounding only. More means its increments
// are too coarse for the impact (the scheme is first order).
constexpr double kPaperEnergyGrowthAllowed = 1e-12;

}  // namespace

const char* cushionModelName(CushionModelChoice choice) {
  switch (choice) {
    case CushionModelChoice::Mathavan2010Exact:
      return "exact";
    case CushionModelChoice::Mathavan2010Paper:
      return "paper";
    case CushionModelChoice::SimpleRestitution:
      return "simple";
  }
  return "unknown";
}

void validateCushionContactParams(const SimulationParams& params) {
  switch (params.cushion_model) {
    case CushionModelChoice::Mathavan2010Exact:
      return;
    case CushionModelChoice::Mathavan2010Paper:
      if (params.cushion_paper_steps < 1) {
        physics::rejectValue("paper solver steps", params.cushion_paper_steps, "it must be >= 1");
      }
      return;
    case CushionModelChoice::SimpleRestitution:
      physics::validateSimpleCushionParams(params.cushion_simple);
      return;
  }
  throw std::invalid_argument(
      "cushion model = " + std::to_string(static_cast<int>(params.cushion_model)) +
      " is not allowed: it must be Mathavan2010Exact, Mathavan2010Paper or SimpleRestitution");
}

physics::BallVelocity resolveCushionContact(const SimulationParams& params,
                                            const physics::BallVelocity& incoming) {
  switch (params.cushion_model) {
    case CushionModelChoice::Mathavan2010Exact:
      return physics::solveCushionImpactExact(params.cushion, incoming, params.cushion_solver)
          .after;
    case CushionModelChoice::Mathavan2010Paper: {
      physics::PaperSolverOptions options;
      options.steps = params.cushion_paper_steps;
      const physics::BallVelocity after =
          physics::solveCushionImpactPaper(params.cushion, incoming, options).after;
      // The paper's Euler scheme is first order: with too few increments it can hand back more
      // energy than the ball brought, and the shot would go on from a state no impact makes.
      const double before_J = physics::kineticEnergy(params.cushion, incoming);
      const double after_J = physics::kineticEnergy(params.cushion, after);
      if (after_J > before_J * (1 + kPaperEnergyGrowthAllowed)) {
        throw std::runtime_error(
            "physics.cushion.paper_steps = " + std::to_string(params.cushion_paper_steps) +
            ": the paper scheme made a cushion impact gain energy (" +
            physics::valueText(before_J) + " J in, " + physics::valueText(after_J) +
            " J out): the scheme's first-order error, which more increments usually shrink; the "
            "exact model (physics.cushion.model \"exact\") does not have it");
      }
      return after;
    }
    case CushionModelChoice::SimpleRestitution:
      return physics::simpleCushionRebound(params.cushion_simple, incoming);
  }
  validateCushionContactParams(params);  // an unknown choice: throws saying so
  return incoming;
}

}  // namespace baize::engine
