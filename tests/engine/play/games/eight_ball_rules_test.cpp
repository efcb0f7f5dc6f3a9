#include "engine/play/games/eight_ball_rules.h"

#include <gtest/gtest.h>

#include "tests/engine/play/games/game_test_support.h"

namespace baize::engine {
namespace {

using Eigen::Vector2d;
using test::HandMadeShot;

GameState table(Group mine = Group::Solids) {
  GameState s = test::stateWith(Game::EightBall, {{"cue", Vector2d(-0.5, 0)},
                                                  {"3", Vector2d(0, 0.2)},
                                                  {"8", Vector2d(0.4, 0)},
                                                  {"12", Vector2d(0.3, -0.3)}});
  s.groups = {mine, mine == Group::Solids ? Group::Stripes
                    : mine == Group::Stripes ? Group::Solids
                                             : Group::None};
  return s;
}

Ruling rule(const GameState& s, const HandMadeShot& shot, const ShotCall& call = {}) {
  return ruleEightBallShot(s, shot.facts(), call, test::poolTable(), test::poolRadius());
}

void expectFoul(const Ruling& r, GameFoul foul) {
  EXPECT_EQ(r.decision.foul, foul) << gameFoulName(r.decision.foul);
  EXPECT_TRUE(r.decision.turn_passes);
  EXPECT_EQ(r.next.in_hand, CueBallInHand::Anywhere);
  EXPECT_FALSE(r.next.frame_over);
}

TEST(EightBallRules, GroupsAndTargets) {
  EXPECT_EQ(groupOf("7"), Group::Solids);
  EXPECT_EQ(groupOf("9"), Group::Stripes);
  EXPECT_EQ(groupOf("8"), Group::None);
  EXPECT_EQ(eightBallTargets(table(), 0), std::vector<std::string>{"3"});
  EXPECT_EQ(eightBallTargets(table(Group::None), 0), (std::vector<std::string>{"3", "12"}));
  GameState cleared = table();
  cleared.balls.erase(cleared.balls.begin() + 1);
  EXPECT_EQ(eightBallTargets(cleared, 0), std::vector<std::string>{"8"});
}

TEST(EightBallRules, OpponentsBallFirstIsAFoul) {
  const GameState s = table();
  expectFoul(rule(s, HandMadeShot(s).hit("cue", "12").cushion("12")), GameFoul::WrongBallFirst);
}

TEST(EightBallRules, TheEightFirstOnAnOpenTableIsAFoul) {
  const GameState s = table(Group::None);
  expectFoul(rule(s, HandMadeShot(s).hit("cue", "8").cushion("8")), GameFoul::WrongBallFirst);
}

TEST(EightBallRules, NoBallNoCushionScratchOffTable) {
  const GameState s = table();
  expectFoul(rule(s, HandMadeShot(s).cushion("cue")), GameFoul::NoBallHit);
  expectFoul(rule(s, HandMadeShot(s).hit("cue", "3")), GameFoul::NoCushionAfterContact);
  expectFoul(rule(s, HandMadeShot(s).hit("cue", "3").pocket("cue", 0)), GameFoul::CueBallPocketed);
  expectFoul(rule(s, HandMadeShot(s).hit("cue", "3").offTable("12")), GameFoul::BallOffTable);
}

TEST(EightBallRules, NoThreeFoulRule) {
  GameState s = table();
  s.consecutive_fouls = {2, 0};
  EXPECT_FALSE(rule(s, HandMadeShot(s).cushion("cue")).next.frame_over);
}

TEST(EightBallRules, CalledPotOnAnOpenTableChoosesTheGroups) {
  const GameState s = table(Group::None);
  const Ruling r = rule(s, HandMadeShot(s).hit("cue", "12").pocket("12", 1), {"12", 1, false});
  EXPECT_EQ(r.decision.foul, GameFoul::None);
  EXPECT_FALSE(r.decision.turn_passes);
  EXPECT_EQ(r.next.groups[0], Group::Stripes);
  EXPECT_EQ(r.next.groups[1], Group::Solids);
}

TEST(EightBallRules, ABallOtherThanTheCalledOnePassesTheTurn) {
  const GameState s = table();
  const Ruling r = rule(s, HandMadeShot(s).hit("cue", "3").hit("3", "12").pocket("12", 1),
                        {"3", 2, false});
  EXPECT_EQ(r.decision.foul, GameFoul::None);
  EXPECT_TRUE(r.decision.turn_passes);
  EXPECT_FALSE(r.next.onTable("12"));
}

TEST(EightBallRules, TheEightEarlyLosesTheRack) {
  const GameState s = table();
  const Ruling r = rule(s, HandMadeShot(s).hit("cue", "3").hit("3", "8").pocket("8", 3));
  EXPECT_TRUE(r.next.frame_over);
  EXPECT_EQ(r.next.winner, 1);
  EXPECT_NE(r.decision.rule.find("WPA 3.8"), std::string::npos);
}

TEST(EightBallRules, TheEightLastWinsInTheCalledPocketOnlyAndNotWithAScratch) {
  GameState s = table();
  s.balls.erase(s.balls.begin() + 1);  // the solids are down
  const ShotCall call{"8", 3, false};
  EXPECT_EQ(rule(s, HandMadeShot(s).hit("cue", "8").pocket("8", 3), call).next.winner, 0);
  EXPECT_EQ(rule(s, HandMadeShot(s).hit("cue", "8").pocket("8", 2), call).next.winner, 1);
  EXPECT_EQ(rule(s, HandMadeShot(s).hit("cue", "8").pocket("8", 3).pocket("cue", 0), call)
                .next.winner,
            1);
}

GameState breaking() {
  GameState s = table(Group::None);
  s.break_shot = true;
  s.balls.push_back({"1", Vector2d(0.5, 0.3)});
  s.balls.push_back({"9", Vector2d(0.5, -0.2)});
  return s;
}

TEST(EightBallRules, BreakWithAPotContinuesOnAnOpenTable) {
  const GameState s = breaking();
  const Ruling r = rule(s, HandMadeShot(s).hit("cue", "12").pocket("3", 1));
  EXPECT_EQ(r.decision.foul, GameFoul::None);
  EXPECT_FALSE(r.decision.turn_passes);
  EXPECT_EQ(r.next.groups[0], Group::None);
}

TEST(EightBallRules, IllegalBreakLeavesTheTableToTheOpponent) {
  const GameState s = breaking();
  const Ruling r = rule(s, HandMadeShot(s).hit("cue", "12").cushion("12").cushion("3").cushion("8"));
  EXPECT_EQ(r.decision.foul, GameFoul::IllegalBreak);
  EXPECT_TRUE(r.decision.turn_passes);
  EXPECT_EQ(r.next.in_hand, CueBallInHand::No);
}

TEST(EightBallRules, EightOnTheBreakIsSpottedAndWithAScratchTheCueBallGoesBehindTheHeadString) {
  const GameState s = breaking();
  const Ruling kept = rule(s, HandMadeShot(s).hit("cue", "12").pocket("8", 3));
  EXPECT_FALSE(kept.next.frame_over);
  EXPECT_FALSE(kept.decision.turn_passes);
  EXPECT_EQ(kept.decision.respotted, std::vector<std::string>{"8"});
  const Ruling scratch = rule(s, HandMadeShot(s).hit("cue", "12").pocket("8", 3).pocket("cue", 0));
  EXPECT_FALSE(scratch.next.frame_over);
  EXPECT_EQ(scratch.decision.foul, GameFoul::CueBallPocketed);
  EXPECT_EQ(scratch.next.in_hand, CueBallInHand::BehindHeadString);
  const Ruling plain = rule(s, HandMadeShot(s).hit("cue", "12").pocket("3", 1).pocket("cue", 0));
  EXPECT_EQ(plain.next.in_hand, CueBallInHand::Anywhere);
}

}  // namespace
}  // namespace baize::engine
