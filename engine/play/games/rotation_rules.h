// The rules of 9-ball and 10-ball (WPA World Standardized Rules, sections 2 and 9, with the
// standard fouls of section 6): the lowest-numbered ball first, the break, the push-out, the money
// ball re-spotted, three fouls in a row (docs/games.md).
#pragma once

#include "engine/io/table.h"
#include "engine/play/games/game_state.h"

namespace baize::engine {

// The lowest-numbered object ball on the table ("" when none).
std::string lowestBall(const GameState& state);

// The next state and the decision after a shot of 9-ball or 10-ball (state.game).
Ruling ruleRotationShot(const GameState& state, const ShotFacts& facts, const ShotCall& call,
                        const Table& table, double ball_radius_m);

}  // namespace baize::engine
