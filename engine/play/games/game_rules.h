// One entry to the rules of every game (docs/games.md): the starting state of a rack, the balls a
// player may hit first, where the cue ball may be placed from hand, and the ruling on a shot.
#pragma once

#include <Eigen/Core>
#include <string>
#include <vector>

#include "engine/io/ball_set.h"
#include "engine/io/table.h"
#include "engine/play/games/game_state.h"

namespace baize::engine {

// The rack of `game` placed on `table` (engine/io/rack.h) with the cue ball in hand for the break:
// behind the head string (pool) or in the D (snooker); player 0 breaks. Throws
// std::invalid_argument when the table is of the other kind or the set lacks the game's balls.
// `rack` may jitter the racked balls (engine/io/rack.h): no two racks are ever alike.
GameState initialGameState(Game game, const Table& table, const BallSet& balls,
                           const RackOptions& rack = {});

// The balls the player to play may hit first.
std::vector<std::string> legalTargets(const GameState& state);

// Why the cue ball may not be placed at `point_m` ("" when it may): not in hand, outside the area
// the rules allow (behind the head string, in the D: the line and the arc included), off the
// playing surface, or touching a ball.
std::string placementRefusal(const GameState& state, const Eigen::Vector2d& point_m,
                             const Table& table, double ball_radius_m);

// The ruling on a shot played from `state` with these facts.
Ruling ruleShot(const GameState& state, const ShotFacts& facts, const ShotCall& call,
                const Table& table, double ball_radius_m);

}  // namespace baize::engine
