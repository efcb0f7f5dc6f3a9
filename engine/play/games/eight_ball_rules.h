// The rules of 8-ball (WPA World Standardized Rules, section 3, with the standard fouls of section
// 6): the break, the open table and the groups, called shots, the 8 last (docs/games.md).
#pragma once

#include <string>
#include <vector>

#include "engine/io/table.h"
#include "engine/play/games/game_state.h"

namespace baize::engine {

// The group of an 8-ball object ball: 1-7 solids, 9-15 stripes, None for the 8 and the cue ball.
Group groupOf(const std::string& id);

// The balls `player` may hit first: on an open table every object ball but the 8, else the
// player's group on the table, and the 8 once that is empty.
std::vector<std::string> eightBallTargets(const GameState& state, int player);

Ruling ruleEightBallShot(const GameState& state, const ShotFacts& facts, const ShotCall& call,
                         const Table& table, double ball_radius_m);

}  // namespace baize::engine
