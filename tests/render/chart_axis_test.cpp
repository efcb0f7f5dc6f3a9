#include "render/chart_axis.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <vector>

#include "tests/physics/rejection_test_support.h"

namespace baize::render {
namespace {

using physics::test::expectRejected;
using physics::test::expectValueRejected;

// Ticks are computed as i x step; comparing them with hand-written decimals allows one rounding
// of a value of this size. Relative.
constexpr double kTickRoundOff = 1e-12;
// Pixel positions are a few arithmetic operations on doubles of order 1e3 px.
constexpr double kPixelRoundOff = 1e-9;

void expectTicks(const AxisTicks& ticks, const std::vector<double>& expected) {
  ASSERT_EQ(ticks.major.size(), expected.size());
  for (size_t i = 0; i < expected.size(); ++i) {
    EXPECT_NEAR(ticks.major[i], expected[i], kTickRoundOff * std::fabs(expected[i]) + 1e-300)
        << "tick " << i;
  }
  EXPECT_EQ(ticks.low, ticks.major.front());
  EXPECT_EQ(ticks.high, ticks.major.back());
}

// Is `step` 1, 2 or 5 times a power of ten?
bool isOneTwoFiveStep(double step) {
  const double decade = std::pow(10.0, std::floor(std::log10(step) + 1e-12));
  const double mantissa = step / decade;
  for (const double allowed : {1.0, 2.0, 5.0, 10.0}) {
    if (std::fabs(mantissa - allowed) < 1e-9) return true;
  }
  return false;
}

// The next smaller 1-2-5 step below `step` (5 -> 2 -> 1 -> 0.5 ...).
double smallerStep(double step) {
  const double decade = std::pow(10.0, std::floor(std::log10(step) + 1e-12));
  const long mantissa = std::lround(step / decade);
  if (mantissa == 5) return 2 * decade;
  if (mantissa == 2) return decade;
  return decade / 2;
}

TEST(LinearTicks, HandWorkedRanges) {
  // span 10 over 5 intervals: step 2 exactly.
  expectTicks(linearTicks(0, 10, 5), {0, 2, 4, 6, 8, 10});
  // 0.3 / 0.1 is 2.9999999999999996 in doubles: the axis still starts at 0.3, not 0.2.
  expectTicks(linearTicks(0.3, 0.7, 4), {0.3, 0.4, 0.5, 0.6, 0.7});
  // raw step 15.8 / 6 = 2.6: step 1 needs 17 intervals, step 2 needs 9 (-4..14), step 5 needs 4.
  expectTicks(linearTicks(-3.7, 12.1, 6), {-5, 0, 5, 10, 15});
  // Fig. 6's rebound angles, 1..179 deg: steps of 20 need 9 intervals (0..180), so a target of 8
  // takes steps of 50 (0..200); never 25 or 30.
  expectTicks(linearTicks(1, 179, 9), {0, 20, 40, 60, 80, 100, 120, 140, 160, 180});
  expectTicks(linearTicks(1, 179, 8), {0, 50, 100, 150, 200});
  EXPECT_EQ(linearTicks(-3.7, 12.1, 6).step, 5);
}

// A quantity constant up to round-off (here 1 and the next double above it) is drawn flat, with
// the labels of a zero-width range rather than sixteen decimals.
TEST(LinearTicks, RoundOffWidthRangeIsDrawnAsOneValue) {
  const AxisTicks flat = linearTicks(1, std::nextafter(1.0, 2.0), 4);
  EXPECT_EQ(flat.low, 0);
  EXPECT_EQ(flat.high, 2);
  EXPECT_EQ(flat.step, 0.5);  // [0, 2] in 4 intervals
  // Tiny values that are not round-off keep their own scale.
  const AxisTicks tiny = linearTicks(2e-9, 7e-9, 5);
  EXPECT_NEAR(tiny.step, 1e-9, 1e-9 * kTickRoundOff);
  EXPECT_EQ(tickLabel(tiny, tiny.major[1]), "3e-09");
}

TEST(LinearTicks, ZeroWidthRangeIsCentredOnTheValue) {
  const AxisTicks around_zero = linearTicks(0, 0, 4);
  EXPECT_EQ(around_zero.low, -1);
  EXPECT_EQ(around_zero.high, 1);
  const AxisTicks around_value = linearTicks(0.25, 0.25, 4);  // padded by 0.1 each side
  EXPECT_NEAR((around_value.low + around_value.high) / 2, 0.25, kTickRoundOff);
  EXPECT_LT(around_value.low, 0.25);
  EXPECT_GT(around_value.high, 0.25);
}

// Over many seeded ranges: 1-2-5 steps, even spacing, the data covered, at most target_count
// intervals, and the smallest such step (the next smaller one would need too many intervals).
TEST(LinearTicks, OneTwoFiveStepsCoverEveryRange) {
  std::mt19937_64 random(20261121);
  std::uniform_real_distribution<double> exponent(-8, 8);
  std::uniform_real_distribution<double> unit(-1, 1);
  std::uniform_int_distribution<int> target(2, 10);
  for (int trial = 0; trial < 2000; ++trial) {
    const double scale = std::pow(10.0, exponent(random));
    double low = unit(random) * scale;
    double high = low + std::fabs(unit(random)) * scale + scale * 1e-6;
    const int count = target(random);
    const AxisTicks ticks = linearTicks(low, high, count);
    ASSERT_TRUE(isOneTwoFiveStep(ticks.step)) << ticks.step;
    ASSERT_LE(ticks.low, low + ticks.step * 1e-9);
    ASSERT_GE(ticks.high, high - ticks.step * 1e-9);
    ASSERT_GE(ticks.major.size(), 2u);
    ASSERT_LE(static_cast<int>(ticks.major.size()) - 1, count);
    for (size_t i = 1; i < ticks.major.size(); ++i) {
      ASSERT_NEAR(ticks.major[i] - ticks.major[i - 1], ticks.step, ticks.step * 1e-9);
    }
    // Neither end is a whole step outside the data: the axis is not wider than it must be.
    ASSERT_GT(ticks.low, low - ticks.step * (1 + 1e-9));
    ASSERT_LT(ticks.high, high + ticks.step * (1 + 1e-9));
    const double finer = smallerStep(ticks.step);
    const double finer_intervals = std::ceil(high / finer - 1e-9) - std::floor(low / finer + 1e-9);
    ASSERT_GT(finer_intervals, count) << "step " << ticks.step << " for [" << low << ", " << high
                                      << "] with " << count << " ticks; " << finer << " fits";
  }
}

TEST(LogTicks, DecadesCoverTheRange) {
  // The bench's errors run from 1.4e-11 to 1.7e-2: decades 1e-11 .. 1e-1.
  const AxisTicks errors = logTicks(1.4e-11, 1.7e-2, 10);
  EXPECT_EQ(errors.step, 1);
  std::vector<double> decades;
  for (int d = -11; d <= -1; ++d) decades.push_back(std::pow(10.0, d));
  expectTicks(errors, decades);
  // Minor ticks at 2..9 x each decade: 8 per decade.
  EXPECT_EQ(errors.minor.size(), 8u * 10);
  EXPECT_NEAR(errors.minor.front(), 2e-11, 2e-11 * kTickRoundOff);
  // A range on exact decades is not widened.
  expectTicks(logTicks(1e-3, 100, 6), {1e-3, 1e-2, 1e-1, 1, 10, 100});
  // Within one decade: that whole decade.
  expectTicks(logTicks(2, 5, 6), {1, 10});
}

TEST(LogTicks, WideRangesStepSeveralDecades) {
  // 40 decades in at most 10 intervals: 5 decades a step (2 would need 20).
  const AxisTicks wide = logTicks(1e-20, 1e20, 10);
  EXPECT_EQ(wide.step, 5);
  expectTicks(wide, {1e-20, 1e-15, 1e-10, 1e-5, 1, 1e5, 1e10, 1e15, 1e20});
  EXPECT_TRUE(wide.minor.empty());
  // 13 decades (-13 .. 0) in at most 6: step 5 from -15 to 0.
  expectTicks(logTicks(3e-14, 0.5, 6), {1e-15, 1e-10, 1e-5, 1});
}

TEST(AxisMapping, LogDecadesAreEvenlySpaced) {
  const AxisTicks ticks = logTicks(1.4e-11, 1.7e-2, 10);
  const AxisMapping mapping(ticks, 100, 900);
  EXPECT_NEAR(mapping.toPixel(ticks.low), 100, kPixelRoundOff);
  EXPECT_NEAR(mapping.toPixel(ticks.high), 900, kPixelRoundOff);
  const double decade_px = 800.0 / (ticks.major.size() - 1);
  for (size_t i = 0; i < ticks.major.size(); ++i) {
    EXPECT_NEAR(mapping.toPixel(ticks.major[i]), 100 + i * decade_px, kPixelRoundOff) << i;
  }
  // 2 x 10^k sits log10(2) of a decade above 10^k.
  EXPECT_NEAR(mapping.toPixel(2e-5) - mapping.toPixel(1e-5), std::log10(2.0) * decade_px,
              kPixelRoundOff);
}

TEST(AxisMapping, LinearAndFlipped) {
  const AxisTicks ticks = linearTicks(0, 10, 5);
  const AxisMapping y_axis(ticks, 500, 100);  // y: low at the bottom row
  EXPECT_NEAR(y_axis.toPixel(0), 500, kPixelRoundOff);
  EXPECT_NEAR(y_axis.toPixel(10), 100, kPixelRoundOff);
  EXPECT_NEAR(y_axis.toPixel(2.5), 400, kPixelRoundOff);
}

TEST(TickLabel, ShowsTheStepsDecimals) {
  const AxisTicks tenths = linearTicks(0.3, 0.7, 4);
  EXPECT_EQ(tickLabel(tenths, tenths.major[0]), "0.3");
  EXPECT_EQ(tickLabel(tenths, tenths.major[4]), "0.7");
  const AxisTicks fives = linearTicks(-3.7, 12.1, 6);
  EXPECT_EQ(tickLabel(fives, -5), "-5");
  EXPECT_EQ(tickLabel(fives, 15), "15");
  const AxisTicks quarters = linearTicks(-0.5, 0.5, 4);  // step 0.5: -0.5 0 0.5, 0 unsigned
  EXPECT_EQ(tickLabel(quarters, -1e-17), "0.0");
  const AxisTicks decades = logTicks(1e-6, 1e3, 10);
  EXPECT_EQ(tickLabel(decades, 1e-6), "10⁻⁶");
  EXPECT_EQ(tickLabel(decades, 1), "1");
  EXPECT_EQ(tickLabel(decades, 10), "10");
  EXPECT_EQ(tickLabel(decades, 1e3), "10³");
  EXPECT_EQ(tickLabel(logTicks(1e-12, 1e-10, 4), 1e-12), "10⁻¹²");
  // Steps past 10^5 and below 10^-4 in exponent notation with the digits the step needs.
  const AxisTicks millions = linearTicks(0, 3e7, 6);  // step 5e6
  EXPECT_EQ(tickLabel(millions, 1.5e7), "1.5e+07");
  EXPECT_EQ(tickLabel(millions, 0), "0");
  const AxisTicks large = linearTicks(0, 3e6, 6);  // step 5e5: still plain digits
  EXPECT_EQ(tickLabel(large, 1.5e6), "1500000");
  const AxisTicks micro = linearTicks(1e-5, 3e-5, 4);  // step 5e-6
  EXPECT_EQ(tickLabel(micro, 1.5e-5), "1.5e-05");
  const AxisTicks fine = linearTicks(0, 1e-3, 5);  // step 2e-4: still plain decimals
  EXPECT_EQ(tickLabel(fine, fine.major[1]), "0.0002");
}

TEST(AxisTicks, BadInputIsRejected) {
  expectValueRejected([] { linearTicks(std::nan(""), 1, 4); }, "axis low end = nan");
  expectValueRejected([] { linearTicks(0, INFINITY, 4); }, "axis high end = inf");
  expectValueRejected([] { linearTicks(2, 1, 4); }, "axis low end = 2");
  expectValueRejected([] { linearTicks(0, 1, 1); }, "axis tick count = 1");
  expectValueRejected([] { linearTicks(0, 1, 101); }, "axis tick count = 101");
  expectRejected([] { linearTicks(-1e305, 1, 4); }, {"axis low end = -1e+305", "at most 1"});
  expectRejected([] { logTicks(1e-310, 1, 4); }, {"log axis low end = 1e-310", "at least 1"});
  expectValueRejected([] { logTicks(0, 1, 4); }, "log axis low end = 0");
  expectValueRejected([] { logTicks(-1, 1, 4); }, "log axis low end = -1");
  expectRejected([] { logTicks(10, 1, 4); }, {"log axis low end = 10", "high end 1"});
}

}  // namespace
}  // namespace baize::render
