#include "engine/play/games/rotation_rules.h"

#include <cstdlib>
#include <string>

#include "engine/play/games/ball_spotting.h"
#include "engine/play/games/ruling_steps.h"

namespace baize::engine {
namespace {

// The three fouls in a row that lose the rack (WPA 6.14).
constexpr int kFoulsLosingRack = 3;
// Object balls to a cushion for a legal break without a pocketed ball (WPA 2.3, 9.3).
constexpr int kOpenBreakBalls = 4;

struct RotationRules {
  bool ten;
  const char* money;
  const char* break_rule;
  const char* push_rule;
  const char* spot_rule;
};

RotationRules rulesOf(Game game) {
  if (game == Game::TenBall) return {true, "10", "WPA 9.3", "WPA 9.4", "WPA 9.9"};
  return {false, "9", "WPA 2.3", "WPA 2.4", "WPA 2.6"};
}

void respotMoneyBall(const RotationRules& rules, const ShotFacts& facts, const Table& table,
                     double radius_m, GameState* next, Decision* decision) {
  if (!facts.pocketedBall(rules.money) && !facts.offTable(rules.money)) return;
  spotPoolBall(rules.money, &next->balls, table, radius_m);
  decision->respotted.push_back(rules.money);
  cite(decision, rules.spot_rule);
}

void ruleFoul(const GameState& state, const RotationRules& rules, const ShotFacts& facts,
              const Table& table, double radius_m, Ruling* r) {
  respotMoneyBall(rules, facts, table, radius_m, &r->next, &r->decision);
  const int fouls = ++r->next.consecutive_fouls[state.player];
  passTurn(&r->next, &r->decision);
  r->next.in_hand = CueBallInHand::Anywhere;
  if (fouls >= kFoulsLosingRack) {
    cite(&r->decision, "WPA 6.14");
    endFrame(opponentOf(state.player), &r->next, &r->decision);
  }
}

bool calledBallMade(const ShotFacts& facts, const ShotCall& call) {
  for (const PocketedBall& p : facts.pocketed) {
    if (p.ball == call.ball && p.pocket == call.pocket) return true;
  }
  return false;
}

// A legal shot of 10-ball after the break: the called ball in the called pocket continues (the 10
// so made wins); any other ball pocketed stays down but ends the turn, the 10 re-spotted
// (WPA 9.5 call shots, 9.7 wrongfully pocketed balls; the opponent's option to hand the shot back
// is not taken: the opponent plays).
bool ruleTenBallPots(const RotationRules& rules, const ShotFacts& facts, const ShotCall& call,
                     const Table& table, double radius_m, Ruling* r) {
  const bool made = calledBallMade(facts, call);
  cite(&r->decision, "WPA 9.5");
  if (made && call.ball == rules.money) {
    endFrame(r->next.player, &r->next, &r->decision);
    return true;
  }
  if (!made && !facts.objectBallsPocketed().empty()) cite(&r->decision, "WPA 9.7");
  respotMoneyBall(rules, facts, table, radius_m, &r->next, &r->decision);
  return made;
}

}  // namespace

std::string lowestBall(const GameState& state) {
  int lowest = 0;
  for (const PlacedBall& b : state.balls) {
    const int number = std::atoi(b.id.c_str());
    if (number > 0 && (lowest == 0 || number < lowest)) lowest = number;
  }
  return lowest == 0 ? "" : std::to_string(lowest);
}

Ruling ruleRotationShot(const GameState& state, const ShotFacts& facts, const ShotCall& call,
                        const Table& table, double ball_radius_m) {
  const RotationRules rules = rulesOf(state.game);
  const bool push = call.push_out && state.push_out_available;
  Ruling r{tableAfterShot(state, facts), {}};
  if (push) cite(&r.decision, rules.push_rule);
  r.decision.foul = poolStandardFoul(facts, facts.first_hit == lowestBall(state), !push, &r.decision);
  if (r.decision.foul == GameFoul::None && state.break_shot &&
      !openBreakMet(facts, kOpenBreakBalls)) {
    r.decision.foul = GameFoul::IllegalBreak;
    cite(&r.decision, rules.break_rule);
  }
  if (r.decision.foul != GameFoul::None) {
    ruleFoul(state, rules, facts, table, ball_radius_m, &r);
    return r;
  }
  r.next.consecutive_fouls[state.player] = 0;
  bool continues = !facts.objectBallsPocketed().empty();
  if (push) {  // the opponent's option to hand the shot back is not taken: the opponent plays
    respotMoneyBall(rules, facts, table, ball_radius_m, &r.next, &r.decision);
    continues = false;
  } else if (!rules.ten) {  // any ball pocketed continues; the 9 pocketed wins (WPA 2.5)
    cite(&r.decision, "WPA 2.5");
    if (facts.pocketedBall(rules.money)) {
      endFrame(state.player, &r.next, &r.decision);
      return r;
    }
  } else if (state.break_shot) {  // the 10 pocketed on the break is spotted (WPA 9.9)
    respotMoneyBall(rules, facts, table, ball_radius_m, &r.next, &r.decision);
  } else {
    continues = ruleTenBallPots(rules, facts, call, table, ball_radius_m, &r);
    if (r.next.frame_over) return r;
  }
  if (!continues) passTurn(&r.next, &r.decision);
  r.next.push_out_available = state.break_shot;
  return r;
}

}  // namespace baize::engine
