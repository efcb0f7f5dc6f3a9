// Tests of cushion model "tabulated", the default: it takes the exact model's keys, echoes them
// under its own name, and with a scene's overrides still answers within 1e-8 V0 of the exact
// model with the same overrides.
#include "engine/models/cushion_tabulated_model.h"

#include <gtest/gtest.h>

#include "engine/models/model_registry.h"
#include "tests/engine/models/model_test_support.h"

namespace baize::engine {
namespace {

using physics::BallVelocity;

double difference(const BallVelocity& a, const BallVelocity& b, double radius_m) {
  return std::max((a.v - b.v).cwiseAbs().maxCoeff(), radius_m * (a.w - b.w).cwiseAbs().maxCoeff());
}

TEST(CushionTabulatedModel, IsTheDefaultAndEchoesItsParameters) {
  EXPECT_STREQ(poolSimulationParams().cushion->name(), "tabulated");
  const auto model = cushionModel({{"restitution", 0.9}, {"friction", 0.1}});
  EXPECT_EQ(model->parametersJson()["model"], "tabulated");
  EXPECT_EQ(model->parametersJson()["restitution"], 0.9);
  EXPECT_EQ(model->parametersJson()["friction"], 0.1);
  EXPECT_EQ(cushionModel(model->parametersJson())->parametersJson(), model->parametersJson())
      << "reads back";
  EXPECT_TRUE(model->worthSolvingAhead());
}

TEST(CushionTabulatedModel, OverriddenParametersGiveTheExactModelsAnswers) {
  for (const nlohmann::json& overrides :
       {nlohmann::json{{"restitution", 0.85}, {"friction", 0.2}},
        nlohmann::json{{"contact_height_m", 0.037}}}) {
    SimulationParams tabulated = poolSimulationParams();
    tabulated.cushion = cushionModel(overrides);
    SimulationParams exact = tabulated;
    nlohmann::json exact_group = overrides;
    exact_group["model"] = "exact";
    exact.cushion = cushionModel(exact_group);
    const double speed = 1.1, radius = tabulated.ball.radius_m;
    // Rolling (from the table) and sliding (exact on both paths).
    for (const double topspin : {speed / radius, 0.0}) {
      const BallVelocity in = physics::incomingBall(speed, 1.1, topspin, 0.3 * speed / radius);
      EXPECT_LE(difference(tabulated.cushion->resolve(tabulated, in),
                           exact.cushion->resolve(exact, in), radius),
                1e-8 * speed)
          << overrides.dump() << " topspin " << topspin;
    }
  }
}

}  // namespace
}  // namespace baize::engine
