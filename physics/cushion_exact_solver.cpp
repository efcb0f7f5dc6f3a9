#include "physics/cushion_exact_solver.h"

#include <stdexcept>

namespace baize::physics {
// Placeholder while the solver is written (replaced before any merge).
CushionImpactResult solveCushionImpactExact(const CushionParams&, const BallVelocity&,
                                            const ExactSolverOptions&) {
  throw std::logic_error("exact solver not written yet");
}
}  // namespace baize::physics
