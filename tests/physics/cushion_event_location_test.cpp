// Tests of the exact cushion solver's event location on a frictionless impact, where the
// compression ends at the closed-form impulse P_c = M v_y0 / c: the phase-end function and its
// slope, a step across the end located onto it, a step aimed short of it landed on it, and the
// bounded list the step loop keeps its events in.
#include "physics/cushion_event_location.h"

#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>

#include "tests/physics/cushion_exact_parts_support.h"

namespace baize::physics {
namespace {

using cushion_exact::Event;
using cushion_exact::EventLocation;
using cushion_exact::FixedList;
using cushion_exact::kP;
using cushion_exact::State;
using cushion_exact::Step;

constexpr double kTolerance = test::kPartsTolerance;

struct Frictionless {
  CushionParams params = [] {
    CushionParams p = test::snookerCushion();
    p.cushion_friction = p.cloth_friction = 0;
    return p;
  }();
  BallVelocity ball = test::spinningBall(params);
  double c = std::sqrt(1 - contactSinTheta(params) * contactSinTheta(params));
  double compression_impulse = params.mass_kg * ball.v.y() / c;  // v_y = v_y0 - c P / M
};

TEST(CushionEventLocation, PhaseEndFunctionIsTheNormalVelocityWhileCompressing) {
  const Frictionless f;
  const EventLocation impact(f.params, f.ball, test::partsOptions());
  const Event phase;
  EXPECT_EQ(impact.eventValue(phase, State::Zero()), f.ball.v.y());
  EXPECT_EQ(impact.phaseEndScale(), f.ball.v.y());
  State r = State::Zero();
  r[kP] = 1;
  EXPECT_NEAR(impact.eventSlope(phase, r), -f.c / f.params.mass_kg, 1e-12);
  EXPECT_NEAR(impact.eventTolerance(phase), 1e-4 * kTolerance * f.ball.v.y(), 1e-30);
}

TEST(CushionEventLocation, LocatesTheEndOfCompressionInsideAStep) {
  const Frictionless f;
  EventLocation impact(f.params, f.ball, test::partsOptions());
  const Event phase;
  const State z = State::Zero();
  const State k1 = impact.rate(z);
  const double h = 1.7 * f.compression_impulse;  // dP/dtau = 1 without friction
  const Step full = impact.rungeKuttaStep(z, k1, h);
  ASSERT_LT(impact.eventValue(phase, full.z), 0);
  double length = 0;
  Step landed;
  ASSERT_TRUE(impact.locate(phase, z, k1, h, full, &length, &landed));
  EXPECT_NEAR(length, f.compression_impulse, 1e-12 * f.compression_impulse);
  EXPECT_NEAR(landed.z[kP], f.compression_impulse, 1e-12 * f.compression_impulse);
  EXPECT_LE(std::abs(impact.eventValue(phase, landed.z)), impact.eventTolerance(phase));
}

TEST(CushionEventLocation, LandsOnThePhaseEndFromAStepAimedShortOfIt) {
  const Frictionless f;
  EventLocation impact(f.params, f.ball, test::partsOptions());
  const Event phase;
  const State z = State::Zero();
  const State k1 = impact.rate(z);
  const double h = (1 - 1e-4) * f.compression_impulse;
  const Step aimed = impact.rungeKuttaStep(z, k1, h);
  double shift = 0;
  Step landed;
  ASSERT_TRUE(impact.landOnPhaseEnd(aimed, h, &shift, &landed));
  EXPECT_NEAR(h + shift, f.compression_impulse, 1e-12 * f.compression_impulse);
  EXPECT_LE(std::abs(impact.eventValue(phase, landed.z)), impact.eventTolerance(phase));
  // Too far away to land on: more than kLandingShiftFraction of the step.
  const double short_h = 0.5 * f.compression_impulse;
  EXPECT_FALSE(
      impact.landOnPhaseEnd(impact.rungeKuttaStep(z, k1, short_h), short_h, &shift, &landed));
}

TEST(CushionEventLocation, FixedListHoldsUpToItsCapacity) {
  FixedList<int, 3> list;
  EXPECT_TRUE(list.empty());
  list.push_back(4);
  list.push_back(5);
  list.push_back(6);
  EXPECT_EQ(list.size(), 3);
  EXPECT_EQ(list[1], 5);
  int sum = 0;
  for (int item : list) sum += item;
  EXPECT_EQ(sum, 15);
  EXPECT_THROW(list.push_back(7), std::logic_error);
}

}  // namespace
}  // namespace baize::physics
