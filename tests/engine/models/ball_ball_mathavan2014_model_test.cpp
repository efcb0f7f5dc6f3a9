// Tests of ball-ball model "mathavan2014": the physics model's result with the shot's ball and
// cloth, its rigid friction mu_b, and the echo reading back.
#include "engine/models/ball_ball_mathavan2014_model.h"

#include <gtest/gtest.h>

#include "engine/models/model_registry.h"
#include "tests/engine/error_test_support.h"
#include "tests/engine/models/model_test_support.h"

namespace baize::engine {
namespace {

TEST(BallBallMathavan2014Model, GivesThePhysicsModelsResultWithTheShotsBallAndCloth) {
  SimulationParams p = poolSimulationParams();
  p.cloth.sliding_friction = 0.25;
  p.ball_ball = ballBallModel({{"model", "mathavan2014"}, {"ball_friction", 0.06}});
  physics::BallBallParams direct;
  direct.model = physics::BallBallModel::Mathavan2014;
  direct.mass1_kg = direct.mass2_kg = p.ball.mass_kg;
  direct.radius_m = p.ball.radius_m;
  direct.cloth_friction = 0.25;
  direct.ball_friction = 0.06;
  const physics::BallVelocity a{{1.2, 0.1, 0}, {3, -40, 5}}, b{{0, 0, 0}, {0, 0, 0}};
  const Eigen::Vector3d normal(1, 0, 0);
  const physics::BallBallImpactResult model = p.ball_ball->resolve(p, a, b, normal);
  const physics::BallBallImpactResult physics_result =
      physics::resolveBallBallImpact(direct, a, b, normal);
  EXPECT_EQ(model.ball1.v, physics_result.ball1.v);
  EXPECT_EQ(model.ball2.w, physics_result.ball2.w);
  EXPECT_EQ(p.ball_ball->rigidContact(p, 1.0).friction, 0.06);
  EXPECT_STREQ(p.ball_ball->name(), "mathavan2014");
}

TEST(BallBallMathavan2014Model, TheEchoReadsBackAndBadValuesAreRefused) {
  const auto model = ballBallModel({{"model", "mathavan2014"}, {"tolerance", 1e-10}});
  const nlohmann::json echo = model->parametersJson();
  EXPECT_EQ(echo["tolerance"], 1e-10);
  EXPECT_EQ(ballBallModel(echo)->parametersJson(), echo);
  SimulationParams p = poolSimulationParams();
  p.ball_ball = ballBallModel({{"model", "mathavan2014"}, {"ball_friction", -1}});
  EXPECT_MENTIONS(invalidArgumentMessage([&] { p.ball_ball->validate(p); }), "= -1");
}

}  // namespace
}  // namespace baize::engine
