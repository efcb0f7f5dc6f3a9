#include "engine/cushion_contact.h"

#include <stdexcept>
#include <string>

#include "engine/shot_simulator.h"
#include "physics/cushion_exact_solver.h"
#include "physics/cushion_paper_solver.h"
#include "physics/cushion_simple_model.h"
#include "physics/value_text.h"

namespace baize::engine {

const char* cushionModelName(CushionModelChoice choice) {
  switch (choice) {
    case CushionModelChoice::SeedExact:
      return "exact";
    case CushionModelChoice::SeedPaper:
      return "paper";
    case CushionModelChoice::SimpleRestitution:
      return "simple";
  }
  return "unknown";
}

void validateCushionContactParams(const SimulationParams& params) {
  switch (params.cushion_model) {
    case CushionModelChoice::SeedExact:
      return;
    case CushionModelChoice::SeedPaper:
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
      " is not allowed: it must be SeedExact, SeedPaper or SimpleRestitution");
}

physics::BallVelocity resolveCushionContact(const SimulationParams& params,
                                            const physics::BallVelocity& incoming) {
  switch (params.cushion_model) {
    case CushionModelChoice::SeedExact:
      return physics::solveCushionImpactExact(params.cushion, incoming, params.cushion_solver)
          .after;
    case CushionModelChoice::SeedPaper: {
      physics::PaperSolverOptions options;
      options.steps = params.cushion_paper_steps;
      return physics::solveCushionImpactPaper(params.cushion, incoming, options).after;
    }
    case CushionModelChoice::SimpleRestitution:
      return physics::simpleCushionRebound(params.cushion_simple, incoming);
  }
  validateCushionContactParams(params);  // an unknown choice: throws saying so
  return incoming;
}

}  // namespace baize::engine
