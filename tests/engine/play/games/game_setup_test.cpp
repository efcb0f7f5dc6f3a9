#include "engine/play/games/game_setup.h"

#include <gtest/gtest.h>

#include "engine/play/games/game_rules.h"

namespace baize::engine {
namespace {

TEST(GameSetup, EveryGameBreaksFromWhereTheRulesAllow) {
  for (Game g : {Game::NineBall, Game::TenBall, Game::EightBall, Game::Snooker}) {
    const GameSetup setup = gameSetup(g);
    const GameState s = initialGameState(g, setup.scene.table, setup.scene.ball_set);
    const GameShot shot = breakShot(setup);
    ASSERT_TRUE(shot.place.has_value()) << gameName(g);
    EXPECT_EQ(placementRefusal(s, *shot.place, setup.scene.table, setup.scene.ball_set.radius_m), "")
        << gameName(g);
    EXPECT_GT(shot.shot.speed_mps, 0);
  }
  EXPECT_EQ(gameSetup(Game::TenBall).scene.balls.size(), 11u);
}

TEST(GameSetup, ShotSceneUsesTheStateAndThePlace) {
  const GameSetup setup = gameSetup(Game::NineBall);
  GameState s = initialGameState(Game::NineBall, setup.scene.table, setup.scene.ball_set);
  s.balls.pop_back();
  GameShot shot = breakShot(setup);
  shot.place = Eigen::Vector2d(-0.9, 0.2);
  const Scene scene = shotScene(setup, s, shot);
  EXPECT_EQ(scene.balls.size(), s.balls.size());
  EXPECT_EQ(scene.balls.front().position_m, *shot.place);
  EXPECT_EQ(scene.shot.speed_mps, shot.shot.speed_mps);
}

TEST(GameSetup, AShotThatCannotRunHasNoFacts) {
  const GameSetup setup = gameSetup(Game::NineBall);
  const GameState s = initialGameState(Game::NineBall, setup.scene.table, setup.scene.ball_set);
  GameShot miscue = breakShot(setup);
  miscue.shot.side_offset = 0.9;  // past the miscue limit (0.5 R)
  EXPECT_FALSE(simulateFacts(shotScene(setup, s, miscue)).has_value());
  const ShotFacts standing = standingFacts(s);
  EXPECT_FALSE(standing.first_hit.has_value());
  EXPECT_EQ(standing.final_balls.size(), s.balls.size());
}

}  // namespace
}  // namespace baize::engine
