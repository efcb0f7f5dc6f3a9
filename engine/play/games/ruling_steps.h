// Steps every game's rules share: the table after the shot, the turn passing, a standard foul's
// penalty of the cue ball in hand, and the decision's rule citations.
#pragma once

#include <string>

#include "engine/play/games/game_state.h"

namespace baize::engine {

inline int opponentOf(int player) { return 1 - player; }

// The state after the shot before any ruling: the balls where the shot left them (a pocketed cue
// ball stays where it last stood, first in the list, to be placed again), one more shot, the break
// and the push-out over.
GameState tableAfterShot(const GameState& before, const ShotFacts& facts);

// Adds "; rule" to the decision's citations.
void cite(Decision* decision, const std::string& rule);

void passTurn(GameState* next, Decision* decision);

// Ends the frame with `winner`.
void endFrame(int winner, GameState* next, Decision* decision);

// Whether a shot of these facts drove at least `count` object balls to a cushion or pocketed one:
// the open-break requirement of 9-, 10- and 8-ball.
bool openBreakMet(const ShotFacts& facts, int count);

// The pool foul common to all three pool games, in the order a referee checks them (WPA 6.1 cue
// ball scratch or off the table, 6.2 wrong ball first, 6.5 ball driven off the table, 6.3 no rail
// after contact), given whether `first_hit_legal`. On a push-out (`hit_rules_apply` false) 6.2 and
// 6.3 do not apply (WPA 2.4, 9.4). Cites the rule it finds.
GameFoul poolStandardFoul(const ShotFacts& facts, bool first_hit_legal, bool hit_rules_apply,
                          Decision* decision);

}  // namespace baize::engine
