// Tests of cushion model "tabulated", the default: it takes the exact model's keys, echoes them
// under its own name, and with a scene's overrides still answers within its promise
// (physics::kTabulatedPathPromise) of the exact model with the same overrides.
#include "engine/models/cushion_tabulated_model.h"

#include <gtest/gtest.h>

#include "engine/models/cushion_mathavan2010.h"
#include "engine/models/model_registry.h"
#include "physics/cushion_rolling_surface.h"
#include "physics/cushion_tabulated_solver.h"
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

// The impacts the table leaves are solved at the path's own tolerance unless the scene sets one.
TEST(CushionTabulatedModel, SolvesWhatItsTableLeavesAtItsOwnToleranceUnlessGivenOne) {
  EXPECT_EQ(cushionModel(nlohmann::json::object())->parametersJson()["tolerance"],
            physics::kTabulatedFallbackTolerance);
  EXPECT_GT(physics::kTabulatedFallbackTolerance, physics::ExactSolverOptions{}.tolerance);
  EXPECT_EQ(cushionModel({{"model", "exact"}})->parametersJson()["tolerance"],
            physics::ExactSolverOptions{}.tolerance);
  EXPECT_EQ(cushionModel({{"tolerance", 1e-12}})->parametersJson()["tolerance"], 1e-12);
  // A sliding ball (no table answer) gets the exact solver's answer with the table's fallback
  // options (its tolerance, and its error share and step control, which the exact model's default
  // does not share),
  // and so lies within the path's promise of the exact model's answer at the same tolerance.
  SimulationParams tabulated = poolSimulationParams(), exact = poolSimulationParams();
  exact.cushion =
      cushionModel({{"model", "exact"}, {"tolerance", physics::kTabulatedFallbackTolerance}});
  EXPECT_GT(physics::kTabulatedFallbackErrorShare, physics::ExactSolverOptions{}.min_error_share);
  const double speed = 1.2;
  const physics::BallVelocity sliding =
      physics::incomingBall(speed, 0.9, 0, 0.2 * speed / tabulated.ball.radius_m);
  const physics::CushionParams params =
      impactParams(readMathavan2010(ModelDefaults{}, nullptr), tabulated);
  const physics::BallVelocity a = tabulated.cushion->resolve(tabulated, sliding);
  const physics::BallVelocity b =
      physics::solveCushionImpactExact(params, sliding, physics::tabulatedFallbackOptions()).after;
  EXPECT_EQ(a.v, b.v);
  EXPECT_EQ(a.w, b.w);
  const physics::BallVelocity c = exact.cushion->resolve(exact, sliding);
  EXPECT_NE(a.v, c.v)
      << "the error share and step control make no difference here: the test cannot tell them "
         "apart";
  EXPECT_LE(difference(a, c, tabulated.ball.radius_m), physics::kTabulatedPathPromise * speed);
}

TEST(CushionTabulatedModel, OverriddenParametersGiveTheExactModelsAnswers) {
  for (const nlohmann::json& overrides : {nlohmann::json{{"restitution", 0.85}, {"friction", 0.2}},
                                          nlohmann::json{{"contact_height_m", 0.037}}}) {
    SimulationParams tabulated = poolSimulationParams();
    tabulated.cushion = cushionModel(overrides);
    SimulationParams exact = tabulated;
    nlohmann::json exact_group = overrides;
    exact_group["model"] = "exact";
    exact.cushion = cushionModel(exact_group);
    const double speed = 1.1, radius = tabulated.ball.radius_m;
    // Rolling (from the table, within its promise) and sliding (exact on both paths, with each
    // path's options: within the path's promise).
    for (const double topspin : {speed / radius, 0.0}) {
      const BallVelocity in = physics::incomingBall(speed, 1.1, topspin, 0.3 * speed / radius);
      const double promise =
          topspin > 0 ? physics::kRollingTablePromise : physics::kTabulatedPathPromise;
      EXPECT_LE(difference(tabulated.cushion->resolve(tabulated, in),
                           exact.cushion->resolve(exact, in), radius),
                promise * speed)
          << overrides.dump() << " topspin " << topspin;
    }
  }
}

}  // namespace
}  // namespace baize::engine
