#include "engine/play/games/pot_ease.h"

#include <gtest/gtest.h>

#include "tests/engine/play/games/game_test_support.h"

namespace baize::engine {
namespace {

using Eigen::Vector2d;

const Vector2d kMouth = test::poolTable().pockets[3].mouth_centre_m;  // top-right corner
const Vector2d kDiagonal = Vector2d(1, 1).normalized();
const Vector2d kOne = kMouth - 0.4 * kDiagonal;

double ease(const std::vector<PlacedBall>& balls, const Vector2d& cue) {
  return potEase(balls, cue, "1", 3, test::poolTable(), test::poolRadius());
}

TEST(PotEase, StraightBeatsCutAndNearBeatsFar) {
  const std::vector<PlacedBall> balls{{"1", kOne}};
  const double straight = ease(balls, kOne - 0.5 * kDiagonal);
  const double far = ease(balls, kOne - 1.0 * kDiagonal);
  const Vector2d side(kDiagonal.y(), -kDiagonal.x());
  const double cut = ease(balls, kOne - 0.5 * kDiagonal + 0.3 * side);
  EXPECT_GT(straight, far);
  EXPECT_GT(straight, cut);
  EXPECT_GT(cut, 0);
  EXPECT_LE(straight, 1);
}

TEST(PotEase, ZeroWhenBlockedOrTooThin) {
  const Vector2d cue = kOne - 0.5 * kDiagonal;
  EXPECT_EQ(ease({{"1", kOne}, {"2", kOne + 0.2 * kDiagonal}}, cue), 0);  // in the pocket's way
  EXPECT_EQ(ease({{"1", kOne}, {"2", kOne - 0.25 * kDiagonal}}, cue), 0);  // in the cue ball's
  const Vector2d side(kDiagonal.y(), -kDiagonal.x());
  EXPECT_EQ(ease({{"1", kOne}}, kOne + 0.3 * side), 0);  // a cut of 90 deg
  EXPECT_EQ(ease({{"2", kOne}}, cue), 0);                  // no such ball
}

TEST(PotEase, TheGhostBallIsTwoRadiiBehindTheBall) {
  const Vector2d ghost = ghostBall(kOne, test::poolTable().pockets[3], test::poolRadius());
  EXPECT_NEAR((ghost - kOne).norm(), 2 * test::poolRadius(), 1e-12);
  EXPECT_GT((kMouth - ghost).norm(), (kMouth - kOne).norm());
}

TEST(PotEase, BestEaseOverTheLegalBalls) {
  GameState s = test::stateWith(Game::NineBall, {{"cue", kOne - 0.5 * kDiagonal}, {"1", kOne}, {"2", Vector2d(0, 0)}});
  EXPECT_EQ(bestPotEase(s, test::poolTable(), test::poolRadius()), ease(s.balls, s.balls[0].position_m));
  s.frame_over = true;
  EXPECT_EQ(bestPotEase(s, test::poolTable(), test::poolRadius()), 1);
}

}  // namespace
}  // namespace baize::engine
