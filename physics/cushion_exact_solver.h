// An accurate solver for the seed paper's cushion impact. It integrates the impact in the normal
// impulse P with an adaptive embedded Runge-Kutta method and locates exactly (to the tolerance) the
// end of compression, the end of restitution and every instant at which a contact's slip vanishes or
// a stuck contact starts to slip again. Between those instants the equations are smooth, so nothing
// chatters: a contact whose slip reaches zero sticks while the friction needed to hold it lies inside
// its friction cone, and otherwise slips on in the direction the dynamics admit.
#pragma once

#include "physics/cushion_model.h"

namespace baize::physics {

struct ExactSolverOptions {
  // Local error allowed per step, relative to the incoming speed (velocities) and the matching
  // impulse and work scales. The default keeps output velocities within 1e-9 V0 of the converged
  // solution (checked by tests and by `baize bench cushion`).
  double tolerance = 1e-11;
  // > 0: record result.trace with samples at least this dense in P (N s), plus every step and event.
  double trace_spacing_Ns = 0;
};

// Throws std::invalid_argument on invalid parameters, incoming state or options.
CushionImpactResult solveCushionImpactExact(const CushionParams& params, const BallVelocity& incoming,
                                            const ExactSolverOptions& options = {});

}  // namespace baize::physics
