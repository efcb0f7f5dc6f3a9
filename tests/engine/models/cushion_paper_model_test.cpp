// Tests of cushion model "paper": it gives exactly the paper scheme's result, agrees with the exact
// solver through the event loop to its first-order error, fails a shot whose impact gains energy,
// and refuses a step count below 1.
#include "engine/models/cushion_paper_model.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "engine/models/model_registry.h"
#include "physics/cushion_paper_solver.h"
#include "tests/engine/error_test_support.h"
#include "tests/engine/models/model_test_support.h"

namespace baize::engine {
namespace {

using physics::BallState;
using physics::BallVelocity;

// The paper scheme's error bound in units of V0 / N. One Euler increment dP = (1 + e) M v_y0 / N
// changes a velocity component by at most |dv/dP| dP <= 1.4 (1 + e) v_y0 / N, about 2.8 V0 / N (R w
// by less), and the scheme stops up to one increment past its end; the Euler drift is smaller
// (this case measures 1.4 at N = 200 and 0.8 at N = 2000). 4 is that increment with room.
constexpr double kPaperErrorPerStep = 4.0;

double largestVelocityDifference(const BallState& a, const BallState& b, double radius_m) {
  return std::max((a.velocity - b.velocity).cwiseAbs().maxCoeff(),
                  radius_m * (a.angular_velocity - b.angular_velocity).cwiseAbs().maxCoeff());
}

TEST(CushionPaperModel, GivesThePaperSchemesResultExactly) {
  SimulationParams p = poolSimulationParams();
  p.cushion = cushionModel({{"model", "paper"}, {"paper_steps", 700}});
  const BallVelocity in = physics::incomingBall(1.7, 0.9, 40, -25);
  physics::CushionParams direct_params;
  direct_params.mass_kg = p.ball.mass_kg;
  direct_params.radius_m = p.ball.radius_m;
  direct_params.contact_height_m = 0.635 * 2 * p.ball.radius_m;
  direct_params.cloth_friction = p.cloth.sliding_friction;
  physics::PaperSolverOptions options;
  options.steps = 700;
  const BallVelocity paper = p.cushion->resolve(p, in);
  const BallVelocity direct = physics::solveCushionImpactPaper(direct_params, in, options).after;
  EXPECT_EQ(paper.v, direct.v);
  EXPECT_EQ(paper.w, direct.w);
  EXPECT_STREQ(p.cushion->name(), "paper");
  EXPECT_TRUE(p.cushion->worthSolvingAhead());
  EXPECT_EQ(p.cushion->parametersJson()["paper_steps"], 700);
}

// The same angled hit with spin through the loop: the paper scheme's rebound differs from the exact
// solver's by at most kPaperErrorPerStep V0 / N, and by less with ten times the steps.
TEST(CushionPaperModel, AgreesWithTheExactSolverToItsFirstOrderError) {
  SimulationParams p = poolSimulationParams();
  const double R = p.ball.radius_m;
  BallState ball = rollingBallAt(0.3, 0.1, 1.5, 0.6, R);
  ball.angular_velocity.z() = 30;  // sidespin, so both contacts slip in changing directions
  const TableGeometry table = rectangularTable(2.0, 1.0);

  const Event exact = firstEventOf(simulate(p, table, {ball}), EventKind::Cushion);
  const double V0 = exact.before[0].velocity.norm();
  double previous_error = 0;
  for (int steps : {200, 2000}) {
    p.cushion = cushionModel({{"model", "paper"}, {"paper_steps", steps}});
    const Event paper = firstEventOf(simulate(p, table, {ball}), EventKind::Cushion);
    ASSERT_EQ(paper.index, exact.index);
    EXPECT_EQ(paper.before[0].velocity, exact.before[0].velocity) << "same path up to the hit";
    const double error = largestVelocityDifference(paper.after[0], exact.after[0], R);
    EXPECT_LE(error, kPaperErrorPerStep * V0 / steps) << steps << " steps";
    if (previous_error > 0) {
      EXPECT_LT(error, previous_error) << "more steps, smaller error";
    }
    previous_error = error;
  }
}

// Too few increments can make the paper scheme hand back more energy than the ball brought (one
// increment gives a rolling ball at 1.5 m/s, 30 degrees, almost twice its energy): the shot fails
// saying so and naming the key, instead of going on from a state no impact makes.
TEST(CushionPaperModel, AnImpactThatGainsEnergyFailsTheShot) {
  SimulationParams p = poolSimulationParams();
  const double R = p.ball.radius_m;
  const BallVelocity in = physics::incomingBall(1.5, 30 * M_PI / 180, 1.5 / R, 0);
  p.cushion = cushionModel({{"model", "paper"}, {"paper_steps", 1}});
  try {
    p.cushion->resolve(p, in);
    ADD_FAILURE() << "no error";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("physics.cushion.paper_steps = 1: the paper scheme made a "
                                         "cushion impact gain energy"),
              std::string::npos)
        << e.what();
  }
  p.cushion = cushionModel({{"model", "paper"}});  // the paper's own N
  const BallVelocity out = p.cushion->resolve(p, in);
  EXPECT_LT(kineticEnergy(p.ball, out), kineticEnergy(p.ball, in));
}

TEST(CushionPaperModel, AStepCountBelowOneIsRefusedNamingTheValue) {
  SimulationParams p = poolSimulationParams();
  const std::vector<BallState> ball = {rollingBallAt(0, 0, 1, 0, p.ball.radius_m)};
  Mathavan2010Cushion cushion;
  cushion.contact_height_m = 0.036;
  p.cushion = std::make_shared<const PaperCushionModel>(cushion, 0);
  const std::string steps =
      invalidArgumentMessage([&] { simulate(p, rectangularTable(2, 1), ball); });
  EXPECT_MENTIONS(steps, "paper solver steps = 0 is not allowed");
}

}  // namespace
}  // namespace baize::engine
