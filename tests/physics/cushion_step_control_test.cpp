// Tests of the exact cushion solver's step control: the fast inverse eighth root, the step factor
// and its bounds, the predictive controller's trend, the extrapolated phase end, and the caps on a
// step from the slips (none without friction; each within its definition with it).
#include "physics/cushion_step_control.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "physics/cushion_tabulated_solver.h"
#include "tests/physics/cushion_exact_parts_support.h"

namespace baize::physics {
namespace {

using cushion_exact::extrapolatedRoot;
using cushion_exact::inverseEighthRoot;
using cushion_exact::kP;
using cushion_exact::State;
using cushion_exact::StepControl;
using cushion_exact::stepFactor;

// inverseEighthRoot's promise (cushion_step_control.cpp): within 0.21 % either way.
constexpr double kEighthRootRelative = 2.1e-3;

TEST(CushionStepControl, InverseEighthRootIsWithinItsPromise) {
  for (double x = 1e-300; x < 1e300; x *= 3.7) {
    const double exact = std::pow(x, -0.125);
    EXPECT_NEAR(inverseEighthRoot(x) / exact, 1, kEighthRootRelative) << x;
  }
}

TEST(CushionStepControl, StepFactorIsBoundedAndShrinksWithTheError) {
  for (const ExactStepControl control : {ExactStepControl{}, kTabulatedFallbackStepControl}) {
    const double safety = control.safety, growth = control.max_growth;
    EXPECT_EQ(stepFactor(0, control), growth);  // no error: the largest growth
    EXPECT_EQ(stepFactor(std::numeric_limits<double>::quiet_NaN(), control), 1.0 / 3);
    EXPECT_EQ(stepFactor(1e30, control), 1.0 / 3);
    EXPECT_NEAR(stepFactor(1, control), safety, safety * kEighthRootRelative);  // the safety
    EXPECT_NEAR(stepFactor(256, control), safety / 2, safety / 2 * kEighthRootRelative);
    EXPECT_EQ(stepFactor(1e-30, control), growth);
  }
}

TEST(CushionStepControl, ExtrapolatedRootOfALineAndOfACubic) {
  // g(t) = 1 - t, seen a step of H = 0.5 before 0: the root is 1.
  double root = 0;
  ASSERT_TRUE(extrapolatedRoot(1.5, -1, 1, -1, 0.5, 2, &root));
  EXPECT_NEAR(root, 1, 1e-15);
  EXPECT_FALSE(extrapolatedRoot(1.5, -1, 1, -1, 0.5, 0.5, &root));  // beyond the limit
  EXPECT_FALSE(extrapolatedRoot(1.5, -1, -1, -1, 0.5, 2, &root));   // already past
  // g(t) = 1 - t - t^3 / 4: g(0.8) = 0.072, the root 0.8351...; seen from H = 0.4 before 0.
  auto g = [](double t) { return 1 - t - t * t * t / 4; };
  auto dg = [](double t) { return -1 - 0.75 * t * t; };
  ASSERT_TRUE(extrapolatedRoot(g(-0.4), dg(-0.4), g(0), dg(0), 0.4, 2, &root));
  EXPECT_NEAR(g(root), 0, 1e-14);
}

TEST(CushionStepControl, ControllerFollowsTheTrendOfAcceptedSteps) {
  const CushionParams p = test::snookerCushion();
  StepControl control(p, test::spinningBall(p), test::partsOptions());
  // The first accepted step: the plain factor.
  EXPECT_EQ(control.acceptedStepFactor(1.0, 0.5), control.stepFactor(0.5));
  // The next, shorter by half with the same error: the steps shrink, and so does the next one.
  const double factor = control.acceptedStepFactor(0.5, 0.5);
  EXPECT_NEAR(factor, control.stepFactor(0.5) * 0.5, 1e-12);
}

TEST(CushionStepControl, StepAfterARetryDoesNotGrow) {
  const CushionParams p = test::snookerCushion();
  StepControl control(p, test::spinningBall(p), test::partsOptions());
  constexpr double kSmallError = 1e-6;  // alone, grows the step to the limit
  EXPECT_EQ(control.acceptedStepFactor(1.0, kSmallError),
            test::partsOptions().step_control.max_growth);
  EXPECT_LT(control.rejectedStepFactor(50), 1.0);
  EXPECT_EQ(control.acceptedStepFactor(0.5, kSmallError), 1.0);  // the retry, accepted
  EXPECT_GT(control.acceptedStepFactor(0.5, kSmallError), 1.0);  // the next grows again
}

TEST(CushionStepControl, StepControlComesFromTheOptions) {
  const CushionParams p = test::snookerCushion();
  ExactSolverOptions options = test::partsOptions();
  options.step_control = {0.5, 1.5, 2};
  const StepControl control(p, test::spinningBall(p), options);
  EXPECT_EQ(control.stepFactor(0.5), stepFactor(0.5, options.step_control));
  EXPECT_LT(control.stepFactor(0.5), stepFactor(0.5, ExactStepControl{}));
  EXPECT_EQ(control.stepFactor(0), 1.5);
}

TEST(CushionStepControl, NoCapsWithoutFrictionAndCapsWithIt) {
  CushionParams p = test::poolCushion();
  const BallVelocity ball = test::spinningBall(p);
  {
    CushionParams smooth = p;
    smooth.cushion_friction = smooth.cloth_friction = 0;
    StepControl control(smooth, ball, test::partsOptions());
    const State z = State::Zero();
    const State k1 = control.rate(z);
    EXPECT_EQ(control.cappedStep(control.slips(z), k1, 0.25), 0.25);
    // The restart step: a tenth of the first step's impulse, M v_y0 / 5, at dP/dtau = 1.
    EXPECT_NEAR(control.restartStep(k1), 0.1 * 0.2 * p.mass_kg * ball.v.y(), 1e-18);
  }
  StepControl control(p, ball, test::partsOptions());
  const State z = State::Zero();
  const State k1 = control.rate(z);
  const auto u = control.slips(z);
  const double turning = control.turningScaleStep(u, k1);
  const double direction = control.slipDirectionStep(u);
  EXPECT_GT(turning, 0);
  EXPECT_GT(direction, 0);
  EXPECT_EQ(control.cappedStep(u, k1, 1e9), std::min(turning, direction));
  // The turning scale: over it one slip changes by its own size (kTurningScaleSteps = 1).
  const auto change = control.slipChanges(k1);
  const double smallest = std::min(u[0].norm() / change[0].norm(), u[1].norm() / change[1].norm());
  EXPECT_NEAR(turning, smallest, 1e-12 * smallest);
  EXPECT_GT(k1[kP], 0);
  // The cap on a slip's turning spans the options' number of its time constants.
  ExactSolverOptions bolder = test::partsOptions();
  bolder.step_control.slip_direction_time_constants = 4;
  const StepControl bold(p, ball, bolder);
  EXPECT_NEAR(bold.slipDirectionStep(u) / direction,
              4 / test::partsOptions().step_control.slip_direction_time_constants, 1e-12);
}

}  // namespace
}  // namespace baize::physics
