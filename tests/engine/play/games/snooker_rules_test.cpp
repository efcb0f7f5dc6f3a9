#include "engine/play/games/snooker_rules.h"

#include <gtest/gtest.h>

#include "engine/play/games/ball_spotting.h"
#include "tests/engine/play/games/game_test_support.h"

namespace baize::engine {
namespace {

using Eigen::Vector2d;
using test::HandMadeShot;

const Vector2d kCueAt(-1.2, 0.1), kRedAt(0.5, 0.4), kRed2At(0.6, -0.5);

// Two reds and every colour on its spot.
GameState frame() {
  GameState s = test::stateWith(Game::Snooker, {{"cue", kCueAt}, {"red1", kRedAt}, {"red2", kRed2At}});
  for (const std::string& c : snookerColours()) s.balls.push_back({c, colourSpot(c, test::snookerTable())});
  return s;
}

Ruling rule(const GameState& s, const HandMadeShot& shot, const ShotCall& call = {}) {
  return ruleSnookerShot(s, shot.facts(), call, test::snookerTable(), test::snookerRadius());
}

void expectFoul(const Ruling& r, GameFoul foul, int penalty) {
  EXPECT_EQ(r.decision.foul, foul) << gameFoulName(r.decision.foul);
  EXPECT_EQ(r.decision.penalty, penalty);
  EXPECT_EQ(r.next.score[1], penalty);
  EXPECT_EQ(r.next.score[0], 0);
  EXPECT_TRUE(r.decision.turn_passes);
}

TEST(SnookerRules, ARedScoresOneAndPutsAColourOn) {
  const GameState s = frame();
  const Ruling r = rule(s, HandMadeShot(s).hit("cue", "red1").pocket("red1", 3));
  EXPECT_EQ(r.decision.points, 1);
  EXPECT_EQ(r.next.score[0], 1);
  EXPECT_EQ(r.next.ball_on, "colour");
  EXPECT_FALSE(r.decision.turn_passes);
}

TEST(SnookerRules, TwoRedsInOneShotScoreTwo) {
  const GameState s = frame();
  EXPECT_EQ(rule(s, HandMadeShot(s).hit("cue", "red1").pocket("red1", 3).pocket("red2", 2))
                .decision.points,
            2);
}

TEST(SnookerRules, AColourAfterARedScoresAndIsSpotted) {
  GameState s = frame();
  s.ball_on = "colour";
  const Ruling r = rule(s, HandMadeShot(s).hit("cue", "blue").pocket("blue", 1), {"blue", 1, false});
  EXPECT_EQ(r.decision.points, 5);
  EXPECT_EQ(r.next.ball_on, "red");
  EXPECT_EQ(r.decision.respotted, std::vector<std::string>{"blue"});
  EXPECT_EQ(r.next.ball("blue")->position_m, colourSpot("blue", test::snookerTable()));
}

TEST(SnookerRules, AColourWhoseSpotIsTakenGoesToTheHighestFreeSpot) {
  GameState s = frame();
  s.ball_on = "colour";
  s.balls.back().position_m = Vector2d(1.0, 0.5);  // the black off its spot
  const Vector2d blue_spot = colourSpot("blue", test::snookerTable());
  // The red comes to rest on the blue's spot; the black's spot is the highest free one.
  const Ruling r = rule(s, HandMadeShot(s).hit("cue", "blue").pocket("blue", 1).moveTo("red1", blue_spot),
                        {"blue", 1, false});
  EXPECT_EQ(r.next.ball("blue")->position_m, colourSpot("black", test::snookerTable()));
}

TEST(SnookerRules, WithEverySpotTakenAColourGoesBehindItsOwnSpot) {
  std::vector<PlacedBall> balls;
  const Table& t = test::snookerTable();
  for (const std::string& c : snookerColours()) {
    if (c != "pink") balls.push_back({"red-" + c, colourSpot(c, t)});
  }
  balls.push_back({"red-pink", colourSpot("pink", t)});
  const std::vector<std::string> placed = spotSnookerColours({"pink"}, &balls, t, test::snookerRadius());
  ASSERT_EQ(placed, std::vector<std::string>{"pink"});
  const Vector2d at = balls.back().position_m;
  EXPECT_EQ(at.y(), colourSpot("pink", t).y());
  EXPECT_GT(at.x(), colourSpot("pink", t).x());  // towards the top cushion
  EXPECT_NEAR((at - colourSpot("pink", t)).norm(), 2 * test::snookerRadius(), 1e-6);
}

TEST(SnookerRules, SeveralColoursTakeTheirOwnSpotsFirst) {
  // Black and pink to spot; the black's spot is taken: the pink keeps its own, the black goes to
  // the highest other free spot (blue).
  std::vector<PlacedBall> balls{{"red1", colourSpot("black", test::snookerTable())}};
  spotSnookerColours({"pink", "black"}, &balls, test::snookerTable(), test::snookerRadius());
  EXPECT_EQ(balls[1].id, "pink");
  EXPECT_EQ(balls[2].position_m, colourSpot("blue", test::snookerTable()));
}

TEST(SnookerRules, NoBallHitCostsFour) {
  const GameState s = frame();
  expectFoul(rule(s, HandMadeShot(s).cushion("cue")), GameFoul::NoBallHit, 4);
}

TEST(SnookerRules, HittingABallNotOnFirstCostsItsValue) {
  const GameState s = frame();
  expectFoul(rule(s, HandMadeShot(s).hit("cue", "black").cushion("black")), GameFoul::WrongBallFirst, 7);
  expectFoul(rule(s, HandMadeShot(s).hit("cue", "green").cushion("green")), GameFoul::WrongBallFirst, 4);
}

TEST(SnookerRules, PottingABallNotOnIsAFoulAndTheColourComesBack) {
  const GameState s = frame();
  const Ruling r = rule(s, HandMadeShot(s).hit("cue", "red1").hit("red1", "pink").pocket("pink", 4));
  expectFoul(r, GameFoul::BallNotOnPotted, 6);
  EXPECT_TRUE(r.next.onTable("pink"));
  EXPECT_EQ(r.next.ball_on, "red");
}

TEST(SnookerRules, InOffGivesTheCueBallInHandInTheD) {
  const GameState s = frame();
  const Ruling r = rule(s, HandMadeShot(s).hit("cue", "red1").pocket("cue", 0));
  expectFoul(r, GameFoul::CueBallPocketed, 4);
  EXPECT_EQ(r.next.in_hand, CueBallInHand::InD);
}

TEST(SnookerRules, ABallOffTheTableIsAFoul) {
  const GameState s = frame();
  expectFoul(rule(s, HandMadeShot(s).hit("cue", "red1").offTable("brown")), GameFoul::BallOffTable, 4);
}

TEST(SnookerRules, AFoulBeforeNominatingAColourCostsSeven) {
  GameState s = frame();
  s.ball_on = "colour";
  expectFoul(rule(s, HandMadeShot(s).cushion("cue")), GameFoul::NoBallHit, 7);
  // Nominated: the nominated colour's value (at least 4).
  expectFoul(rule(s, HandMadeShot(s).cushion("cue"), {"pink", -1, false}), GameFoul::NoBallHit, 6);
}

TEST(SnookerRules, AMissPassesTheTurnWithRedsOn) {
  GameState s = frame();
  s.ball_on = "colour";
  const Ruling r = rule(s, HandMadeShot(s).hit("cue", "blue").cushion("blue"), {"blue", -1, false});
  EXPECT_EQ(r.decision.foul, GameFoul::None);
  EXPECT_TRUE(r.decision.turn_passes);
  EXPECT_EQ(r.next.ball_on, "red");
}

GameState finalColours(const std::vector<std::string>& colours) {
  GameState s = test::stateWith(Game::Snooker, {{"cue", kCueAt}});
  for (const std::string& c : colours) s.balls.push_back({c, colourSpot(c, test::snookerTable())});
  s.ball_on = colours.front();
  return s;
}

TEST(SnookerRules, InTheFinalSequenceAPottedColourStaysDown) {
  const GameState s = finalColours({"yellow", "green"});
  const Ruling r = rule(s, HandMadeShot(s).hit("cue", "yellow").pocket("yellow", 0));
  EXPECT_EQ(r.decision.points, 2);
  EXPECT_FALSE(r.next.onTable("yellow"));
  EXPECT_EQ(r.next.ball_on, "green");
}

TEST(SnookerRules, TheLastBlackEndsTheFrameOnScores) {
  GameState s = finalColours({"black"});
  s.score = {10, 14};
  const Ruling r = rule(s, HandMadeShot(s).hit("cue", "black").pocket("black", 3));
  EXPECT_TRUE(r.next.frame_over);
  EXPECT_EQ(r.next.winner, 0);  // 17 to 14
}

TEST(SnookerRules, LevelScoresAfterTheBlackRespotIt) {
  GameState s = finalColours({"black"});
  s.score = {7, 14};
  const Ruling r = rule(s, HandMadeShot(s).hit("cue", "black").pocket("black", 3));
  EXPECT_FALSE(r.next.frame_over);
  EXPECT_TRUE(r.next.onTable("black"));
  EXPECT_EQ(r.next.ball_on, "black");
  EXPECT_EQ(r.next.in_hand, CueBallInHand::InD);
  EXPECT_EQ(r.next.player, 1);
}

TEST(SnookerRules, AFoulOnTheLastBlackEndsTheFrame) {
  GameState s = finalColours({"black"});
  s.score = {20, 14};
  const Ruling r = rule(s, HandMadeShot(s).cushion("cue"));
  EXPECT_EQ(r.decision.penalty, 7);
  EXPECT_TRUE(r.next.frame_over);
  EXPECT_EQ(r.next.winner, 1);  // 20 to 21
}

}  // namespace
}  // namespace baize::engine
