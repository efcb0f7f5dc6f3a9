#include "engine/play/games/snooker_rules.h"

#include <algorithm>

#include "engine/play/games/ball_spotting.h"
#include "engine/play/games/ruling_steps.h"

namespace baize::engine {
namespace {

// The least penalty of a foul, and the penalty of a foul after a red before a colour is
// nominated (WPBSA section 3, penalties).
constexpr int kMinPenalty = 4;
constexpr int kUnnominatedPenalty = 7;
const char* const kFoulRule = "WPBSA 3 fouls and penalties";
const char* const kSpotRule = "WPBSA 3 spotting colours";
const char* const kEndRule = "WPBSA 3 end of frame";

// What is on for this shot.
struct BallOn {
  std::string on;         // as in GameState::ball_on
  std::string nominated;  // after a red: the colour nominated ("" none)
  bool isOn(const std::string& id) const {
    if (on == "red") return isRed(id);
    if (on == "colour") return nominated.empty() ? snookerValue(id) >= 2 : id == nominated;
    return id == on;
  }
  int value() const {
    if (on == "red") return 1;
    if (on == "colour") return nominated.empty() ? kUnnominatedPenalty : snookerValue(nominated);
    return snookerValue(on);
  }
};

BallOn ballOnFor(const GameState& state, const ShotFacts& facts, const ShotCall& call) {
  BallOn b{state.ball_on, ""};
  if (b.on != "colour") return b;
  if (snookerValue(call.ball) >= 2) {
    b.nominated = call.ball;
  } else if (facts.first_hit && snookerValue(*facts.first_hit) >= 2) {
    b.nominated = *facts.first_hit;
  }
  return b;
}

// The foul committed (the first a referee sees) and the penalty: the highest of 4, the ball on's
// value and the values of the balls concerned.
GameFoul findFoul(const ShotFacts& facts, const BallOn& on, int* penalty) {
  GameFoul foul = GameFoul::None;
  *penalty = std::max(kMinPenalty, on.value());
  const auto concern = [&](GameFoul kind, const std::string& id) {
    if (foul == GameFoul::None) foul = kind;
    *penalty = std::max(*penalty, snookerValue(id));
  };
  if (facts.cueBallPocketed()) concern(GameFoul::CueBallPocketed, "");
  if (!facts.first_hit) concern(GameFoul::NoBallHit, "");
  if (facts.first_hit && !on.isOn(*facts.first_hit)) {
    concern(GameFoul::WrongBallFirst, *facts.first_hit);
  }
  for (const std::string& id : facts.objectBallsPocketed()) {
    if (!on.isOn(id)) concern(GameFoul::BallNotOnPotted, id);
  }
  for (const std::string& id : facts.off_table) {
    if (id != facts.cue_ball) concern(GameFoul::BallOffTable, id);
  }
  return foul;
}

// The frame is over when the black, last on the table, is potted or fouled: the higher score
// wins; scores level, the black is re-spotted and the other player plays from in hand (the
// rules draw lots for who plays; Baize gives it to the player who did not end the frame).
void endOnScores(const GameState& state, const Table& table, double radius_m, Ruling* r) {
  cite(&r->decision, kEndRule);
  const std::array<int, 2>& s = r->next.score;
  if (s[0] != s[1]) {
    endFrame(s[0] > s[1] ? 0 : 1, &r->next, &r->decision);
    return;
  }
  if (!r->next.onTable("black")) {
    spotSnookerColours({"black"}, &r->next.balls, table, radius_m);
    r->decision.respotted.push_back("black");
  }
  r->next.ball_on = "black";
  r->next.player = opponentOf(state.player);
  r->decision.turn_passes = true;
  r->next.in_hand = CueBallInHand::InD;
}

std::vector<std::string> coloursDown(const ShotFacts& facts) {
  std::vector<std::string> down;
  for (const std::string& id : facts.objectBallsPocketed()) {
    if (snookerValue(id) >= 2) down.push_back(id);
  }
  for (const std::string& id : facts.off_table) {
    if (snookerValue(id) >= 2) down.push_back(id);
  }
  return down;
}

void ruleFoul(const GameState& state, const ShotFacts& facts, int penalty, const Table& table,
              double radius_m, Ruling* r) {
  cite(&r->decision, kFoulRule);
  r->decision.penalty = penalty;
  r->next.score[opponentOf(state.player)] += penalty;
  if (state.ball_on == "black") {  // only the black was left: the foul ends the frame
    endOnScores(state, table, radius_m, r);
    if (r->next.frame_over || r->next.in_hand == CueBallInHand::InD) return;
  }
  const std::vector<std::string> down = coloursDown(facts);
  if (!down.empty()) {
    r->decision.respotted = spotSnookerColours(down, &r->next.balls, table, radius_m);
    cite(&r->decision, kSpotRule);
  }
  passTurn(&r->next, &r->decision);
  r->next.in_hand = facts.cueBallPocketed() ? CueBallInHand::InD : CueBallInHand::No;
  r->next.ball_on = ballOnAtTurnStart(r->next);
}

void rulePots(const GameState& state, const ShotFacts& facts, const BallOn& on,
              const Table& table, double radius_m, Ruling* r) {
  const std::vector<std::string> potted = facts.objectBallsPocketed();
  if (on.on == "red") {
    r->decision.points = static_cast<int>(potted.size());
    r->next.ball_on = "colour";
  } else if (on.on == "colour") {  // a colour after a red comes back while reds remain or just went
    r->decision.points = snookerValue(potted.front());
    r->decision.respotted = spotSnookerColours({potted.front()}, &r->next.balls, table, radius_m);
    cite(&r->decision, kSpotRule);
    r->next.ball_on = ballOnAtTurnStart(r->next);
  } else {  // the final sequence: the colour stays down
    r->decision.points = snookerValue(on.on);
    r->next.ball_on = ballOnAtTurnStart(r->next);
  }
  r->next.score[state.player] += r->decision.points;
  if (r->next.ball_on.empty()) endOnScores(state, table, radius_m, r);
}

}  // namespace

std::vector<std::string> snookerTargets(const GameState& state) {
  std::vector<std::string> targets;
  for (const PlacedBall& b : state.balls) {
    const bool target = state.ball_on == "red"      ? isRed(b.id)
                        : state.ball_on == "colour" ? snookerValue(b.id) >= 2
                                                    : b.id == state.ball_on;
    if (target) targets.push_back(b.id);
  }
  return targets;
}

std::string ballOnAtTurnStart(const GameState& state) {
  int lowest = 0;
  for (const PlacedBall& b : state.balls) {
    if (isRed(b.id)) return "red";
    const int v = snookerValue(b.id);
    if (v >= 2 && (lowest == 0 || v < lowest)) lowest = v;
  }
  return lowest == 0 ? "" : snookerColours()[lowest - 2];
}

Ruling ruleSnookerShot(const GameState& state, const ShotFacts& facts, const ShotCall& call,
                       const Table& table, double ball_radius_m) {
  Ruling r{tableAfterShot(state, facts), {}};
  const BallOn on = ballOnFor(state, facts, call);
  int penalty = 0;
  r.decision.foul = findFoul(facts, on, &penalty);
  if (r.decision.foul != GameFoul::None) {
    ruleFoul(state, facts, penalty, table, ball_radius_m, &r);
  } else if (facts.objectBallsPocketed().empty()) {
    passTurn(&r.next, &r.decision);
    if (on.on == "red" || on.on == "colour") r.next.ball_on = ballOnAtTurnStart(r.next);
  } else {
    rulePots(state, facts, on, table, ball_radius_m, &r);
  }
  return r;
}

}  // namespace baize::engine
