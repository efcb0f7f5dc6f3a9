#include "engine/play/games/shot_facts.h"

#include <algorithm>
#include <stdexcept>

namespace baize::engine {

ShotFacts shotFacts(const std::vector<std::string>& ball_ids, const SimulationResult& result,
                    const std::string& cue_ball) {
  const auto cue_at = std::find(ball_ids.begin(), ball_ids.end(), cue_ball);
  if (cue_at == ball_ids.end() || result.final_balls.size() != ball_ids.size()) {
    throw std::invalid_argument("shot facts: cue ball '" + cue_ball +
                                "' is not allowed: it must be one of the run's balls, and the run "
                                "must hold one final record per ball");
  }
  const int cue = static_cast<int>(cue_at - ball_ids.begin());
  ShotFacts facts;
  facts.cue_ball = cue_ball;
  for (const Event& e : result.events) {
    const bool cushion = e.kind == EventKind::Cushion || e.kind == EventKind::Jaw;
    if (e.kind == EventKind::BallBall && !facts.first_hit && (e.ball == cue || e.other == cue)) {
      facts.first_hit = ball_ids.at(e.ball == cue ? e.other : e.ball);
    } else if (cushion && facts.first_hit) {
      facts.cushion_after_first_hit = true;
    }
    if (cushion && e.ball != cue) {
      const std::string& id = ball_ids.at(e.ball);
      auto& seen = facts.object_balls_to_cushion;
      if (std::find(seen.begin(), seen.end(), id) == seen.end()) seen.push_back(id);
    }
    if (e.kind == EventKind::Pocket) facts.pocketed.push_back({ball_ids.at(e.ball), e.index});
  }
  for (std::size_t i = 0; i < ball_ids.size(); ++i) {
    const BallRecord& record = result.final_balls[i];
    if (!record.pocketed) facts.final_balls.push_back({ball_ids[i], record.state.position});
  }
  return facts;
}

}  // namespace baize::engine
