// Tests of the exact cushion solver's impact equations: the slips at the start are the model's
// (cushion_model.h), they change linearly in the state at the rate each friction law gives, the
// stick law of both contacts holds both slips, the ball's velocities follow the model's impulse
// response, and the extended state carries the slips.
#include "physics/cushion_impact_equations.h"

#include <gtest/gtest.h>

#include <cmath>

#include "tests/physics/cushion_exact_parts_support.h"

namespace baize::physics {
namespace {

using cushion_exact::Extended;
using cushion_exact::Friction;
using cushion_exact::ImpactEquations;
using cushion_exact::kAx;
using cushion_exact::kAy;
using cushion_exact::kBx;
using cushion_exact::kBy;
using cushion_exact::kP;
using cushion_exact::kStateSize;
using cushion_exact::kWork;
using cushion_exact::Laws;
using cushion_exact::State;

// Arithmetic in another association than the code under test, on values of order 1 m/s
// (absolute, m/s).
constexpr double kRoundoff = 1e-13;

// A state after some impulse: P and both friction impulses (N s), and some work (J).
State someState() {
  State z;
  z << 0.05, 0.004, -0.003, 0.006, 0.002, 0.01;
  return z;
}

TEST(CushionImpactEquations, SlipsAtTheStartAreTheModels) {
  for (const CushionParams& p : {test::snookerCushion(), test::poolCushion()}) {
    const BallVelocity ball = test::spinningBall(p);
    const ImpactEquations impact(p, ball, test::partsOptions());
    const auto u = impact.slips(State::Zero());
    EXPECT_NEAR((u[0] - cushionSlip(p, ball)).norm(), 0, kRoundoff);
    EXPECT_NEAR((u[1] - clothSlip(p, ball)).norm(), 0, kRoundoff);
    EXPECT_DOUBLE_EQ(impact.normalVelocity(State::Zero()), ball.v.y());
  }
}

TEST(CushionImpactEquations, SlipsChangeAtTheRateEachFrictionLawGives) {
  const CushionParams p = test::snookerCushion();
  const ImpactEquations impact(p, test::spinningBall(p), test::partsOptions());
  const State z = someState();
  Laws laws;
  laws.direction = {Eigen::Vector2d(0.6, 0.8), Eigen::Vector2d(-1, 0)};
  for (int stuck = 0; stuck < 4; ++stuck) {
    laws.stick = {(stuck & 1) != 0, (stuck & 2) != 0};
    const Friction f = impact.frictionFor(laws);
    const double dP = 0.01;
    State dz = State::Zero();
    dz[kP] = dP;
    dz[kAx] = f.a.x() * dP, dz[kAy] = f.a.y() * dP, dz[kBx] = f.b.x() * dP, dz[kBy] = f.b.y() * dP;
    const auto before = impact.slips(z), after = impact.slips(z + dz);
    for (int k = 0; k < 2; ++k) {
      EXPECT_NEAR((after[k] - before[k] - dP * impact.slipRate(k, f)).norm(), 0, kRoundoff)
          << stuck << " " << k;
      // slipChanges gives the same from the rate (1, a, b).
      State r = dz / dP;
      EXPECT_NEAR((impact.slipChanges(r)[k] - impact.slipRate(k, f)).norm(), 0, kRoundoff);
    }
    // A stuck contact's law holds its slip: its slip rate is zero.
    for (int k = 0; k < 2; ++k) {
      if (!laws.stick[k]) continue;
      EXPECT_NEAR(impact.slipRate(k, f).norm(), 0, kRoundoff) << stuck;
    }
    // A sliding contact's friction lies on its cone's edge, along its direction.
    if (!laws.stick[0]) {
      EXPECT_NEAR(impact.coneMargin(0, f), 0, kRoundoff);
      EXPECT_NEAR(f.a.normalized().dot(laws.direction[0]), 1, kRoundoff);
    }
  }
}

TEST(CushionImpactEquations, BallFollowsTheModelsImpulseResponse) {
  const CushionParams p = test::poolCushion();
  const BallVelocity ball = test::spinningBall(p);
  const ImpactEquations impact(p, ball, test::partsOptions());
  const State z = someState();
  const BallVelocity change =
      impulseResponse(p, z[kP], Eigen::Vector2d(z[kAx], z[kAy]), Eigen::Vector2d(z[kBx], z[kBy]));
  const BallVelocity after = impact.ballAt(z);
  EXPECT_NEAR((after.v.head<2>() - (ball.v + change.v).head<2>()).norm(), 0, kRoundoff);
  EXPECT_NEAR((after.w - (ball.w + change.w)).norm(), 0, kRoundoff);
  EXPECT_EQ(after.v.z(), 0);
  // Its slips are the model's slips of that ball.
  EXPECT_NEAR((impact.slips(z)[0] - cushionSlip(p, after)).norm(), 0, kRoundoff);
  EXPECT_NEAR((impact.slips(z)[1] - clothSlip(p, after)).norm(), 0, kRoundoff);
}

TEST(CushionImpactEquations, ExtendedStateCarriesTheSlipsAndTheirRates) {
  const CushionParams p = test::snookerCushion();
  const ImpactEquations impact(p, test::spinningBall(p), test::partsOptions());
  const State z = someState();
  const Extended y = impact.withSlips(z);
  EXPECT_EQ(y.head<kStateSize>(), z);
  EXPECT_EQ(y.segment<2>(kStateSize), impact.slips(z)[0]);
  EXPECT_EQ(y.segment<2>(kStateSize + 2), impact.slips(z)[1]);
  State r;
  r << 0.7, 0.1, -0.05, 0.08, 0.02, 0.3;
  const Extended rates = impact.withSlipRates(r);
  EXPECT_NEAR((rates.segment<2>(kStateSize) - impact.slipChanges(r)[0]).norm(), 0, kRoundoff);
  EXPECT_NEAR((rates.segment<2>(kStateSize + 2) - impact.slipChanges(r)[1]).norm(), 0, kRoundoff);
  EXPECT_EQ(rates[kWork], r[kWork]);
}

TEST(CushionImpactEquations, ContactsStartSlippingAndFrictionlessOnesNeverDo) {
  CushionParams p = test::snookerCushion();
  p.cloth_friction = 0;
  const ImpactEquations impact(p, test::spinningBall(p), test::partsOptions());
  EXPECT_TRUE(impact.slipping(0));
  EXPECT_FALSE(impact.held(0));
  EXPECT_FALSE(impact.slipping(1));
  EXPECT_FALSE(impact.held(1));
  EXPECT_TRUE(impact.contact(1).frictionless);
}

}  // namespace
}  // namespace baize::physics
