#include "engine/play/games/ruling_steps.h"

#include <algorithm>

namespace baize::engine {

GameState tableAfterShot(const GameState& before, const ShotFacts& facts) {
  GameState next = before;
  next.balls.clear();
  if (facts.cueBallPocketed() && !before.balls.empty()) next.balls.push_back(before.balls.front());
  for (const PlacedBall& b : facts.final_balls) {
    if (!facts.offTable(b.id)) next.balls.push_back(b);
  }
  next.in_hand = CueBallInHand::No;
  next.break_shot = false;
  next.push_out_available = false;
  ++next.shots;
  return next;
}

void cite(Decision* decision, const std::string& rule) {
  decision->rule += (decision->rule.empty() ? "" : "; ") + rule;
}

void passTurn(GameState* next, Decision* decision) {
  next->player = opponentOf(next->player);
  decision->turn_passes = true;
}

void endFrame(int winner, GameState* next, Decision* decision) {
  next->frame_over = true;
  next->winner = winner;
  decision->frame_over = true;
  decision->winner = winner;
}

bool openBreakMet(const ShotFacts& facts, int count) {
  return !facts.objectBallsPocketed().empty() ||
         static_cast<int>(facts.object_balls_to_cushion.size()) >= count;
}

GameFoul poolStandardFoul(const ShotFacts& facts, bool first_hit_legal, bool hit_rules_apply,
                          Decision* decision) {
  GameFoul foul = GameFoul::None;
  if (facts.cueBallPocketed()) {
    foul = GameFoul::CueBallPocketed;
    cite(decision, "WPA 6.1");
  } else if (hit_rules_apply && !facts.first_hit) {
    foul = GameFoul::NoBallHit;
    cite(decision, "WPA 6.2");
  } else if (hit_rules_apply && !first_hit_legal) {
    foul = GameFoul::WrongBallFirst;
    cite(decision, "WPA 6.2");
  } else if (!facts.off_table.empty()) {
    foul = GameFoul::BallOffTable;
    cite(decision, "WPA 6.5");
  } else if (hit_rules_apply && facts.objectBallsPocketed().empty() &&
             !facts.cushion_after_first_hit) {
    foul = GameFoul::NoCushionAfterContact;
    cite(decision, "WPA 6.3");
  }
  return foul;
}

}  // namespace baize::engine
