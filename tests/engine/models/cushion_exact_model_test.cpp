// Tests of cushion model "exact": it gives exactly the event-located solver's result with the
// shot's ball and cloth, echoes its parameters, and refuses a tolerance out of range.
#include "engine/models/cushion_exact_model.h"

#include <gtest/gtest.h>

#include "engine/models/model_registry.h"
#include "tests/engine/error_test_support.h"
#include "tests/engine/models/model_test_support.h"

namespace baize::engine {
namespace {

using physics::BallVelocity;

TEST(CushionExactModel, GivesTheSolversResultWithTheShotsBallAndCloth) {
  SimulationParams p = poolSimulationParams();
  p.ball.mass_kg = 0.16;
  p.cloth.sliding_friction = 0.25;
  p.cushion = cushionModel({{"model", "exact"}, {"restitution", 0.95}, {"tolerance", 1e-12}});
  const BallVelocity in = physics::incomingBall(1.7, 0.9, 40, -25);
  physics::CushionParams direct_params;
  direct_params.mass_kg = 0.16;
  direct_params.radius_m = p.ball.radius_m;
  direct_params.contact_height_m = ModelDefaults{}.cushion_contact_height_m;
  direct_params.restitution = 0.95;
  direct_params.cloth_friction = 0.25;
  physics::ExactSolverOptions options;
  options.tolerance = 1e-12;
  const BallVelocity direct = physics::solveCushionImpactExact(direct_params, in, options).after;
  const BallVelocity model = p.cushion->resolve(p, in);
  EXPECT_EQ(model.v, direct.v);
  EXPECT_EQ(model.w, direct.w);
  EXPECT_TRUE(p.cushion->worthSolvingAhead());
  EXPECT_EQ(p.cushion->rigidContact(p).contact_sin_theta, physics::contactSinTheta(direct_params));
}

TEST(CushionExactModel, EchoesEveryParameterUnderItsSceneKey) {
  const auto model = cushionModel({{"model", "exact"}, {"friction", 0.12}, {"contact_height_m", 0.04}});
  const nlohmann::json expected = {{"model", "exact"},
                                   {"restitution", 0.98},
                                   {"friction", 0.12},
                                   {"contact_height_m", 0.04},
                                   {"tolerance", 3e-11}};
  EXPECT_EQ(model->parametersJson(), expected);
  EXPECT_EQ(cushionModel(model->parametersJson())->parametersJson(), expected) << "reads back";
}

TEST(CushionExactModel, ATolerancesOutOfRangeIsRefused) {
  SimulationParams p = poolSimulationParams();
  p.cushion = cushionModel({{"model", "exact"}, {"tolerance", 0.5}});
  EXPECT_MENTIONS(invalidArgumentMessage([&] { p.cushion->validate(p); }),
                  "exact solver tolerance = 0.5");
}

}  // namespace
}  // namespace baize::engine
