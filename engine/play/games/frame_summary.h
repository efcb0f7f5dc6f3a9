// What a played frame amounts to (`baize play`'s summary, `baize bench play`): per player the
// shots, visits to the table, balls potted, fouls and the best visit; the winner; whether the
// breaker ran out (won without the opponent taking a shot); whether the first visit after the
// break cleared the table; snooker breaks.
#pragma once

#include <array>
#include <vector>

#include "engine/play/games/game_play.h"

namespace baize::engine {

struct PlayerSummary {
  int shots = 0;
  int visits = 0;    // turns at the table
  int potted = 0;    // object balls pocketed on legal shots
  int fouls = 0;
  int best_visit = 0;  // balls potted (pool) or points scored (snooker) in one visit
};

struct FrameSummary {
  std::array<PlayerSummary, 2> players;
  int winner = -1;
  bool finished = false;
  bool run_out = false;     // the breaker won and the opponent never played (break and run)
  // The player of the first shot after the break won in that one visit (cleared the table).
  bool first_visit_run_out = false;
  std::vector<int> breaks;  // snooker: the points of each scoring visit, in order
};

FrameSummary summarizeFrame(const PlayedFrame& frame);

}  // namespace baize::engine
