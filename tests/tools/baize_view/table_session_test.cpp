#include "tools/baize_view/table_session.h"

#include <gtest/gtest.h>

#include <cmath>

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
  const render::ShotRecord first = session.shot();
  const Eigen::Vector2d cue_rest = session.cueBallAtRest();
  session.aimAt(cue_rest + Eigen::Vector2d(0, 1));  // straight along +y
  EXPECT_NEAR(session.cue().heading_rad, M_PI / 2, kAngleTolerance_rad);
  session.changeSpeed(-100);
  EXPECT_DOUBLE_EQ(session.cue().speed_mps, kMinCueSpeed_mps);
  session.moveTip(0, 0);
  ASSERT_FALSE(session.strike().has_value());

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
