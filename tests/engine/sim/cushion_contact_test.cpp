// Tests of the cushion model dispatch: each choice gives exactly its physics model's result, the
// choice reaches every cushion hit of the event loop (the simple rule's head-on rebound is e times
// the incoming speed through simulate()), the paper scheme agrees with the exact solver to its
// first-order error, and bad options are refused.
#include "engine/sim/cushion_contact.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "engine/sim/shot_simulator.h"
#include "physics/cushion_exact_solver.h"
#include "physics/cushion_paper_solver.h"
#include "physics/cushion_simple_model.h"
#include "tests/engine/error_test_support.h"

namespace baize::engine {
namespace {

using physics::BallState;
using physics::BallVelocity;

// Closed-form speeds through the loop (a frame rotation there and back): rounding, relative.
constexpr double kClosedFormRelative = 1e-12;
// The paper scheme's error bound in units of V0 / N. One Euler increment dP = (1 + e) M v_y0 / N
// changes a velocity component by at most |dv/dP| dP <= 1.4 (1 + e) v_y0 / N, about 2.8 V0 / N (R w
// by less), and the scheme stops up to one increment past its end; the Euler drift is smaller
// (this case measures 1.4 at N = 200 and 0.8 at N = 2000). 4 is that increment with room.
constexpr double kPaperErrorPerStep = 4.0;

BallState rollingBallAt(double x, double y, double vx, double vy, double radius_m) {
  BallState b;
  b.position = {x, y};
  b.velocity = {vx, vy, 0};
  b.angular_velocity = {-vy / radius_m, vx / radius_m, 0};  // rolling: v + R z x w = 0
  return b;
}

const Event& firstCushionHit(const SimulationResult& r) {
  const auto hit = std::find_if(r.events.begin(), r.events.end(),
                                [](const Event& e) { return e.kind == EventKind::Cushion; });
  if (hit == r.events.end()) throw std::logic_error("no cushion hit");
  return *hit;
}

double largestVelocityDifference(const BallState& a, const BallState& b, double radius_m) {
  return std::max((a.velocity - b.velocity).cwiseAbs().maxCoeff(),
                  radius_m * (a.angular_velocity - b.angular_velocity).cwiseAbs().maxCoeff());
}

TEST(CushionContact, EachChoiceGivesItsModelsResultExactly) {
  SimulationParams p = poolSimulationParams();
  p.cushion_paper_steps = 700;
  p.cushion_simple.restitution = 0.85;
  const BallVelocity in = physics::incomingBall(1.7, 0.9, 40, -25);

  p.cushion_model = CushionModelChoice::Mathavan2010Exact;
  const BallVelocity exact = resolveCushionContact(p, in);
  const BallVelocity exact_direct =
      physics::solveCushionImpactExact(p.cushion, in, p.cushion_solver).after;
  EXPECT_EQ(exact.v, exact_direct.v);
  EXPECT_EQ(exact.w, exact_direct.w);

  p.cushion_model = CushionModelChoice::Mathavan2010Paper;
  physics::PaperSolverOptions options;
  options.steps = 700;
  const BallVelocity paper = resolveCushionContact(p, in);
  const BallVelocity paper_direct = physics::solveCushionImpactPaper(p.cushion, in, options).after;
  EXPECT_EQ(paper.v, paper_direct.v);
  EXPECT_EQ(paper.w, paper_direct.w);

  p.cushion_model = CushionModelChoice::SimpleRestitution;
  const BallVelocity simple = resolveCushionContact(p, in);
  EXPECT_EQ(simple.v, physics::simpleCushionRebound(p.cushion_simple, in).v);
  EXPECT_EQ(simple.w, in.w);
}

// A rolling ball meets the right-hand cushion head-on: with the simple rule it leaves at exactly
// e times its incoming speed, straight back, spin unchanged.
TEST(CushionContact, SimpleRuleHeadOnReboundIsETimesTheIncomingSpeedThroughTheLoop) {
  SimulationParams p = poolSimulationParams();
  p.cushion_model = CushionModelChoice::SimpleRestitution;
  p.cushion_simple.restitution = 0.7;
  const double R = p.cushion.radius_m;
  const SimulationResult r =
      simulate(p, rectangularTable(2.0, 1.0), {rollingBallAt(0.5, 0, 1.2, 0, R)});
  const Event& hit = firstCushionHit(r);
  const double V = hit.before[0].velocity.x();
  ASSERT_GT(V, 0);
  EXPECT_NEAR(hit.after[0].velocity.x(), -0.7 * V, kClosedFormRelative * V);
  EXPECT_NEAR(hit.after[0].velocity.y(), 0, kClosedFormRelative * V);
  EXPECT_NEAR((hit.after[0].angular_velocity - hit.before[0].angular_velocity).norm(), 0,
              kClosedFormRelative * V / R);
}

// The same angled hit with spin through the loop: the paper scheme's rebound differs from the exact
// solver's by at most kPaperErrorPerStep V0 / N, and by less with ten times the steps.
TEST(CushionContact, PaperSchemeAgreesWithTheExactSolverToItsFirstOrderError) {
  SimulationParams p = poolSimulationParams();
  const double R = p.cushion.radius_m;
  BallState ball = rollingBallAt(0.3, 0.1, 1.5, 0.6, R);
  ball.angular_velocity.z() = 30;  // sidespin, so both contacts slip in changing directions
  const TableGeometry table = rectangularTable(2.0, 1.0);

  p.cushion_model = CushionModelChoice::Mathavan2010Exact;
  const Event exact = firstCushionHit(simulate(p, table, {ball}));
  const double V0 = exact.before[0].velocity.norm();
  double previous_error = 0;
  for (int steps : {200, 2000}) {
    p.cushion_model = CushionModelChoice::Mathavan2010Paper;
    p.cushion_paper_steps = steps;
    const Event paper = firstCushionHit(simulate(p, table, {ball}));
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
TEST(CushionContact, APaperImpactThatGainsEnergyFailsTheShot) {
  SimulationParams p = poolSimulationParams();
  p.cushion_model = CushionModelChoice::Mathavan2010Paper;
  const double R = p.cushion.radius_m;
  const BallVelocity in = physics::incomingBall(1.5, 30 * M_PI / 180, 1.5 / R, 0);
  p.cushion_paper_steps = 1;
  try {
    resolveCushionContact(p, in);
    ADD_FAILURE() << "no error";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("physics.cushion.paper_steps = 1: the paper scheme made a "
                                         "cushion impact gain energy"),
              std::string::npos)
        << e.what();
  }
  p.cushion_paper_steps = 5000;  // the paper's own N
  const BallVelocity out = resolveCushionContact(p, in);
  EXPECT_LT(physics::kineticEnergy(p.cushion, out), physics::kineticEnergy(p.cushion, in));
}

TEST(CushionContact, BadOptionsAreRefusedNamingTheValue) {
  SimulationParams p = poolSimulationParams();
  const std::vector<BallState> ball = {rollingBallAt(0, 0, 1, 0, p.cushion.radius_m)};
  p.cushion_model = CushionModelChoice::Mathavan2010Paper;
  p.cushion_paper_steps = 0;
  const std::string steps =
      invalidArgumentMessage([&] { simulate(p, rectangularTable(2, 1), ball); });
  EXPECT_MENTIONS(steps, "paper solver steps = 0 is not allowed");

  p = poolSimulationParams();
  p.cushion_model = CushionModelChoice::SimpleRestitution;
  p.cushion_simple.restitution = 1.5;
  const std::string e = invalidArgumentMessage([&] { simulate(p, rectangularTable(2, 1), ball); });
  EXPECT_MENTIONS(e, "simple cushion restitution e = 1.5");

  p = poolSimulationParams();
  p.cushion_model = static_cast<CushionModelChoice>(7);
  const std::string model = invalidArgumentMessage([&] { validateCushionContactParams(p); });
  EXPECT_MENTIONS(model, "cushion model = 7");
}

TEST(CushionContact, ModelNamesAreTheSceneFileNames) {
  EXPECT_STREQ(cushionModelName(CushionModelChoice::Mathavan2010Exact), "exact");
  EXPECT_STREQ(cushionModelName(CushionModelChoice::Mathavan2010Paper), "paper");
  EXPECT_STREQ(cushionModelName(CushionModelChoice::SimpleRestitution), "simple");
}

}  // namespace
}  // namespace baize::engine
