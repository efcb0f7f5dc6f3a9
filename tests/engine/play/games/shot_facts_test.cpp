#include "engine/play/games/shot_facts.h"

#include <gtest/gtest.h>

#include "tests/engine/play/games/game_test_support.h"

namespace baize::engine {
namespace {

using Eigen::Vector2d;

const GameState kBalls = test::stateWith(
    Game::NineBall, {{"cue", Vector2d(-0.5, 0)}, {"1", Vector2d(0, 0)}, {"2", Vector2d(0.3, 0.3)}});

TEST(ShotFacts, FirstHitAndCushionsAfterIt) {
  const ShotFacts before = test::HandMadeShot(kBalls).cushion("cue").hit("cue", "1").facts();
  EXPECT_EQ(before.first_hit, std::optional<std::string>("1"));
  EXPECT_FALSE(before.cushion_after_first_hit);
  const ShotFacts after = test::HandMadeShot(kBalls).hit("1", "2").hit("cue", "2").cushion("1").facts();
  EXPECT_EQ(after.first_hit, std::optional<std::string>("2"));  // the cue ball's first contact
  EXPECT_TRUE(after.cushion_after_first_hit);
}

TEST(ShotFacts, ObjectBallsToACushionAreCountedOnce) {
  const ShotFacts f =
      test::HandMadeShot(kBalls).cushion("cue").cushion("1").cushion("2").cushion("1").facts();
  EXPECT_EQ(f.object_balls_to_cushion, (std::vector<std::string>{"1", "2"}));
}

TEST(ShotFacts, PocketedBallsInOrderAndLeftOffTheFinalBalls) {
  const ShotFacts f = test::HandMadeShot(kBalls).hit("cue", "2").pocket("2", 4).pocket("cue", 1).facts();
  ASSERT_EQ(f.pocketed.size(), 2u);
  EXPECT_EQ(f.pocketed[0].ball, "2");
  EXPECT_EQ(f.pocketed[0].pocket, 4);
  EXPECT_TRUE(f.cueBallPocketed());
  EXPECT_EQ(f.objectBallsPocketed(), std::vector<std::string>{"2"});
  ASSERT_EQ(f.final_balls.size(), 1u);
  EXPECT_EQ(f.final_balls[0].id, "1");
}

TEST(ShotFacts, RefusesAMissingCueBall) {
  SimulationResult result;
  result.final_balls.resize(1);
  EXPECT_THROW(shotFacts({"1"}, result, "cue"), std::invalid_argument);
}

}  // namespace
}  // namespace baize::engine
