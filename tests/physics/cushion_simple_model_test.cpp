// Tests of the simple restitution cushion rule: its values, that it never adds energy, that it
// commutes with the mirror x -> -x, and that it refuses bad input.
#include "physics/cushion_simple_model.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "tests/physics/cushion_test_support.h"
#include "tests/physics/rejection_test_support.h"

namespace baize::physics {
namespace {

using test::degrees;
using test::expectValueRejected;
using test::mirrored;
using test::RandomImpacts;

// Energies are sums of a few squares: rounding of a few ulp, relative to the energy
// (dimensionless).
constexpr double kEnergyRoundoffRelative = 1e-14;
// Speeds and angles from one multiplication and an atan2 or tan: a few ulp (relative; rad).
constexpr double kRoundoffRelative = 1e-14;
constexpr std::uint64_t kSeed = 0x5eed'51b1e'0001ULL;
constexpr int kRandomCases = 500;  // cheap algebraic checks: enough to cover every sign pattern

TEST(CushionSimpleModel, NormalVelocityReversesTimesETangentAndSpinsAreKept) {
  SimpleCushionParams params;
  params.restitution = 0.8;
  BallVelocity in;
  in.v = {0.7, 1.5, 0};
  in.w = {-20, 30, 45};
  const BallVelocity out = simpleCushionRebound(params, in);
  EXPECT_EQ(out.v.y(), -0.8 * 1.5);  // one multiplication: exact to the rounding it repeats
  EXPECT_EQ(out.v.x(), 0.7);
  EXPECT_EQ(out.v.z(), 0);
  EXPECT_EQ(out.w, in.w);
}

// Head-on the rebound speed is e times the incoming speed; at incidence alpha the rebound angle
// from the cushion line is atan(e tan(alpha)), a closed form of the rule.
TEST(CushionSimpleModel, ReboundSpeedAndAngleFollowTheClosedForm) {
  const SimpleCushionParams params;  // e = 0.91
  const double e = params.restitution;
  const BallVelocity head_on = simpleCushionRebound(params, incomingBall(2.0, degrees(90), 0, 0));
  EXPECT_NEAR(test::reboundSpeed(head_on), e * 2.0, kRoundoffRelative * 2.0);
  for (double alpha_deg : {10.0, 30.0, 45.0, 60.0, 80.0}) {
    const BallVelocity out =
        simpleCushionRebound(params, incomingBall(1.0, degrees(alpha_deg), 30, -12));
    EXPECT_NEAR(test::reboundAngle(out), std::atan(e * std::tan(degrees(alpha_deg))),
                kRoundoffRelative)
        << alpha_deg << " deg";
  }
}

// Energy never grows, and the loss is exactly (1 - e^2) of the normal translational energy.
TEST(CushionSimpleModel, EnergyNeverGrowsAndTheLossIsTheNormalPart) {
  RandomImpacts random(kSeed);
  for (int i = 0; i < kRandomCases; ++i) {
    const test::RandomImpact impact = random.next(/*random_params=*/true);
    SimpleCushionParams params;
    params.restitution = random.uniform(0.05, 1.0);
    const BallVelocity out = simpleCushionRebound(params, impact.incoming);
    const double before = kineticEnergy(impact.params, impact.incoming);
    const double after = kineticEnergy(impact.params, out);
    const double e = params.restitution, vy = impact.incoming.v.y();
    const double expected_loss = 0.5 * impact.params.mass_kg * (1 - e * e) * vy * vy;
    EXPECT_LE(after, before * (1 + kEnergyRoundoffRelative)) << "case " << i;
    EXPECT_NEAR(before - after, expected_loss, kEnergyRoundoffRelative * before) << "case " << i;
  }
}

// The rule commutes with the reflection x -> -x (velocity flips x, angular velocity flips y and z).
TEST(CushionSimpleModel, MirroredImpactGivesTheMirroredRebound) {
  RandomImpacts random(kSeed + 1);
  const SimpleCushionParams params;
  for (int i = 0; i < kRandomCases; ++i) {
    const BallVelocity in = random.next(/*random_params=*/false).incoming;
    const BallVelocity direct = mirrored(simpleCushionRebound(params, in));
    const BallVelocity via_mirror = simpleCushionRebound(params, mirrored(in));
    EXPECT_EQ(direct.v, via_mirror.v) << "case " << i;
    EXPECT_EQ(direct.w, via_mirror.w) << "case " << i;
  }
}

TEST(CushionSimpleModel, BadInputIsRefusedNamingTheValue) {
  const BallVelocity in = incomingBall(1.0, degrees(60), 0, 0);
  for (double e : {0.0, -0.5, 1.2, std::numeric_limits<double>::quiet_NaN()}) {
    SimpleCushionParams params;
    params.restitution = e;
    expectValueRejected([&] { simpleCushionRebound(params, in); }, "simple cushion restitution e");
  }
  BallVelocity leaving = in;
  leaving.v.y() = -1.0;  // moving away from the cushion
  expectValueRejected([&] { simpleCushionRebound(SimpleCushionParams{}, leaving); }, "v_y");
}

}  // namespace
}  // namespace baize::physics
