#include "engine/play/games/game_player.h"

#include <gtest/gtest.h>

#include <cmath>

#include "engine/play/games/game_rules.h"
#include "engine/play/games/pot_ease.h"

namespace baize::engine {
namespace {

using Eigen::Vector2d;

const GameSetup& nineBall() {
  static const GameSetup setup = gameSetup(Game::NineBall);
  return setup;
}

double radius() { return nineBall().scene.ball_set.radius_m; }

GameState openTable() {
  GameState s;
  s.game = Game::NineBall;
  s.break_shot = false;
  // The 1 on the top-right corner's diagonal, the cue ball 0.5 m behind it: a straight pot.
  const Vector2d mouth = nineBall().scene.table.pockets[3].mouth_centre_m;
  const Vector2d one = mouth - 0.4 * Vector2d(1, 1).normalized();
  s.balls = {{"cue", one - 0.5 * Vector2d(1, 1).normalized()},
             {"1", one},
             {"9", Vector2d(-0.6, -0.3)}};
  return s;
}

Ruling noiseFreeRuling(const GameState& s, const GameShot& shot) {
  const std::optional<ShotFacts> facts = simulateFacts(shotScene(nineBall(), s, shot));
  EXPECT_TRUE(facts.has_value());
  return ruleShot(s, *facts, shot.call, nineBall().scene.table, radius());
}

TEST(GamePlayer, PotsAStraightBallAndKeepsTheTable) {
  const GameState s = openTable();
  PlayerOptions options;
  options.noise = ExecutionNoise();
  const GameShot shot = chooseShot(nineBall(), s, options, 1);
  EXPECT_EQ(shot.kind, "pot");
  EXPECT_EQ(shot.call.ball, "1");
  EXPECT_EQ(shot.call.pocket, 3);
  EXPECT_FALSE(shot.place.has_value());
  const Ruling r = noiseFreeRuling(s, shot);
  EXPECT_EQ(r.decision.foul, GameFoul::None);
  EXPECT_FALSE(r.next.onTable("1"));
  EXPECT_FALSE(r.decision.turn_passes);
}

TEST(GamePlayer, IsDeterministicForASeed) {
  const GameState s = openTable();
  const GameShot a = chooseShot(nineBall(), s, PlayerOptions(), 4);
  const GameShot b = chooseShot(nineBall(), s, PlayerOptions(), 4);
  EXPECT_EQ(a.shot.heading_rad, b.shot.heading_rad);
  EXPECT_EQ(a.shot.speed_mps, b.shot.speed_mps);
  EXPECT_EQ(a.shot.height_offset, b.shot.height_offset);
}

TEST(GamePlayer, PlacesTheCueBallFromHandWhereTheRulesAllow) {
  GameState s = openTable();
  s.in_hand = CueBallInHand::Anywhere;
  const GameShot shot = chooseShot(nineBall(), s, PlayerOptions(), 2);
  ASSERT_TRUE(shot.place.has_value());
  EXPECT_EQ(placementRefusal(s, *shot.place, nineBall().scene.table, radius()), "");
  EXPECT_EQ(shot.kind, "pot");
}

// The 1 ringed by six balls, one on the line to each pocket: no pot is on, so the player plays a
// safety at the 1 through the gap the cue ball comes from, and it is legal.
TEST(GamePlayer, PlaysASafetyWhenNoPotIsOn) {
  GameState s;
  s.game = Game::NineBall;
  s.break_shot = false;
  const Vector2d one(0, 0);
  s.balls = {{"cue", one + 0.6 * Vector2d(std::cos(-1.01), std::sin(-1.01))}, {"1", one}};
  const double ring = 4 * radius();
  for (int k = 0; k < 6; ++k) {
    const Vector2d to = (nineBall().scene.table.pockets[k].mouth_centre_m - one).normalized();
    s.balls.push_back({std::to_string(k + 2), one + ring * to});
  }
  for (int k = 0; k < 6; ++k) {
    EXPECT_EQ(potEase(s.balls, s.balls[0].position_m, "1", k, nineBall().scene.table, radius()), 0);
  }
  const GameShot shot = chooseShot(nineBall(), s, PlayerOptions(), 3);
  EXPECT_EQ(shot.kind, "safety");
  EXPECT_EQ(shot.call.ball, "1");
  EXPECT_EQ(noiseFreeRuling(s, shot).decision.foul, GameFoul::None);
}

TEST(GamePlayer, TheBreakIsTheScenesBreak) {
  const GameState s = initialGameState(Game::NineBall, nineBall().scene.table, nineBall().scene.ball_set);
  const GameShot shot = chooseShot(nineBall(), s, PlayerOptions(), 1);
  EXPECT_EQ(shot.kind, "break");
  EXPECT_EQ(shot.shot.speed_mps, nineBall().scene.shot.speed_mps);
  ASSERT_TRUE(shot.place.has_value());
  EXPECT_EQ(placementRefusal(s, *shot.place, nineBall().scene.table, radius()), "");
}

}  // namespace
}  // namespace baize::engine
