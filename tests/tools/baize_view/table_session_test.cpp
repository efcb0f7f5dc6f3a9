#include "tools/baize_view/table_session.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <limits>

namespace baize::tools {
namespace {

// Headings come from atan2 of metre-sized differences: rounding ~1e-15 rad.
constexpr double kAngleTolerance_rad = 1e-12;
constexpr double kPositionTolerance_m = 1e-12;

engine::Scene shippedScene(const std::string& name) {
  return engine::loadScene(engine::assetsDirectory() + "/scenes/" + name + ".json");
}

int indexOf(const render::ShotRecord& shot, const std::string& id) {
  for (std::size_t i = 0; i < shot.ball_ids.size(); ++i) {
    if (shot.ball_ids[i] == id) return static_cast<int>(i);
  }
  return -1;
}

TEST(TableSession, StrikingAgainStartsFromWhereTheBallsCameToRest) {
  TableSession session(shippedScene("9-ball-break"));
  session.advanceTo(std::numeric_limits<double>::infinity());
  ASSERT_TRUE(session.atRest());
  const render::ShotRecord first = session.shot();
  const Eigen::Vector2d cue_rest = session.cueBallAtRest();
  session.aimAt(cue_rest + Eigen::Vector2d(0, 1));  // straight along +y
  EXPECT_NEAR(session.cue().heading_rad, M_PI / 2, kAngleTolerance_rad);
  session.changeSpeed(-100);
  EXPECT_DOUBLE_EQ(session.cue().speed_mps, kMinCueSpeed_mps);
  session.moveTip(0, 0);
  ASSERT_FALSE(session.strike().has_value());

  session.advanceTo(std::numeric_limits<double>::infinity());
  const render::ShotRecord& second = session.shot();
  std::size_t left = 0;
  for (std::size_t i = 0; i < first.ball_ids.size(); ++i) {
    const bool pocketed = first.trajectories[i].back().pocketed;
    const int j = indexOf(second, first.ball_ids[i]);
    if (pocketed && first.ball_ids[i] != "cue") {
      EXPECT_EQ(j, -1) << first.ball_ids[i] << " was pocketed and stays off the table";
      continue;
    }
    ++left;
    ASSERT_GE(j, 0);
    const Eigen::Vector2d rest =
        engine::sampleTrajectory(first.cloth, first.trajectories[i], first.end_time_s).position;
    EXPECT_NEAR((second.trajectories[j].front().state.position - rest).norm(), 0,
                kPositionTolerance_m);
  }
  EXPECT_EQ(second.ball_ids.size(), left);
  // The cue ball leaves along the aim (a centre hit: no squirt).
  const Eigen::Vector3d v = second.trajectories[indexOf(second, "cue")].front().state.velocity;
  EXPECT_NEAR(std::atan2(v.y(), v.x()), M_PI / 2, kAngleTolerance_rad);
}

// The shot on show is stepped as the clock runs: at each time it holds exactly the events up to
// then, and stepped to the end it is the run to rest, bit for bit.
TEST(TableSession, TheShotIsSteppedAsTheClockRunsAndEndsAsTheRunToRest) {
  const engine::Scene scene = shippedScene("9-ball-break");
  const engine::SceneRun run = engine::runScene(scene, /*record_trajectories=*/true);
  TableSession session(scene);
  EXPECT_TRUE(session.shot().events.empty());
  for (double t = 0.05; !session.atRest(); t += 0.05) {
    session.advanceTo(t);
    std::size_t due = 0;
    while (due < run.result.events.size() && run.result.events[due].time_s <= t) ++due;
    ASSERT_EQ(session.shot().events.size(), due) << "at t = " << t;
    if (!session.atRest()) {
      EXPECT_EQ(session.shot().end_time_s, t);
    }
  }
  EXPECT_FALSE(session.failure().has_value());
  const render::ShotRecord& shot = session.shot();
  EXPECT_EQ(shot.end_time_s, run.result.end_time_s);
  ASSERT_EQ(shot.trajectories.size(), run.result.trajectories.size());
  for (std::size_t i = 0; i < shot.trajectories.size(); ++i) {
    ASSERT_EQ(shot.trajectories[i].size(), run.result.trajectories[i].size());
    for (std::size_t k = 0; k < shot.trajectories[i].size(); ++k) {
      const auto& a = shot.trajectories[i][k];
      const auto& b = run.result.trajectories[i][k];
      EXPECT_EQ(std::memcmp(&a.start_time_s, &b.start_time_s, sizeof(double)), 0);
      EXPECT_EQ(std::memcmp(a.state.position.data(), b.state.position.data(), 2 * sizeof(double)),
                0);
      EXPECT_EQ(std::memcmp(a.state.velocity.data(), b.state.velocity.data(), 3 * sizeof(double)),
                0);
      EXPECT_EQ(a.pocketed, b.pocketed);
    }
  }
}

// A shot the event loop cannot finish stops where it failed and says why.
TEST(TableSession, AShotThatFailsStopsAndSaysWhy) {
  engine::Scene scene = shippedScene("9-ball-break");
  scene.overrides.max_events = 20;
  TableSession session(scene);
  session.advanceTo(std::numeric_limits<double>::infinity());
  EXPECT_TRUE(session.atRest());
  ASSERT_TRUE(session.failure().has_value());
  EXPECT_NE(session.failure()->find("max_events = 20"), std::string::npos) << *session.failure();
}

TEST(TableSession, TipOffsetStaysInsideTheMiscueLimit) {
  TableSession session(shippedScene("stun-shot"));
  session.moveTip(100, 100);
  EXPECT_NEAR(std::hypot(session.cue().side_offset, session.cue().height_offset), kMaxTipOffset_R,
              1e-12);
  EXPECT_GT(session.cue().side_offset, 0);
  EXPECT_GT(session.cue().height_offset, 0);
}

}  // namespace
}  // namespace baize::tools
