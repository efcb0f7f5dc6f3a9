// Tests of ball-ball model "frictional": the physics model's result with the shot's ball and cloth,
// the friction law's keys refused with the other law, and the echo reading back.
#include "engine/models/ball_ball_frictional_model.h"

#include <gtest/gtest.h>

#include "engine/models/model_registry.h"
#include "tests/engine/error_test_support.h"
#include "tests/engine/models/model_test_support.h"

namespace baize::engine {
namespace {

TEST(BallBallFrictionalModel, GivesThePhysicsModelsResultWithTheShotsBall) {
  SimulationParams p = poolSimulationParams();
  p.ball.mass_kg = 0.16;
  p.ball_ball = ballBallModel({{"friction_law", "constant"}, {"constant_friction", 0.05}});
  physics::BallBallParams direct;
  direct.mass1_kg = direct.mass2_kg = 0.16;
  direct.radius_m = p.ball.radius_m;
  direct.cloth_friction = p.cloth.sliding_friction;
  direct.friction_law = physics::BallBallFrictionLaw::Constant;
  direct.constant_friction = 0.05;
  const physics::BallVelocity a{{1.2, 0.1, 0}, {3, -40, 5}}, b{{0, 0, 0}, {0, 0, 0}};
  const Eigen::Vector3d normal(1, 0, 0);
  const physics::BallBallImpactResult model = p.ball_ball->resolve(p, a, b, normal);
  const physics::BallBallImpactResult physics_result =
      physics::resolveBallBallImpact(direct, a, b, normal);
  EXPECT_EQ(model.ball1.v, physics_result.ball1.v);
  EXPECT_EQ(model.ball2.w, physics_result.ball2.w);
  EXPECT_EQ(p.ball_ball->rigidContact(p, 1.0).friction, 0.05);
}

TEST(BallBallFrictionalModel, TheOtherLawsKeysAreRefused) {
  EXPECT_MENTIONS(invalidArgumentMessage([] {
                    ballBallModel({{"friction_law", "constant"}, {"friction_fit_a", 0.01}});
                  }),
                  "physics.ball_ball.friction_fit_a = 0.01 is not allowed: it applies only to "
                  "model \"frictional\" with friction_law \"alciatore\"");
  EXPECT_MENTIONS(invalidArgumentMessage([] {
                    ballBallModel({{"friction_law", "coulomb"}});
                  }),
                  "\"alciatore\" or \"constant\"");
}

TEST(BallBallFrictionalModel, TheEchoReadsBack) {
  const auto model = ballBallModel({{"restitution", 0.9}});
  const nlohmann::json echo = model->parametersJson();
  EXPECT_EQ(echo["model"], "frictional");
  EXPECT_EQ(echo["friction_law"], "alciatore");
  EXPECT_EQ(ballBallModel(echo)->parametersJson(), echo);
}

}  // namespace
}  // namespace baize::engine
