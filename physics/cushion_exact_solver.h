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

// The exact solver's step control (docs/cushion-solvers.md, "Error control and steps"). The
// defaults keep kExactPromise at the default tolerance and are the best measured there (a growth
// limit of 2 cost 2.5 % more rate evaluations on the impacts of play); the default path's
// fallback, whose error is counted per step and whose promise is looser, takes its own
// (tabulatedFallbackOptions).
struct ExactStepControl {
  // The next step is this safety factor times error^(-1/8) times the last, within [1/3,
  // max_growth]. Accepted: [0.5, 1].
  double safety = 0.9;
  // The most a step may grow over the last. Accepted: [1.5, 5].
  double max_growth = 3;
  // A step (in tau) may span at most this many time constants of the fastest-settling slip
  // direction. A small slip's direction settles where friction and the other forces balance at a
  // rate that grows as 1 / (|u| + s0), and steps of more than about two of its time constants run
  // toward the method's stability limit (about 6 on the real axis), where the embedded estimate
  // missed steps' true errors by 10 to 100 times: a nose slip of 2 s0 with a large cloth slip left
  // an impact 4.7e-9 V0 off, and grippy cushions (mu_s 0.35 to 0.425) missed 1e-9 V0 in 3 of 1000
  // impacts. Of the caps tried (1.5 to 5), 2.75 was the one with no impact above kExactPromise on
  // any set (docs/cushion-solvers.md, "Error control and steps"). Accepted: [0.5, 5].
  double slip_direction_time_constants = 2.75;
};

struct ExactSolverOptions {
  // Error allowed, relative to the velocity scale |v| + R |w| (and the matching impulse and work
  // scales), per share of the impact's impulse (error per unit step; see min_error_share).
  // Accepted: [1e-14, 1e-6]. The default keeps output velocities within kExactPromise of the
  // converged solution: over the 12000 seeded impacts of `baize bench cushion --impacts 8000` (wide
  // and rolling sets) the largest error is 1.9e-10 V0 on the paper's snooker cushion and 3.0e-10
  // V0 on the 9 ft pool table's (tests and the bench check it on smaller sets); over the 13,002
  // impacts of 5000 random single shots (`baize bench cushion --from-shots 5000`) it is 2.5e-10 V0.
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
  // How the steps are sized; the default path's fallback takes its own (tabulatedFallbackOptions).
  ExactStepControl step_control;
  // > 0: record result.trace with samples at least this dense in P (N s), plus every step and
  // event.
  double trace_spacing_Ns = 0;
};

// Throws std::invalid_argument naming the value unless the tolerance lies in [1e-14, 1e-6], the
// smallest error share in (0, 1], the step control within the ranges above and the trace spacing
// is finite and >= 0.
void validateExactSolverOptions(const ExactSolverOptions& options);

// Throws std::invalid_argument on invalid parameters, incoming state or options.
CushionImpactResult solveCushionImpactExact(const CushionParams& params,
                                            const BallVelocity& incoming,
                                            const ExactSolverOptions& options = {});

}  // namespace baize::physics
