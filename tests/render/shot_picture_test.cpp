#include "render/shot_picture.h"

#include <gtest/gtest.h>

#include <cmath>
#include <iomanip>
#include <sstream>
#include <stdexcept>

#include "engine/io/scene.h"
#include "render/table_picture.h"

namespace baize::render {
namespace {

// Positions are sampled from closed forms in metres: rounding ~1e-15 m.
constexpr double kPositionTolerance_m = 1e-12;

// Balls alone on the 9 ft table, each one trajectory piece from t = 0 (nothing to hit).
ShotRecord loneBalls(const std::vector<std::pair<std::string, physics::BallState>>& balls) {
  ShotRecord shot;
  shot.table = engine::builtinTable("pool-9ft");
  shot.ball_set = engine::builtinBallSet("pool");
  shot.cloth = physics::poolCloth();
  for (const auto& [id, state] : balls) {
    shot.ball_ids.push_back(id);
    shot.trajectories.push_back({engine::TrajectoryPiece{0, state, false}});
    physics::BallState s = state;
    double t = 0;
    while (physics::motionState(shot.cloth, s) != physics::MotionState::Stationary) {
      const double dt = physics::timeToStateChange(shot.cloth, s);
      s = physics::advance(shot.cloth, s, dt);
      t += dt;
    }
    shot.end_time_s = std::max(shot.end_time_s, t);
  }
  return shot;
}

physics::BallState rollingAlongX(double x_m, double y_m, double speed_mps, double radius_m) {
  physics::BallState s;
  s.position = {x_m, y_m};
  s.velocity = {speed_mps, 0, 0};
  s.angular_velocity = {0, speed_mps / radius_m, 0};  // u = v + R z x w = 0
  return s;
}

std::vector<const Stroke*> strokesOf(const Picture& picture, const Rgba& colour) {
  std::vector<const Stroke*> out;
  for (const DrawItem& item : picture.items) {
    const Stroke* s = std::get_if<Stroke>(&item);
    if (s != nullptr && s->colour == colour) out.push_back(s);
  }
  return out;
}

std::vector<const Disc*> discsOf(const Picture& picture, DiscStyle style) {
  std::vector<const Disc*> out;
  for (const DrawItem& item : picture.items) {
    const Disc* d = std::get_if<Disc>(&item);
    if (d != nullptr && d->style == style) out.push_back(d);
  }
  return out;
}

TEST(ShotPicture, RollingBallLeavesOneSolidStraightTraceEndingAtTheBall) {
  const double R = engine::builtinBallSet("pool").radius_m;
  const ShotRecord shot = loneBalls({{"3", rollingAlongX(-0.5, 0.2, 0.5, R)}});
  PictureOptions options;
  const Picture picture = buildShotPicture(shot, options);
  const Eigen::Vector2d end =
      engine::sampleTrajectory(shot.cloth, shot.trajectories[0], shot.end_time_s).position;
  // Rolling to rest from 0.5 m/s covers v^2 / (2 mu_r g).
  EXPECT_NEAR(end.x() + 0.5, 0.25 / (2 * shot.cloth.rolling_friction * shot.cloth.gravity_mps2),
              kPositionTolerance_m);

  const std::vector<const Stroke*> trace = strokesOf(picture, ballColour(shot.ball_set, "3"));
  ASSERT_EQ(trace.size(), 1u);  // rolling throughout: one solid stroke
  EXPECT_DOUBLE_EQ(trace[0]->width_m, kTraceWidth_px * options.pixel_size_m);
  const std::vector<Eigen::Vector2d>& points = trace[0]->points_m;
  EXPECT_NEAR((points.front() - Eigen::Vector2d(-0.5, 0.2)).norm(), 0, kPositionTolerance_m);
  EXPECT_NEAR((points.back() - end).norm(), 0, kPositionTolerance_m);
  for (std::size_t i = 1; i < points.size(); ++i) {
    EXPECT_NEAR(points[i].y(), 0.2, kPositionTolerance_m);
    EXPECT_GT(points[i].x(), points[i - 1].x());
    EXPECT_LE(points[i].x() - points[i - 1].x(),
              kTraceStep_px * options.pixel_size_m + kPositionTolerance_m);
  }
  const std::vector<const Disc*> balls = discsOf(picture, DiscStyle::Ball);
  ASSERT_EQ(balls.size(), 1u);
  EXPECT_NEAR((balls[0]->centre_m.head<2>() - end).norm(), 0, kPositionTolerance_m);
  EXPECT_DOUBLE_EQ(balls[0]->centre_m.z(), R);  // a sphere resting on the cloth
  EXPECT_DOUBLE_EQ(balls[0]->radius_m, R);
  const std::vector<const Disc*> rings = discsOf(picture, DiscStyle::Ring);
  ASSERT_EQ(rings.size(), 1u);  // where it started
  EXPECT_NEAR((rings[0]->centre_m.head<2>() - Eigen::Vector2d(-0.5, 0.2)).norm(), 0,
              kPositionTolerance_m);
}

TEST(ShotPicture, SlidingIsDashedAndRollingSolidWithTheSwitchWhereTheSlideEnds) {
  physics::BallState stun;  // struck centre-ball: slides, then rolls
  stun.position = {-0.8, -0.3};
  stun.velocity = {1.0, 0, 0};
  const ShotRecord shot = loneBalls({{"cue", stun}});
  PictureOptions options;
  const Picture picture = buildShotPicture(shot, options);
  const physics::ClothParams& cloth = shot.cloth;
  const double slide_end_s = 2 * 1.0 / (7 * cloth.sliding_friction * cloth.gravity_mps2);
  const double slide_end_x =
      engine::sampleTrajectory(cloth, shot.trajectories[0], slide_end_s).position.x();

  const std::vector<const Stroke*> trace = strokesOf(picture, ballColour(shot.ball_set, "cue"));
  ASSERT_GE(trace.size(), 3u);  // several dashes, then the solid rolling part
  const double on_m = kDashOn_px * options.pixel_size_m;
  for (std::size_t i = 0; i + 1 < trace.size(); ++i) {
    const std::vector<Eigen::Vector2d>& dash = trace[i]->points_m;
    EXPECT_LE((dash.back() - dash.front()).norm(), on_m + kPositionTolerance_m) << "dash " << i;
    EXPECT_LE(dash.back().x(), slide_end_x + kPositionTolerance_m);
  }
  EXPECT_NEAR(trace.back()->points_m.front().x(), slide_end_x, kPositionTolerance_m);
  EXPECT_GT(trace.back()->points_m.back().x() - slide_end_x, on_m);  // rolls on, solid
}

TEST(ShotPicture, AtATimeTheBallStandsThereAndTheTraceStopsThere) {
  const double R = engine::builtinBallSet("pool").radius_m;
  const ShotRecord shot = loneBalls({{"11", rollingAlongX(0.0, -0.4, 0.8, R)}});
  PictureOptions options;
  options.time_s = 1.0;
  const Picture picture = buildShotPicture(shot, options);
  const Eigen::Vector2d at =
      engine::sampleTrajectory(shot.cloth, shot.trajectories[0], 1.0).position;
  const std::vector<const Disc*> balls = discsOf(picture, DiscStyle::StripedBall);  // 11: striped
  ASSERT_EQ(balls.size(), 1u);
  EXPECT_NEAR((balls[0]->centre_m.head<2>() - at).norm(), 0, kPositionTolerance_m);
  const std::vector<const Stroke*> trace = strokesOf(picture, ballColour(shot.ball_set, "11"));
  ASSERT_EQ(trace.size(), 1u);
  EXPECT_NEAR((trace[0]->points_m.back() - at).norm(), 0, kPositionTolerance_m);
  // A striped ball's trace carries a white core along the same points.
  const std::vector<const Stroke*> core = strokesOf(picture, colourFromHex("#ffffff"));
  ASSERT_EQ(core.size(), 1u);
  EXPECT_EQ(core[0]->points_m, trace[0]->points_m);
  EXPECT_LT(core[0]->width_m, trace[0]->width_m);
}

TEST(ShotPicture, NineBallBreakHasAMarkerPerEventAndABallPerBallLeft) {
  const engine::Scene scene =
      engine::loadScene(engine::assetsDirectory() + "/scenes/9-ball-break.json");
  const engine::SceneRun run = engine::runScene(scene, /*record_trajectories=*/true);
  const ShotRecord shot = shotRecordOf(scene, run);
  const Picture picture = buildShotPicture(shot, PictureOptions{});
  std::size_t ball_ball = 0, cushion = 0, pocket = 0;
  for (const engine::Event& e : run.result.events) {
    ball_ball += e.kind == engine::EventKind::BallBall;
    cushion += e.kind == engine::EventKind::Cushion || e.kind == engine::EventKind::Jaw;
    pocket += e.kind == engine::EventKind::Pocket;
  }
  std::size_t seen_ball_ball = 0, seen_cushion = 0, seen_pocket = 0;
  for (const DrawItem& item : picture.items) {
    const Disc* d = std::get_if<Disc>(&item);
    if (d == nullptr) continue;
    seen_ball_ball += d->style == DiscStyle::Ring && d->colour == ballBallMarkerColour();
    seen_cushion += d->style == DiscStyle::Flat && d->colour == cushionMarkerColour();
    seen_pocket += d->style == DiscStyle::Ring && d->colour == pocketMarkerColour();
  }
  EXPECT_EQ(seen_ball_ball, ball_ball);
  EXPECT_EQ(seen_cushion, cushion);
  EXPECT_EQ(seen_pocket, pocket);
  EXPECT_GT(pocket, 0u);

  std::vector<Eigen::Vector2d> left;
  for (const engine::BallRecord& b : run.result.final_balls) {
    if (!b.pocketed) left.push_back(b.state.position);
  }
  std::vector<const Disc*> balls = discsOf(picture, DiscStyle::Ball);
  for (const Disc* d : discsOf(picture, DiscStyle::StripedBall)) balls.push_back(d);
  ASSERT_EQ(balls.size(), left.size());
  for (const Disc* d : balls) {  // pool balls carry their number; the cue ball none
    const bool is_cue = d->colour == ballColour(shot.ball_set, "cue");
    EXPECT_EQ(d->label.empty(), is_cue) << d->label;
    if (!is_cue) {
      EXPECT_EQ(d->colour, ballColour(shot.ball_set, d->label));
    }
  }
  for (const Eigen::Vector2d& p : left) {
    double nearest = 1e9;
    for (const Disc* d : balls) nearest = std::min(nearest, (d->centre_m.head<2>() - p).norm());
    EXPECT_LT(nearest, kPositionTolerance_m);
  }
}

TEST(ShotPicture, LegendGivesEachMovingBallItsFirstSpeedAndSpin) {
  const double R = engine::builtinBallSet("pool").radius_m;
  physics::BallState topspin = rollingAlongX(-0.5, 0.0, 0.5, R);  // rolling: roll = v / R
  topspin.angular_velocity.z() = -3.0;
  const ShotRecord shot = loneBalls({{"cue", topspin},
                                     {"5", rollingAlongX(0.5, 0.3, 0.01, R)},  // nudged
                                     {"8", physics::BallState{}}});            // never moves
  PictureOptions options;
  EXPECT_TRUE(buildShotPicture(shot, options).legend.empty());
  options.legend = true;
  const Picture picture = buildShotPicture(shot, options);
  ASSERT_EQ(picture.legend.size(), 4u);  // cue, the nudged line, the two key lines
  EXPECT_TRUE(picture.legend[0].swatch);
  EXPECT_EQ(picture.legend[0].colour, ballColour(shot.ball_set, "cue"));
  // 0.5 / 0.028575 = 17.5 rad/s rounds to 17 or 18; check the exact text.
  std::ostringstream roll;
  roll << std::fixed << std::setprecision(0) << std::round(0.5 / R);
  EXPECT_EQ(picture.legend[0].text, "cue: 0.50 m/s, roll " + roll.str() + " rad/s, side -3 rad/s");
  EXPECT_FALSE(picture.legend[1].swatch);
  EXPECT_EQ(picture.legend[1].text.rfind("1 more ball nudged", 0), 0u) << picture.legend[1].text;
  EXPECT_FALSE(legendText("8", shot.trajectories[2]).has_value());
  EXPECT_DOUBLE_EQ(firstSpeed(shot.trajectories[1]), 0.01);
}

TEST(ShotPicture, BadOptionsAreRefused) {
  const double R = engine::builtinBallSet("pool").radius_m;
  const ShotRecord shot = loneBalls({{"1", rollingAlongX(0, 0, 0.3, R)}});
  PictureOptions options;
  options.time_s = -1;
  EXPECT_THROW(buildShotPicture(shot, options), std::invalid_argument);
  options.time_s = std::nan("");
  EXPECT_THROW(buildShotPicture(shot, options), std::invalid_argument);
  options = PictureOptions{};
  options.pixel_size_m = 0;
  EXPECT_THROW(buildShotPicture(shot, options), std::invalid_argument);
}

}  // namespace
}  // namespace baize::render
