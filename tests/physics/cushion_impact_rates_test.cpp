// Tests of the exact cushion solver's rates and Runge-Kutta step: the written-out rates of the
// common modes equal the general laws' rate, the change of variable's sigma is the product of the
// slipping contacts' factors, a frictionless impact is integrated exactly, a step costs twelve
// evaluations and its error estimate falls with the step at the pair's order.
#include "physics/cushion_impact_rates.h"

#include <gtest/gtest.h>

#include <cmath>

#include "tests/physics/cushion_exact_parts_support.h"

namespace baize::physics {
namespace {

using cushion_exact::ImpactRates;
using cushion_exact::kP;
using cushion_exact::kWork;
using cushion_exact::State;
using cushion_exact::Step;
using Rates = test::Exposed<ImpactRates>;

// The written-out rates reassociate the general laws' arithmetic (relative to the rate's size).
constexpr double kReassociationRelative = 1e-14;

double relativeDifference(const State& a, const State& b) {
  return (a - b).cwiseAbs().maxCoeff() / b.cwiseAbs().maxCoeff();
}

TEST(CushionImpactRates, BothSlidingRateIsTheGeneralLawsRate) {
  for (const CushionParams& p : {test::snookerCushion(), test::poolCushion()}) {
    Rates impact(p, test::spinningBall(p), test::partsOptions());
    ASSERT_TRUE(impact.bothSliding());
    State z;
    z << 0.01, 0.001, -0.0005, 0.002, 0.0004, 0.001;
    const State fast = impact.rate(z), general = impact.generalRate(z);
    EXPECT_LE(relativeDifference(fast, general), kReassociationRelative);
    // sigma = dP/dtau: the product of |u| / (|u| + s0) over the slipping contacts.
    const auto u = impact.slips(z);
    const double s0 = impact.regularizingSlip();
    const double sigma = u[0].norm() / (u[0].norm() + s0) * u[1].norm() / (u[1].norm() + s0);
    EXPECT_NEAR(fast[kP], sigma, kReassociationRelative);
    // The nose's friction per unit P is mu_w along its slip.
    const Eigen::Vector2d a(fast[1] / fast[kP], fast[2] / fast[kP]);
    EXPECT_NEAR(a.norm(), p.cushion_friction, 1e-15);
    EXPECT_NEAR(a.normalized().dot(u[0].normalized()), 1, 1e-15);
  }
}

TEST(CushionImpactRates, HeldClothRateIsTheGeneralLawsRate) {
  const CushionParams p = test::snookerCushion();
  for (double angle_deg : {15.0, 45.0, 75.0}) {
    const double a = angle_deg * 3.14159265358979323846 / 180;
    Rates impact(p, incomingBall(1.5, a, 1.5 / p.radius_m, 0.5 / p.radius_m), test::partsOptions());
    impact.setContactMode(1, ContactMode::Stick);
    ASSERT_TRUE(impact.clothHeldWhileNoseSlides());
    State z;
    z << 0.005, 0.0005, -0.0002, 0.0001, 0.0001, 0.0005;
    EXPECT_LE(relativeDifference(impact.rate(z), impact.generalRate(z)), kReassociationRelative)
        << angle_deg;
  }
}

TEST(CushionImpactRates, HeldClothSlidingFromRestHasTheGeneralLawsLag) {
  // A slippery cloth its cone cannot hold, its slip grown from zero along a direction phi* has
  // turned away from: the written-out rate lags phi* as the general laws do, at either order.
  CushionParams p = test::snookerCushion();
  p.cloth_friction = 0.02;
  int compared = 0;
  for (double angle_deg : {15.0, 45.0, 75.0}) {
    const double a = angle_deg * 3.14159265358979323846 / 180;
    for (double growth_order : {1.0, 2.0}) {
      Rates impact(p, incomingBall(1.5, a, 1.5 / p.radius_m, 0.5 / p.radius_m),
                   test::partsOptions());
      impact.setContactMode(1, ContactMode::Stick);
      if (!impact.clothHeldWhileNoseSlides()) continue;
      State z;
      z << 0.005, 0.0005, -0.0002, 0.0001, 0.0001, 0.0005;
      const State without_lag = impact.rate(z);
      const Eigen::Vector2d turned_origin(std::cos(a), -std::sin(a));
      impact.setCreepFromRest(1, turned_origin, growth_order);
      // The lag is there: the cloth slides (its cone does not hold it) and lags.
      constexpr double kVisibleLag = 1e-6;
      EXPECT_GT(relativeDifference(impact.rate(z), without_lag), kVisibleLag) << angle_deg;
      EXPECT_LE(relativeDifference(impact.rate(z), impact.generalRate(z)), kReassociationRelative)
          << angle_deg << " deg, order " << growth_order;
      ++compared;
    }
  }
  EXPECT_GT(compared, 0);
}

TEST(CushionImpactRates, FrictionlessImpactIsIntegratedExactly) {
  CushionParams p = test::snookerCushion();
  p.cushion_friction = 0;
  p.cloth_friction = 0;
  const BallVelocity ball = test::spinningBall(p);
  Rates impact(p, ball, test::partsOptions());
  const State z = State::Zero();
  const State k1 = impact.rate(z);
  // dP/dtau = 1, no friction, dW/dP = c v_y with v_y = v_y0 - c P / M.
  const double s = contactSinTheta(p), c = std::sqrt(1 - s * s), M = p.mass_kg;
  EXPECT_EQ(k1[kP], 1);
  EXPECT_EQ(k1.segment<4>(1), Eigen::Vector4d::Zero());
  const double h = 0.5 * M * ball.v.y() / c;
  const long before = impact.evaluations();
  const Step step = impact.rungeKuttaStep(z, k1, h);
  EXPECT_EQ(impact.evaluations() - before, 12);  // eleven stages and the rate at the end
  EXPECT_NEAR(step.z[kP], h, 1e-16);
  EXPECT_NEAR(step.z[kWork], c * (ball.v.y() * h - c * h * h / (2 * M)), 1e-15);
  EXPECT_LE(step.error, 1e-3);  // a quadratic: the embedded solutions agree to rounding
  EXPECT_NEAR(impact.normalVelocity(step.z), 0.5 * ball.v.y(), 1e-15);
}

TEST(CushionImpactRates, StepErrorFallsWithTheStep) {
  const CushionParams p = test::poolCushion();
  Rates impact(p, test::spinningBall(p), test::partsOptions());
  const State z = State::Zero();
  const State k1 = impact.rate(z);
  const double h = 0.3 * p.mass_kg * test::spinningBall(p).v.y();
  const Step long_step = impact.rungeKuttaStep(z, k1, h);
  const Step short_step = impact.rungeKuttaStep(z, k1, h / 2);
  EXPECT_GT(long_step.error, 0);
  // Error per unit step of an 8th-order estimate: at least 2^5 smaller per halving (its 5th-order
  // part), at the error share's floor.
  EXPECT_GT(long_step.error / short_step.error, 25);
  // The step's end carries its slips, and the rate there.
  EXPECT_EQ(long_step.slips_at_end[0], impact.slips(long_step.z)[0]);
  EXPECT_LE(relativeDifference(long_step.rate_at_end, impact.rate(long_step.z)), 1e-13);
}

}  // namespace
}  // namespace baize::physics
