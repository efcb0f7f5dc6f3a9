// An accurate solver for the cushion impact of the Mathavan 2010 model. It integrates the impact
// with an adaptive Dormand-Prince 8(5,3) pair (dop853.h) and locates exactly (to the tolerance) the
// end of compression, the end of restitution and every instant at which a stuck contact starts to
// slide or is held again, so nothing chatters: a contact whose slip vanishes sticks while the
// friction needed to hold it lies inside its friction cone, and otherwise slides along the one
// direction in which its slip grows along itself. Near a vanishing slip, where the friction
// direction turns arbitrarily fast, the independent variable is rescaled so that the slip decays
// smoothly instead of being stepped across. See the top of cushion_exact_solver.cpp for the method
// and docs/cushion-solvers.md for its derivation.
#pragma once

#include "physics/cushion_model.h"

namespace baize::physics {

// The exact solver's promise: at its default tolerance (ExactSolverOptions), each outgoing velocity
// within this of the converged solution, in units of V0 (spins as R w).
constexpr double kExactPromise = 1e-9;

struct ExactSolverOptions {
  // Error allowed, relative to the velocity scale |v| + R |w| (and the matching impulse and work
  // scales), per share of the impact's impulse (error per unit step; see min_error_share).
  // Accepted: [1e-14, 1e-6]. The default keeps output velocities within kExactPromise of the
  // converged solution: over the 12000 seeded impacts of `baize bench cushion --impacts 8000` (wide
  // and rolling sets) the largest error is 1.9e-10 V0 on the paper's snooker cushion and 4.95e-10
  // V0 on the 9 ft pool table's (tests and the bench check it on smaller sets); over the 16,180
  // impacts of 5000 random single shots (`baize bench cushion --from-shots 5000`) it is 3.5e-10 V0.
  double tolerance = 3e-11;
  // The smallest share of the impact's impulse scale (M times the velocity scale) a step's error
  // allowance is cut to: a step covering a share s of it may add s times the tolerance, but no
  // less than this share of it, so that steps in the change of variable near a vanishing slip,
  // which advance P very little, are not held to an allowance near zero. Accepted: (0, 1]; 1 makes
  // the tolerance an error per step (for every step covering at most the impulse scale, which is
  // about all of them). 0.2 keeps the exact solver's promise of 1e-9 V0: floors of
  // 0.3 to 1 cost 3 to 10 % fewer evaluations but let rare impacts of the drawn rolling set exceed
  // it.
  double min_error_share = 0.2;
  // > 0: record result.trace with samples at least this dense in P (N s), plus every step and
  // event.
  double trace_spacing_Ns = 0;
};

// Throws std::invalid_argument naming the value unless the tolerance lies in [1e-14, 1e-6], the
// smallest error share in (0, 1] and the trace spacing is finite and >= 0.
void validateExactSolverOptions(const ExactSolverOptions& options);

// Throws std::invalid_argument on invalid parameters, incoming state or options.
CushionImpactResult solveCushionImpactExact(const CushionParams& params,
                                            const BallVelocity& incoming,
                                            const ExactSolverOptions& options = {});

}  // namespace baize::physics
