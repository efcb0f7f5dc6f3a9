// Tests of cushion model "simple": through the event loop a head-on rebound is e times the
// incoming speed, it is not worth solving ahead, and a restitution out of (0, 1] is refused.
#include "engine/models/cushion_simple_model.h"

#include <gtest/gtest.h>

#include "engine/models/model_registry.h"
#include "tests/engine/error_test_support.h"
#include "tests/engine/models/model_test_support.h"

namespace baize::engine {
namespace {

// Closed-form speeds through the loop (a frame rotation there and back): rounding, relative.
constexpr double kClosedFormRelative = 1e-12;

// A rolling ball meets the right-hand cushion head-on: it leaves at exactly e times its incoming
// speed, straight back, spin unchanged.
TEST(CushionSimpleModel, HeadOnReboundIsETimesTheIncomingSpeedThroughTheLoop) {
  SimulationParams p = poolSimulationParams();
  p.cushion = cushionModel({{"model", "simple"}, {"simple_restitution", 0.7}});
  EXPECT_FALSE(p.cushion->worthSolvingAhead());
  const double R = p.ball.radius_m;
  const SimulationResult r =
      simulate(p, rectangularTable(2.0, 1.0), {rollingBallAt(0.5, 0, 1.2, 0, R)});
  const Event& hit = firstEventOf(r, EventKind::Cushion);
  const double V = hit.before[0].velocity.x();
  ASSERT_GT(V, 0);
  EXPECT_NEAR(hit.after[0].velocity.x(), -0.7 * V, kClosedFormRelative * V);
  EXPECT_NEAR(hit.after[0].velocity.y(), 0, kClosedFormRelative * V);
  EXPECT_NEAR((hit.after[0].angular_velocity - hit.before[0].angular_velocity).norm(), 0,
              kClosedFormRelative * V / R);
}

TEST(CushionSimpleModel, ARestitutionOutOfRangeIsRefusedAndTheEchoReadsBack) {
  SimulationParams p = poolSimulationParams();
  p.cushion = cushionModel({{"model", "simple"}, {"simple_restitution", 1.5}});
  const std::vector<physics::BallState> ball = {rollingBallAt(0, 0, 1, 0, p.ball.radius_m)};
  EXPECT_MENTIONS(invalidArgumentMessage([&] { simulate(p, rectangularTable(2, 1), ball); }),
                  "simple cushion restitution e = 1.5");
  const nlohmann::json echo = {{"model", "simple"}, {"simple_restitution", 1.5}};
  EXPECT_EQ(p.cushion->parametersJson(), echo);
}

}  // namespace
}  // namespace baize::engine
