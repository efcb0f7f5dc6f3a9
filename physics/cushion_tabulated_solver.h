// The default way to resolve a cushion impact of the Mathavan 2010 model: a rolling ball's impact
// from its parameter set's table of exact solutions (cushion_rolling_surface.h), within
// kRollingTablePromise of the exact solver, and every other impact from the exact solver
// (cushion_exact_solver.h) at a looser tolerance: the path promises kTabulatedPathPromise. With a
// speed-dependent restitution (impactScalesWithSpeed false) the table cannot answer, since it holds
// outcomes per unit speed: every impact goes to the exact solver.
#pragma once

#include "physics/cushion_exact_solver.h"

namespace baize::physics {

// The default path's promise: each outgoing velocity within this of the converged solution, in
// units of V0 (spins as R w), a micrometre per metre of travel. Looser than the exact solver's
// 1e-9 V0 because the time of a shot is mostly the impacts the table leaves to the exact solver:
// against the fallback tolerance that kept 1e-8 V0 (3e-10), this one takes 12 % fewer
// instructions per random single shot (132.6k to 116.3k) and per 9-ball break (1.211M to 1.064M;
// callgrind, the difference of 40 and 20 runs), and the full model's median shot falls under
// 1.8 times the simple rule's (`baize bench shots`).
constexpr double kTabulatedPathPromise = 1e-6;

// The exact solver's tolerance for the impacts the table does not answer. Over the 77,538 impacts
// of 30,000 random single shots, the 21,877 the table leaves take 227.4 rate evaluations each and
// the path's largest error is 2.1e-7 V0 (99.9th percentile 8.5e-8 V0), a fifth of the promise
// (against the exact solver at 1e-14, with the error share and step control below). 3e-10 took
// 302.3 evaluations (largest 5.9e-9 V0, which would keep 1e-8 V0), and 3e-8 took 211.0 but
// reached 1.7e-6 V0, beyond the promise.
constexpr double kTabulatedFallbackTolerance = 1e-8;

// The exact solver's smallest error share for those impacts: 1, an error per step. It keeps the
// path's promise with fewer evaluations than the exact solver's 0.2, which its own tighter promise
// needs: on the 2,209 of those impacts in the first 3000 shots, 223.4 rate evaluations each
// against 229.9 at 0.5 and 241.2 at 0.2, with largest errors of 9.4e-8, 1.0e-7 and 8.1e-8 V0.
constexpr double kTabulatedFallbackErrorShare = 1;

// The step control of those impacts: bolder than the exact solver's, whose constants keep its
// tighter promise. With an error per step the best safety factor is lower and the best growth
// limit smaller (the steps' errors add up, and a rejection costs a whole step), and the steps may
// span more of a slip direction's time constants (the estimate's misses there, 10 to 100 times a
// step's allowance, stay far below this path's promise). Rate evaluations per impact with the
// exact solver's control (0.9, 3, 2.75) and with this one, the largest errors the same (against
// the exact solver at 1e-14): 239.7 and 223.4 on the 2,209 impacts the table leaves of the
// benches' first 3000 random single shots, 241.8 and 221.0 on the 9-ball break's 5, 243.8 and
// 227.4 on the 21,877 of 30,000 shots (2.1e-7 V0 at most). A growth limit of 3 instead of 2 took
// 227.8, 225.4 and 231.3; a cap of 5 time constants took 224.3 on the 30,000 shots' impacts but
// reached 6.5e-7 V0, where the estimate failed; a safety factor of 0.7, 229.6.
constexpr ExactStepControl kTabulatedFallbackStepControl = {0.8, 2, 4};

// The options of the exact solver behind the table: its defaults, at kTabulatedFallbackTolerance,
// kTabulatedFallbackErrorShare and kTabulatedFallbackStepControl.
inline ExactSolverOptions tabulatedFallbackOptions() {
  ExactSolverOptions options;
  options.tolerance = kTabulatedFallbackTolerance;
  options.min_error_share = kTabulatedFallbackErrorShare;
  options.step_control = kTabulatedFallbackStepControl;
  return options;
}

// Where the table answers, the result holds `after` alone (no impulses, work, contact log or
// evaluations); otherwise it is the exact solver's, with `options`. Throws std::invalid_argument
// on invalid parameters, incoming state or options.
CushionImpactResult solveCushionImpactTabulated(
    const CushionParams& params, const BallVelocity& incoming,
    const ExactSolverOptions& options = tabulatedFallbackOptions());

}  // namespace baize::physics
