// The checks a shot's input must pass before the event loop runs, and the runtime guard against
// a ball leaving the table.
#pragma once

#include <string>
#include <vector>

#include "engine/sim/shot_events.h"
#include "engine/sim/simulation_params.h"
#include "engine/sim/table_geometry.h"

namespace baize::engine {

// The checks simulate() makes of its input, for other simulators of the same scenes: consistent
// parameters (ball radius and mass agree across the models), a well-formed table, finite states,
// no overlapping balls, no ball beyond a cushion or inside a jaw. Throws std::invalid_argument
// naming the ball and the value. `ball_ids`, when given (one per ball), names the balls in
// messages ("ball 'cue'"); otherwise they are named by number ("ball 0").
void validateSimulationInput(const SimulationParams& params, const TableGeometry& table,
                             const std::vector<physics::BallState>& balls,
                             const std::vector<std::string>& ball_ids = {});

// The runtime guard: throws BallLeftTableError naming the ball (as above), the event and where
// the ball's centre is, unless it is pocketed or inside the table's cushion outline.
void requireOnTable(const TableGeometry& table, const Event& event, int ball, bool pocketed,
                    const physics::BallState& state, const std::vector<std::string>& ids);

}  // namespace baize::engine
