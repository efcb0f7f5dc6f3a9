// Which cushion model resolves a ball's hit on a cushion or jaw, and the dispatch to it. Every
// cushion contact (straight segment or jaw arc) goes through resolveCushionContact in the frame of
// its contact normal (the local cushion frame of physics/cushion_model.h).
#pragma once

#include "physics/cushion_model.h"

namespace baize::engine {

struct SimulationParams;  // engine/sim/shot_simulator.h

enum class CushionModelChoice {
  Mathavan2010Exact,          // the Mathavan 2010 model, event-located solver (physics/cushion_exact_solver.h)
  Mathavan2010Paper,          // the Mathavan 2010 model, the paper's Euler scheme (physics/cushion_paper_solver.h)
  SimpleRestitution,  // v_y' = -e v_y, the rest kept (physics/cushion_simple_model.h)
};

// "exact", "paper", "simple": the names scene files use (docs/scenes.md).
const char* cushionModelName(CushionModelChoice choice);

// Throws std::invalid_argument naming the value unless the parameters of the chosen model are
// valid: Mathavan 2010's CushionParams for Mathavan2010Exact and Mathavan2010Paper (checked by simulate() in any case),
// the step count (>= 1) for Mathavan2010Paper, the restitution for SimpleRestitution, and a known choice.
void validateCushionContactParams(const SimulationParams& params);

// The ball's velocities just after the impact, local cushion frame, by the model params chooses.
// `incoming` must move into the cushion (v.y > 0).
physics::BallVelocity resolveCushionContact(const SimulationParams& params,
                                            const physics::BallVelocity& incoming);

}  // namespace baize::engine
