// Tests of the ball's own parameter group: its energy is physics::kineticEnergy's to the bit.
#include "engine/sim/ball_properties.h"

#include <gtest/gtest.h>

namespace baize::engine {
namespace {

TEST(BallProperties, KineticEnergyIsThePhysicsOnesToTheBit) {
  BallProperties ball;
  ball.mass_kg = 0.1406;
  ball.radius_m = 0.02625;
  physics::CushionParams same;
  same.mass_kg = ball.mass_kg;
  same.radius_m = ball.radius_m;
  const physics::BallVelocity v{{1.3, -0.2, 0}, {7, 41, -3}};
  EXPECT_EQ(kineticEnergy(ball, v), physics::kineticEnergy(same, v));
  EXPECT_EQ(BallProperties::kInertiaFactor, 2.0 / 5.0);
}

}  // namespace
}  // namespace baize::engine
