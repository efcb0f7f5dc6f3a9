#include "engine/play/games/rotation_rules.h"

#include <gtest/gtest.h>

#include "tests/engine/play/games/game_test_support.h"

namespace baize::engine {
namespace {

using Eigen::Vector2d;
using test::HandMadeShot;

const Vector2d kCueAt(-0.5, 0), kOneAt(0, 0.2), kTwoAt(0.3, -0.3), kMoneyAt(0.2, 0.4);

GameState rack(Game game) {
  const std::string money = game == Game::TenBall ? "10" : "9";
  return test::stateWith(game, {{"cue", kCueAt}, {"1", kOneAt}, {"2", kTwoAt}, {money, kMoneyAt}});
}

Ruling rule(const GameState& s, const HandMadeShot& shot, const ShotCall& call = {}) {
  return ruleRotationShot(s, shot.facts(), call, test::poolTable(), test::poolRadius());
}

// Every foul of section 6 passes the turn with the cue ball in hand anywhere and counts one foul,
// in both games.
void expectStandardFoul(const Ruling& r, GameFoul foul, const std::string& rule) {
  EXPECT_EQ(r.decision.foul, foul) << gameFoulName(r.decision.foul);
  EXPECT_NE(r.decision.rule.find(rule), std::string::npos) << r.decision.rule;
  EXPECT_TRUE(r.decision.turn_passes);
  EXPECT_EQ(r.next.player, 1);
  EXPECT_EQ(r.next.in_hand, CueBallInHand::Anywhere);
  EXPECT_EQ(r.next.consecutive_fouls[0], 1);
  EXPECT_FALSE(r.next.frame_over);
}

TEST(RotationRules, LowestBallIsTheLowestNumberOnTheTable) {
  EXPECT_EQ(lowestBall(rack(Game::NineBall)), "1");
  GameState s = rack(Game::NineBall);
  s.balls.erase(s.balls.begin() + 1);
  EXPECT_EQ(lowestBall(s), "2");
}

TEST(RotationRules, WrongBallFirstIsAFoulInBothGames) {
  for (Game g : {Game::NineBall, Game::TenBall}) {
    expectStandardFoul(rule(rack(g), HandMadeShot(rack(g)).hit("cue", "2").cushion("2")),
                       GameFoul::WrongBallFirst, "WPA 6.2");
  }
}

TEST(RotationRules, NoBallHitIsAFoul) {
  for (Game g : {Game::NineBall, Game::TenBall}) {
    expectStandardFoul(rule(rack(g), HandMadeShot(rack(g)).cushion("cue")), GameFoul::NoBallHit,
                       "WPA 6.2");
  }
}

TEST(RotationRules, NoCushionAfterContactIsAFoul) {
  for (Game g : {Game::NineBall, Game::TenBall}) {
    // A cushion before the contact does not count.
    expectStandardFoul(rule(rack(g), HandMadeShot(rack(g)).cushion("cue").hit("cue", "1")),
                       GameFoul::NoCushionAfterContact, "WPA 6.3");
  }
}

TEST(RotationRules, CueBallPocketedIsAFoulAndTheCueBallKeepsItsPlace) {
  for (Game g : {Game::NineBall, Game::TenBall}) {
    const Ruling r = rule(rack(g), HandMadeShot(rack(g)).hit("cue", "1").pocket("cue", 2));
    expectStandardFoul(r, GameFoul::CueBallPocketed, "WPA 6.1");
    ASSERT_EQ(r.next.balls.front().id, "cue");
    EXPECT_EQ(r.next.balls.front().position_m, kCueAt);
  }
}

TEST(RotationRules, ObjectBallOffTheTableIsAFoulAndStaysOff) {
  for (Game g : {Game::NineBall, Game::TenBall}) {
    const Ruling r = rule(rack(g), HandMadeShot(rack(g)).hit("cue", "1").offTable("2"));
    expectStandardFoul(r, GameFoul::BallOffTable, "WPA 6.5");
    EXPECT_FALSE(r.next.onTable("2"));
  }
}

TEST(RotationRules, ThreeFoulsInARowLoseTheRack) {
  GameState s = rack(Game::NineBall);
  s.consecutive_fouls = {2, 0};
  const Ruling r = rule(s, HandMadeShot(s).hit("cue", "2").cushion("2"));
  EXPECT_TRUE(r.next.frame_over);
  EXPECT_EQ(r.next.winner, 1);
  EXPECT_NE(r.decision.rule.find("WPA 6.14"), std::string::npos);
}

TEST(RotationRules, ALegalShotClearsTheFoulCount) {
  GameState s = rack(Game::NineBall);
  s.consecutive_fouls = {2, 1};
  const Ruling r = rule(s, HandMadeShot(s).hit("cue", "1").cushion("1"));
  EXPECT_EQ(r.decision.foul, GameFoul::None);
  EXPECT_EQ(r.next.consecutive_fouls[0], 0);
  EXPECT_EQ(r.next.consecutive_fouls[1], 1);
  EXPECT_TRUE(r.decision.turn_passes);  // nothing pocketed
  EXPECT_EQ(r.next.in_hand, CueBallInHand::No);
}

TEST(RotationRules, NineBallAnyPocketedBallContinues) {
  const GameState s = rack(Game::NineBall);
  const Ruling r = rule(s, HandMadeShot(s).hit("cue", "1").hit("1", "2").pocket("2", 0));
  EXPECT_EQ(r.decision.foul, GameFoul::None);
  EXPECT_FALSE(r.decision.turn_passes);
  EXPECT_EQ(r.next.player, 0);
  EXPECT_FALSE(r.next.onTable("2"));
}

TEST(RotationRules, NineBallPocketedLegallyWinsEvenOnACombination) {
  const GameState s = rack(Game::NineBall);
  const Ruling r = rule(s, HandMadeShot(s).hit("cue", "1").hit("1", "9").pocket("9", 3));
  EXPECT_TRUE(r.next.frame_over);
  EXPECT_EQ(r.next.winner, 0);
}

TEST(RotationRules, NineBallPocketedOnAFoulIsSpottedOnTheFootSpot) {
  const GameState s = rack(Game::NineBall);
  const Ruling r = rule(s, HandMadeShot(s).hit("cue", "2").hit("2", "9").pocket("9", 3));
  EXPECT_EQ(r.decision.foul, GameFoul::WrongBallFirst);
  EXPECT_EQ(r.decision.respotted, std::vector<std::string>{"9"});
  ASSERT_TRUE(r.next.onTable("9"));
  EXPECT_EQ(r.next.ball("9")->position_m, test::poolTable().pool_markings->foot_spot_m);
  EXPECT_FALSE(r.next.frame_over);
}

TEST(RotationRules, NineBallSpottedBehindABallOnTheFootSpot) {
  const Vector2d foot = test::poolTable().pool_markings->foot_spot_m;
  const GameState s = test::stateWith(
      Game::NineBall, {{"cue", kCueAt}, {"1", kOneAt}, {"2", foot}, {"9", kMoneyAt}});
  const Ruling r = rule(s, HandMadeShot(s).cushion("cue").pocket("9", 3));
  ASSERT_TRUE(r.next.onTable("9"));
  const Vector2d at = r.next.ball("9")->position_m;
  EXPECT_EQ(at.y(), 0);
  EXPECT_GT(at.x(), foot.x());  // towards the foot cushion, frozen to the 2
  EXPECT_NEAR((at - foot).norm(), 2 * test::poolRadius(), 1e-6);
}

TEST(RotationRules, NineBallSpottedInFrontWhenTheStringBehindIsFull) {
  const Vector2d foot = test::poolTable().pool_markings->foot_spot_m;
  const double step = 2 * test::poolRadius() + 1e-4;
  GameState s = test::stateWith(Game::NineBall, {{"cue", kCueAt}, {"1", kOneAt}, {"9", kMoneyAt}});
  for (int k = 0; foot.x() + k * step < test::poolTable().length_m / 2; ++k) {
    s.balls.push_back({"b" + std::to_string(k), foot + Vector2d(k * step, 0)});
  }
  const Ruling r = rule(s, HandMadeShot(s).cushion("cue").pocket("9", 3));
  ASSERT_TRUE(r.next.onTable("9"));
  const Vector2d at = r.next.ball("9")->position_m;
  EXPECT_EQ(at.y(), 0);
  EXPECT_LT(at.x(), foot.x());  // towards the head, frozen to the ball on the spot
  EXPECT_NEAR(foot.x() - at.x(), 2 * test::poolRadius(), 1e-6);
}

TEST(RotationRules, LegalBreakWithoutAPotPassesAndOffersThePushOut) {
  for (Game g : {Game::NineBall, Game::TenBall}) {
    GameState s = rack(g);
    s.break_shot = true;
    const Ruling r = rule(
        s, HandMadeShot(s).hit("cue", "1").cushion("1").cushion("2").cushion(g == Game::TenBall ? "10" : "9").cushion("cue"));
    // Three object balls to a cushion only (the cue ball does not count): an illegal break.
    EXPECT_EQ(r.decision.foul, GameFoul::IllegalBreak);
    EXPECT_EQ(r.next.in_hand, CueBallInHand::Anywhere);
    GameState four = s;
    four.balls.push_back({"3", Vector2d(-0.2, -0.4)});
    const Ruling ok = rule(four, HandMadeShot(four).hit("cue", "1").cushion("1").cushion("2").cushion("3").cushion(g == Game::TenBall ? "10" : "9"));
    EXPECT_EQ(ok.decision.foul, GameFoul::None);
    EXPECT_TRUE(ok.decision.turn_passes);
    EXPECT_TRUE(ok.next.push_out_available);
    EXPECT_FALSE(ok.next.break_shot);
  }
}

TEST(RotationRules, BreakMustHitTheOneFirst) {
  GameState s = rack(Game::NineBall);
  s.break_shot = true;
  const Ruling r = rule(s, HandMadeShot(s).hit("cue", "2").pocket("2", 1));
  EXPECT_EQ(r.decision.foul, GameFoul::WrongBallFirst);
}

TEST(RotationRules, PushOutNeedsNoHitAndRespotsTheNine) {
  GameState s = rack(Game::NineBall);
  s.push_out_available = true;
  ShotCall push;
  push.push_out = true;
  const Ruling miss = rule(s, HandMadeShot(s).moveTo("cue", Vector2d(0, -0.4)), push);
  EXPECT_EQ(miss.decision.foul, GameFoul::None);
  EXPECT_TRUE(miss.decision.turn_passes);
  EXPECT_FALSE(miss.next.push_out_available);
  const Ruling nine = rule(s, HandMadeShot(s).hit("cue", "9").pocket("9", 3), push);
  EXPECT_EQ(nine.decision.foul, GameFoul::None);
  EXPECT_FALSE(nine.next.frame_over);
  EXPECT_EQ(nine.decision.respotted, std::vector<std::string>{"9"});
  // Without the push-out available the same shot is a foul.
  s.push_out_available = false;
  EXPECT_EQ(rule(s, HandMadeShot(s).cushion("cue"), push).decision.foul, GameFoul::NoBallHit);
}

TEST(RotationRules, TenBallCalledBallContinuesAndAnUncalledPotPasses) {
  const GameState s = rack(Game::TenBall);
  const ShotCall call{"1", 3, false};
  const Ruling made = rule(s, HandMadeShot(s).hit("cue", "1").pocket("1", 3), call);
  EXPECT_FALSE(made.decision.turn_passes);
  const Ruling wrong_pocket = rule(s, HandMadeShot(s).hit("cue", "1").pocket("1", 2), call);
  EXPECT_EQ(wrong_pocket.decision.foul, GameFoul::None);
  EXPECT_TRUE(wrong_pocket.decision.turn_passes);
  EXPECT_FALSE(wrong_pocket.next.onTable("1"));  // it stays down
}

TEST(RotationRules, TenBallWinsOnlyWhenCalled) {
  const GameState s = rack(Game::TenBall);
  const Ruling called =
      rule(s, HandMadeShot(s).hit("cue", "1").hit("1", "10").pocket("10", 4), {"10", 4, false});
  EXPECT_TRUE(called.next.frame_over);
  EXPECT_EQ(called.next.winner, 0);
  const Ruling slop =
      rule(s, HandMadeShot(s).hit("cue", "1").hit("1", "10").pocket("10", 4), {"1", 3, false});
  EXPECT_FALSE(slop.next.frame_over);
  EXPECT_TRUE(slop.decision.turn_passes);
  EXPECT_EQ(slop.decision.respotted, std::vector<std::string>{"10"});
}

TEST(RotationRules, TenBallOnTheBreakIsSpottedAndTheBreakerContinues) {
  GameState s = rack(Game::TenBall);
  s.break_shot = true;
  const Ruling r = rule(s, HandMadeShot(s).hit("cue", "1").hit("1", "10").pocket("10", 3));
  EXPECT_EQ(r.decision.foul, GameFoul::None);
  EXPECT_FALSE(r.next.frame_over);
  EXPECT_FALSE(r.decision.turn_passes);
  EXPECT_TRUE(r.next.onTable("10"));
}

}  // namespace
}  // namespace baize::engine
