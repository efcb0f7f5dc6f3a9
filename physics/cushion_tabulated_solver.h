// The default way to resolve a cushion impact of the Mathavan 2010 model: a rolling ball's impact
// from its parameter set's table of exact solutions (cushion_rolling_surface.h), within 1e-8 V0 of
// the exact solver, and every other impact from the exact solver (cushion_exact_solver.h) at a
// tolerance that keeps the same promise. With a speed-dependent restitution (impactScalesWithSpeed
// false) the table cannot answer, since it holds outcomes per unit speed: every impact goes to the
// exact solver.
#pragma once

#include "physics/cushion_exact_solver.h"

namespace baize::physics {

// The exact solver's tolerance for the impacts the table does not answer, looser than the exact
// solver's own default (3e-11): it spends the path's promise of 1e-8 V0 instead of the exact
// solver's 1e-9 V0. On the 21,877 impacts of 30,000 random single shots that the table leaves to
// the exact solver it takes 20 % fewer rate evaluations than 3e-11 (351.6 against 441.5 per
// impact), with the largest error 4.4e-9 V0 (99.9th percentile 2.4e-9 V0) where 3e-11 gave
// 4.0e-10 V0; 1e-9 left 26 of 2,209 impacts of 3,000 shots above 5e-9 V0 and one above the
// promise. (Those figures are per unit step, the exact solver's own error share; see below.)
constexpr double kTabulatedFallbackTolerance = 3e-10;

// The exact solver's smallest error share for those impacts: 1, an error per step. It keeps the
// path's promise with fewer evaluations than the exact solver's 0.2, which its own tighter promise
// needs: over the 103,206 impacts of 40,000 random single shots, the 29,172 the table leaves take
// 325.9 rate evaluations each against 351.1 at 0.2, with the same largest error (4.36e-9 V0;
// 99.9th percentile 2.06e-9 against 1.95e-9), and the drawn, spinning and grippy sets stay within
// 5e-9 V0 (4.91e-9 on the drawn pool set).
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
