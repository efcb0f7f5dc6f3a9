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

// The exact solver's tolerance for the impacts the table does not answer. Over the 103,206 impacts
// of 40,000 random single shots, the 29,172 the table leaves take 253.8 rate evaluations each and
// the path's largest error is 2.0e-7 V0 (99.9th percentile 6.8e-8 V0), a fifth of the promise. On
// 2,209 of those impacts, 3e-10 took 320.1 evaluations (largest 4.4e-9 V0, which kept 1e-8 V0),
// and 3e-8 took 231.9 but reached 6.6e-7 V0, too near the promise (all with the error share
// below).
constexpr double kTabulatedFallbackTolerance = 1e-8;

// The exact solver's smallest error share for those impacts: 1, an error per step. It keeps the
// path's promise with fewer evaluations than the exact solver's 0.2, which its own tighter promise
// needs: on the same 2,209 impacts at kTabulatedFallbackTolerance, 249.9 rate evaluations each
// against 256.2 at 0.5 and 264.1 at 0.2, with largest errors of 9.7e-8, 1.2e-7 and 8.0e-8 V0.
constexpr double kTabulatedFallbackErrorShare = 1;

// The options of the exact solver behind the table: its defaults, at kTabulatedFallbackTolerance
// and kTabulatedFallbackErrorShare.
inline ExactSolverOptions tabulatedFallbackOptions() {
  ExactSolverOptions options;
  options.tolerance = kTabulatedFallbackTolerance;
  options.min_error_share = kTabulatedFallbackErrorShare;
  return options;
}

// Where the table answers, the result holds `after` alone (no impulses, work, contact log or
// evaluations); otherwise it is the exact solver's, with `options`. Throws std::invalid_argument
// on invalid parameters, incoming state or options.
CushionImpactResult solveCushionImpactTabulated(
    const CushionParams& params, const BallVelocity& incoming,
    const ExactSolverOptions& options = tabulatedFallbackOptions());

}  // namespace baize::physics
