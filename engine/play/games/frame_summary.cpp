#include "engine/play/games/frame_summary.h"

#include <algorithm>

namespace baize::engine {

FrameSummary summarizeFrame(const PlayedFrame& frame) {
  FrameSummary summary;
  summary.finished = frame.finished;
  summary.winner = frame.final_state.winner;
  int visit = 0;  // this visit's balls or points so far
  for (std::size_t i = 0; i < frame.shots.size(); ++i) {
    const PlayedShot& s = frame.shots[i];
    PlayerSummary& p = summary.players[s.state.player];
    const bool new_visit = i == 0 || frame.shots[i - 1].state.player != s.state.player ||
                           frame.shots[i - 1].decision.turn_passes;
    if (new_visit) {
      ++p.visits;
      visit = 0;
    }
    ++p.shots;
    if (s.decision.foul != GameFoul::None) {
      ++p.fouls;
    } else {
      const int balls = static_cast<int>(s.facts.objectBallsPocketed().size());
      p.potted += balls;
      visit += s.state.game == Game::Snooker ? s.decision.points : balls;
    }
    p.best_visit = std::max(p.best_visit, visit);
    const bool visit_ends = s.decision.turn_passes || i + 1 == frame.shots.size();
    if (visit_ends && s.state.game == Game::Snooker && visit > 0) summary.breaks.push_back(visit);
  }
  summary.run_out = summary.finished && summary.winner == 0 && summary.players[1].shots == 0;
  const auto& shots = frame.shots;
  summary.first_visit_run_out =
      summary.finished && shots.size() > 1 && summary.winner == shots[1].state.player &&
      std::none_of(shots.begin() + 1, shots.end(),
                   [](const PlayedShot& s) { return s.decision.turn_passes; });
  return summary;
}

}  // namespace baize::engine
