// The default way to resolve a cushion impact of the Mathavan 2010 model: a rolling ball's impact
// from its parameter set's table of exact solutions (cushion_rolling_surface.h), within 1e-8 V0 of
// the exact solver, and every other impact from the exact solver (cushion_exact_solver.h). With a
// speed-dependent restitution (impactScalesWithSpeed false) the table cannot answer, since it
// holds outcomes per unit speed: every impact goes to the exact solver.
#pragma once

#include "physics/cushion_exact_solver.h"

namespace baize::physics {

// Where the table answers, the result holds `after` alone (no impulses, work, contact log or
// evaluations); otherwise it is the exact solver's, with `options`. Throws std::invalid_argument
// on invalid parameters, incoming state or options.
CushionImpactResult solveCushionImpactTabulated(const CushionParams& params,
                                                const BallVelocity& incoming,
                                                const ExactSolverOptions& options = {});

}  // namespace baize::physics
