// The rules of snooker (WPBSA Official Rules of Snooker, section 3 "The Game", with the definitions
// of section 2): the ball on, scoring, fouls and their penalties, colours re-spotted, the end of
// the frame and the re-spotted black (docs/games.md).
#pragma once

#include <string>
#include <vector>

#include "engine/io/table.h"
#include "engine/play/games/game_state.h"

namespace baize::engine {

// The balls the striker may hit first: every red when "red" is on, every colour after a red
// ("colour", the one nominated), or the one colour on in the final sequence.
std::vector<std::string> snookerTargets(const GameState& state);

// The ball on at the start of a turn: "red" while reds remain, else the lowest colour ("" none).
std::string ballOnAtTurnStart(const GameState& state);

// The next state and the decision after a snooker shot. `call.ball` is the colour nominated after
// a red; without one, the first colour hit counts as nominated.
Ruling ruleSnookerShot(const GameState& state, const ShotFacts& facts, const ShotCall& call,
                       const Table& table, double ball_radius_m);

}  // namespace baize::engine
