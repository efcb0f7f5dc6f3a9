#include "engine/play/games/eight_ball_rules.h"

#include <algorithm>
#include <cstdlib>

#include "engine/play/games/ball_spotting.h"
#include "engine/play/games/ruling_steps.h"

namespace baize::engine {
namespace {

constexpr int kOpenBreakBalls = 4;  // object balls to a cushion without a pocketed ball (WPA 3.3)
const std::string kEight = "8";

bool eightDown(const ShotFacts& facts) {
  return facts.pocketedBall(kEight) || facts.offTable(kEight);
}

// The break (WPA 3.3): no ball need be hit first; the 8 pocketed is spotted and the breaker
// continues (option (e)(1)); with a scratch as well, the opponent has the cue ball behind the head
// string (option (f)(1)); an illegal break leaves the table as it lies to the opponent (option
// (d)(1)). The table stays open.
Ruling ruleBreak(const GameState& state, const ShotFacts& facts, const Table& table,
                 double radius_m) {
  Ruling r{tableAfterShot(state, facts), {}};
  cite(&r.decision, "WPA 3.3");
  r.decision.foul = poolStandardFoul(facts, true, false, &r.decision);
  if (eightDown(facts)) {
    spotPoolBall(kEight, &r.next.balls, table, radius_m);
    r.decision.respotted.push_back(kEight);
  }
  if (r.decision.foul != GameFoul::None) {
    passTurn(&r.next, &r.decision);
    r.next.in_hand = eightDown(facts) && facts.cueBallPocketed() ? CueBallInHand::BehindHeadString
                                                                 : CueBallInHand::Anywhere;
  } else if (!openBreakMet(facts, kOpenBreakBalls)) {
    r.decision.foul = GameFoul::IllegalBreak;
    passTurn(&r.next, &r.decision);
  } else if (facts.objectBallsPocketed().empty()) {
    passTurn(&r.next, &r.decision);
  }
  return r;
}

// The ball that counts as called: the call, or without one the first target pocketed (an obvious
// shot need not be called).
ShotCall effectiveCall(const ShotFacts& facts, const ShotCall& call,
                       const std::vector<std::string>& targets) {
  if (!call.ball.empty()) return call;
  for (const PocketedBall& p : facts.pocketed) {
    if (std::find(targets.begin(), targets.end(), p.ball) != targets.end()) {
      return {p.ball, p.pocket, false};
    }
  }
  return {};
}

bool madeInPocket(const ShotFacts& facts, const ShotCall& call) {
  return std::any_of(facts.pocketed.begin(), facts.pocketed.end(), [&](const PocketedBall& p) {
    return p.ball == call.ball && (call.pocket < 0 || p.pocket == call.pocket);
  });
}

// The 8 down after the break: won when it was the player's ball, called into the pocket it fell
// in, without a foul; lost otherwise (WPA 3.8).
void ruleEightDown(const GameState& state, const ShotFacts& facts, const ShotCall& call,
                   bool on_eight, Ruling* r) {
  const bool won = r->decision.foul == GameFoul::None && on_eight && call.ball == kEight &&
                   call.pocket >= 0 && madeInPocket(facts, call) && !facts.offTable(kEight);
  if (!won) cite(&r->decision, "WPA 3.8");
  endFrame(won ? state.player : opponentOf(state.player), &r->next, &r->decision);
}

}  // namespace

Group groupOf(const std::string& id) {
  const int n = std::atoi(id.c_str());
  if (n >= 1 && n <= 7) return Group::Solids;
  if (n >= 9 && n <= 15) return Group::Stripes;
  return Group::None;
}

std::vector<std::string> eightBallTargets(const GameState& state, int player) {
  const Group group = state.groups[player];
  std::vector<std::string> targets;
  for (const PlacedBall& b : state.balls) {
    const Group g = groupOf(b.id);
    if (g != Group::None && (group == Group::None || g == group)) targets.push_back(b.id);
  }
  if (targets.empty() && group != Group::None && state.onTable(kEight)) targets.push_back(kEight);
  return targets;
}

Ruling ruleEightBallShot(const GameState& state, const ShotFacts& facts, const ShotCall& call,
                         const Table& table, double ball_radius_m) {
  if (state.break_shot) return ruleBreak(state, facts, table, ball_radius_m);
  const std::vector<std::string> targets = eightBallTargets(state, state.player);
  const bool on_eight = targets.size() == 1 && targets[0] == kEight;
  const bool first_legal = facts.first_hit && std::find(targets.begin(), targets.end(),
                                                        *facts.first_hit) != targets.end();
  Ruling r{tableAfterShot(state, facts), {}};
  r.decision.foul = poolStandardFoul(facts, first_legal, true, &r.decision);
  if (eightDown(facts)) {
    ruleEightDown(state, facts, call, on_eight, &r);
    return r;
  }
  if (r.decision.foul != GameFoul::None) {  // 8-ball has no three-foul rule
    passTurn(&r.next, &r.decision);
    r.next.in_hand = CueBallInHand::Anywhere;
    return r;
  }
  const ShotCall called = effectiveCall(facts, call, targets);
  const bool made = !called.ball.empty() &&
                    std::find(targets.begin(), targets.end(), called.ball) != targets.end() &&
                    madeInPocket(facts, called);
  if (made && state.groups[state.player] == Group::None) {  // the groups are chosen (WPA 3.4)
    const Group mine = groupOf(called.ball);
    r.next.groups[state.player] = mine;
    r.next.groups[opponentOf(state.player)] =
        mine == Group::Solids ? Group::Stripes : Group::Solids;
    cite(&r.decision, "WPA 3.4");
  }
  if (!made) passTurn(&r.next, &r.decision);
  return r;
}

}  // namespace baize::engine
