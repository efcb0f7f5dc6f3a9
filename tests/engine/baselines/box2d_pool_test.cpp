#include "engine/baselines/box2d_pool.h"

#include <gtest/gtest.h>

#include <cmath>

#include "engine/io/table.h"
#include "engine/models/model_registry.h"

namespace baize::engine {
namespace {

using physics::BallState;

// The cloth acts in half steps around each Box2D step, so Box2D moves a ball with its mid-step
// velocity: exact under constant deceleration, except in a step where the state changes (sliding
// to rolling, rolling to rest), which is off by at most about v dt. The tolerance takes v0 dt.
constexpr double kTimeStep_s = 1e-3;

// Box2D keeps positions in float: each step's x += v dt may round by half a float ulp of the
// coordinate (in Box2D units), and over thousands of steps those roundings add up, m.
double floatRounding_m(double largest_coordinate_m, double duration_s, double dt) {
  const double unit_m = box2dLengthUnit_m(dt);
  const float x = static_cast<float>(largest_coordinate_m / unit_m);
  const double ulp = std::nextafter(x, 2 * x + 1) - x;
  return 0.5 * ulp * unit_m * duration_s / dt;
}

BallState rollingBall(double x, double y, double vx, double vy, double R) {
  BallState b;
  b.position = {x, y};
  b.velocity = {vx, vy, 0};
  b.angular_velocity = {-vy / R, vx / R, 0};  // w = z x v / R: natural roll
  return b;
}

Box2dPoolSettings settingsWithStep(double dt) {
  Box2dPoolSettings s;
  s.time_step_s = dt;
  return s;
}

// A rolling ball decelerates at mu_r g and stops after v^2 / (2 mu_r g).
TEST(Box2dPool, RollingBallStopsAtTheRollingDistance) {
  const engine::SimulationParams p = engine::poolSimulationParams();
  const double R = p.ball.radius_m, v0 = 1.0;
  const double expected_m = v0 * v0 / (2 * p.cloth.rolling_friction * p.cloth.gravity_mps2);
  const engine::SimulationResult r =
      simulateBox2d(p, engine::rectangularTable(20, 10), {rollingBall(-8, 0, v0, 0, R)},
                    settingsWithStep(kTimeStep_s));
  ASSERT_EQ(r.final_balls.size(), 1u);
  const double t_stop_s = v0 / (p.cloth.rolling_friction * p.cloth.gravity_mps2);
  EXPECT_NEAR(r.final_balls[0].state.position.x() + 8, expected_m,
              v0 * kTimeStep_s + floatRounding_m(8, t_stop_s, kTimeStep_s));
  EXPECT_NEAR(r.final_balls[0].state.position.y(), 0, 1e-6);
  EXPECT_EQ(r.final_balls[0].state.velocity.norm(), 0);
  EXPECT_NEAR(r.end_time_s, v0 / (p.cloth.rolling_friction * p.cloth.gravity_mps2), kTimeStep_s);
}

// A ball struck without spin slides 12 v^2 / (49 mu_s g), then rolls on at 5/7 v.
TEST(Box2dPool, StunShotSlidesThenRollsAsTheClothModelSays) {
  const engine::SimulationParams p = engine::poolSimulationParams();
  const double v0 = 2.0, g = p.cloth.gravity_mps2;
  BallState b;
  b.position = {-8, 0};
  b.velocity = {v0, 0, 0};
  const double rolling_v = 5.0 / 7 * v0;
  const double expected_m = 12 * v0 * v0 / (49 * p.cloth.sliding_friction * g) +
                            rolling_v * rolling_v / (2 * p.cloth.rolling_friction * g);
  const engine::SimulationResult r =
      simulateBox2d(p, engine::rectangularTable(20, 10), {b}, settingsWithStep(kTimeStep_s));
  const double t_stop_s =
      2 * v0 / (7 * p.cloth.sliding_friction * g) + rolling_v / (p.cloth.rolling_friction * g);
  EXPECT_NEAR(r.final_balls[0].state.position.x() + 8, expected_m,
              v0 * kTimeStep_s + floatRounding_m(8, t_stop_s, kTimeStep_s));
}

// Head on into a cushion: the normal velocity reverses, at the calibrated restitution of the speed
// it arrived with, give or take what the cloth does in the few ms after the contact.
TEST(Box2dPool, CushionReboundReversesTheNormalVelocity) {
  const engine::SimulationParams p = engine::poolSimulationParams();
  const double R = p.ball.radius_m, v0 = 1.0, g = p.cloth.gravity_mps2;
  const double dt = 1e-4;
  const double gap_m = 0.2;  // from the ball's surface to the cushion at x = 1.27
  const double x0 = 1.27 - R - gap_m;
  // Arrival: rolling at mu_r g over the gap.
  const double v_in = std::sqrt(v0 * v0 - 2 * p.cloth.rolling_friction * g * gap_m);
  const double t_in = (v0 - v_in) / (p.cloth.rolling_friction * g);
  const double after_s = 0.005;  // look this long after the impact
  // Cloth friction changes the speed by at most mu_s g per second, plus a step of lateness.
  const double tolerance_mps = p.cloth.sliding_friction * g * (after_s + dt) + 1e-3;
  Box2dPoolSettings s = settingsWithStep(dt);
  s.stop_after_s = t_in + after_s;
  const engine::SimulationResult r =
      simulateBox2d(p, engine::rectangularTable(2.54, 1.27), {rollingBall(x0, 0, v0, 0, R)}, s);
  const double e = calibratedCushionRestitution(p);
  EXPECT_GT(e, 0.5);
  EXPECT_LT(e, 1.0);
  EXPECT_NEAR(r.final_balls[0].state.velocity.x(), -e * v_in, tolerance_mps);
  ASSERT_FALSE(r.events.empty());
  EXPECT_EQ(r.events[0].kind, engine::EventKind::Cushion);
  EXPECT_EQ(r.events[0].index, 1);  // the +x cushion of rectangularTable
  EXPECT_NEAR(r.events[0].time_s, t_in, 2 * dt);
}

// At an angle, the normal component reverses and the ball keeps moving along the cushion.
TEST(Box2dPool, AngledReboundKeepsTheTangentialDirection) {
  const engine::SimulationParams p = engine::poolSimulationParams();
  const double R = p.ball.radius_m;
  Box2dPoolSettings s = settingsWithStep(1e-4);
  s.stop_after_s = 0.45;  // it reaches the +x cushion after about 0.35 s, the +y one after 0.6 s
  const engine::SimulationResult r =
      simulateBox2d(p, engine::rectangularTable(2.54, 1.27), {rollingBall(0.9, 0, 1.0, 1.0, R)}, s);
  ASSERT_FALSE(r.events.empty());
  EXPECT_LT(r.final_balls[0].state.velocity.x(), 0);
  EXPECT_GT(r.final_balls[0].state.velocity.y(), 0);
}

// A ball rolled straight at a corner pocket falls in, and nothing else is recorded for it after.
TEST(Box2dPool, BallRolledIntoACornerPocketFallsIn) {
  const engine::Table table = engine::builtinTable("pool-9ft");
  const engine::SimulationParams p = engine::poolSimulationParams();
  const Eigen::Vector2d target = table.pockets[3].capture.centre_m;  // corner (+x, +y)
  const Eigen::Vector2d start(0.5, 0.2);
  const Eigen::Vector2d v = 2.0 * (target - start).normalized();
  const engine::SimulationResult r =
      simulateBox2d(p, engine::geometryOf(table),
                    {rollingBall(start.x(), start.y(), v.x(), v.y(), p.ball.radius_m)},
                    settingsWithStep(kTimeStep_s));
  ASSERT_FALSE(r.events.empty());
  EXPECT_EQ(r.events.back().kind, engine::EventKind::Pocket);
  EXPECT_EQ(r.events.back().index, 3);
  EXPECT_TRUE(r.final_balls[0].pocketed);
}

// Same input, same output: the 9-ball rack broken twice ends bit for bit the same.
TEST(Box2dPool, SameInputGivesTheSameOutput) {
  const engine::Table table = engine::builtinTable("pool-9ft");
  const engine::SimulationParams p = engine::poolSimulationParams();
  const double R = p.ball.radius_m;
  std::vector<BallState> balls = {rollingBall(-0.6, 0.01, 3.0, 0, R)};
  for (int row = 0; row < 3; ++row)  // a small triangle, 1 mm apart
    for (int k = 0; k <= row; ++k)
      balls.push_back(rollingBall(0.4 + row * (2 * R + 1e-3) * std::sqrt(3.0) / 2,
                                  (k - row / 2.0) * (2 * R + 1e-3), 0, 0, R));
  const engine::SimulationResult a =
      simulateBox2d(p, engine::geometryOf(table), balls, settingsWithStep(kTimeStep_s));
  const engine::SimulationResult b =
      simulateBox2d(p, engine::geometryOf(table), balls, settingsWithStep(kTimeStep_s));
  ASSERT_EQ(a.events.size(), b.events.size());
  EXPECT_GT(a.events.size(), 3u);
  for (std::size_t i = 0; i < balls.size(); ++i) {
    EXPECT_EQ(a.final_balls[i].pocketed, b.final_balls[i].pocketed);
    EXPECT_EQ(a.final_balls[i].state.position.x(), b.final_balls[i].state.position.x());
    EXPECT_EQ(a.final_balls[i].state.position.y(), b.final_balls[i].state.position.y());
  }
}

TEST(Box2dPool, RejectsBadSettings) {
  const engine::SimulationParams p = engine::poolSimulationParams();
  BallState b;
  EXPECT_THROW(simulateBox2d(p, engine::rectangularTable(2.54, 1.27), {b}, settingsWithStep(0)),
               std::invalid_argument);
  Box2dPoolSettings s;
  s.velocity_iterations = 0;
  EXPECT_THROW(simulateBox2d(p, engine::rectangularTable(2.54, 1.27), {b}, s),
               std::invalid_argument);
}

}  // namespace
}  // namespace baize::engine
