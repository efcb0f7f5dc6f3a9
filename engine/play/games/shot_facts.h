// A simulated shot's facts for the referee (game_state.h, ShotFacts): read from the events of the
// run, no physics of its own.
#pragma once

#include <string>
#include <vector>

#include "engine/play/games/game_state.h"
#include "engine/sim/shot_events.h"

namespace baize::engine {

// The facts of a run whose ball i is ball_ids[i]. Throws std::invalid_argument when the cue ball is
// not among them or the result does not hold one record per ball.
ShotFacts shotFacts(const std::vector<std::string>& ball_ids, const SimulationResult& result,
                    const std::string& cue_ball);

}  // namespace baize::engine
