#include "physics/cushion_tabulated_solver.h"

#include "physics/cushion_rolling_surface.h"

namespace baize::physics {

CushionImpactResult solveCushionImpactTabulated(const CushionParams& params,
                                                const BallVelocity& incoming,
                                                const ExactSolverOptions& options) {
  validateExactSolverOptions(options);
  if (!impactScalesWithSpeed(params)) return solveCushionImpactExact(params, incoming, options);
  if (std::optional<BallVelocity> answered = rollingSurfaceFor(params).answer(incoming)) {
    CushionImpactResult result;
    result.after = *answered;
    return result;
  }
  return solveCushionImpactExact(params, incoming, options);
}

}  // namespace baize::physics
