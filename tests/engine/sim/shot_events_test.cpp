#include "engine/sim/shot_events.h"

#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>
#include <string>

namespace baize::engine {
namespace {

TEST(ShotEvents, EveryEventKindHasItsName) {
  EXPECT_STREQ(eventKindName(EventKind::StateChange), "state change");
  EXPECT_STREQ(eventKindName(EventKind::BallBall), "ball-ball");
  EXPECT_STREQ(eventKindName(EventKind::Cushion), "cushion");
  EXPECT_STREQ(eventKindName(EventKind::Jaw), "jaw");
  EXPECT_STREQ(eventKindName(EventKind::Pocket), "pocket");
}

// A trajectory is sampled from the last piece that starts at or before the time; a pocketed
// piece stays where the ball fell.
TEST(ShotEvents, ATrajectoryIsSampledFromThePieceInForce) {
  const physics::ClothParams cloth = physics::poolCloth();
  physics::BallState start;
  start.velocity = Eigen::Vector3d(1, 0, 0);
  start.angular_velocity = Eigen::Vector3d(0, 1 / cloth.radius_m, 0);  // rolling
  physics::BallState second = physics::advance(cloth, start, 0.5);
  second.velocity = -second.velocity;
  second.angular_velocity = -second.angular_velocity;
  physics::BallState fallen = physics::advance(cloth, second, 0.25);
  const Trajectory path = {{0, start, false}, {0.5, second, false}, {0.75, fallen, true}};
  EXPECT_EQ(sampleTrajectory(cloth, path, 0.25).position,
            physics::advance(cloth, start, 0.25).position);
  EXPECT_EQ(sampleTrajectory(cloth, path, 0.5).position, second.position);
  EXPECT_EQ(sampleTrajectory(cloth, path, 0.6).position,
            physics::advance(cloth, second, 0.1).position);
  EXPECT_EQ(sampleTrajectory(cloth, path, 10).position, fallen.position);
}

TEST(ShotEvents, BadSampleTimesAndEmptyTrajectoriesAreRefused) {
  const physics::ClothParams cloth = physics::poolCloth();
  const Trajectory path = {{0, physics::BallState{}, false}};
  EXPECT_THROW(sampleTrajectory(cloth, {}, 0), std::invalid_argument);
  for (double t : {-1.0, std::nan(""), static_cast<double>(INFINITY)}) {
    try {
      sampleTrajectory(cloth, path, t);
      ADD_FAILURE() << "t = " << t << " was accepted";
    } catch (const std::invalid_argument& e) {
      EXPECT_NE(std::string(e.what()).find("sample time"), std::string::npos) << e.what();
    }
  }
}

}  // namespace
}  // namespace baize::engine
