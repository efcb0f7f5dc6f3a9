// Tests of the generic Dormand-Prince 8(5,3) integrator on its own, on problems with closed-form
// solutions: exponential decay and the harmonic oscillator. Its order (8th: halving the step
// divides the global error by about 256), its error estimate, its dense output between a step's
// ends, the location of an event at its exact time, and the scalar helpers.
#include "physics/dop853.h"

#include <gtest/gtest.h>

#include <Eigen/Core>
#include <cmath>
#include <limits>

namespace baize::physics {
namespace {

using Oscillator = Eigen::Vector2d;  // (x, v) of x'' = -x
using Scalar = Eigen::Matrix<double, 1, 1>;

constexpr double kPi = 3.14159265358979323846;
// Halving the step of an 8th-order method divides its global error by 2^8 = 256; asking for 200
// leaves room for the next term of the error's expansion at these steps.
constexpr double kEighthOrderRatio = 200;
// The error estimate is of 8th order too in its leading term; its 5th-order part makes it fall
// at least 2^5 = 32 times per halving (asked: 25).
constexpr double kEstimateRatio = 25;
// Rounding accumulated over a few dozen steps of unit-size values (absolute).
constexpr double kRoundoff = 1e-14;

Oscillator harmonic(const Oscillator& y) { return {y.y(), -y.x()}; }
Oscillator exactHarmonic(double t) { return {std::cos(t), -std::sin(t)}; }

// Integrates x'' = -x from (1, 0) over [0, t_end] in n equal steps; returns the largest error.
double harmonicError(int n, double t_end) {
  const double h = t_end / n;
  Oscillator y(1, 0);
  Oscillator k1 = harmonic(y);
  for (int i = 0; i < n; ++i) {
    const dop853::Stages<Oscillator> s = dop853::stages(y, k1, h, harmonic);
    y = s.end;
    k1 = s.rate_at_end;
  }
  return (y - exactHarmonic(t_end)).cwiseAbs().maxCoeff();
}

TEST(Dop853, HarmonicOscillatorConvergesAtEighthOrder) {
  const double coarse = harmonicError(8, 4.0), fine = harmonicError(16, 4.0);
  EXPECT_GT(coarse, 0);
  EXPECT_LT(coarse, 1e-7);  // h = 0.5: C h^8 with C of order 1e-5
  EXPECT_GT(coarse / fine, kEighthOrderRatio);
}

TEST(Dop853, ExponentialDecayConvergesAtEighthOrder) {
  auto decay = [](const Scalar& y) { return Scalar(-y[0]); };
  auto error = [&](int n) {
    const double h = 2.0 / n;
    Scalar y(1.0), k1 = decay(y);
    for (int i = 0; i < n; ++i) {
      const dop853::Stages<Scalar> s = dop853::stages(y, k1, h, decay);
      y = s.end;
      k1 = s.rate_at_end;
    }
    return std::abs(y[0] - std::exp(-2.0));
  };
  EXPECT_GT(error(4) / error(8), kEighthOrderRatio);
  EXPECT_LT(error(8), 1e-10);
}

TEST(Dop853, LastStageIsTheRateAtTheEnd) {
  const Oscillator y(0.3, -0.8);
  const dop853::Stages<Oscillator> s = dop853::stages(y, harmonic(y), 0.7, harmonic);
  EXPECT_EQ(s.rate_at_end, harmonic(s.end));
  EXPECT_EQ(s.k[0], harmonic(y));
  // The weighted rates are the step's mean slope.
  EXPECT_NEAR((s.end - y).x() / 0.7, s.slope.x(), kRoundoff);
}

TEST(Dop853, ErrorEstimateFollowsTheTrueErrorAndFallsWithTheStep) {
  const Oscillator y(1, 0), scale(1, 1);
  auto estimate = [&](double h) {
    const dop853::Stages<Oscillator> s = dop853::stages(y, harmonic(y), h, harmonic);
    return dop853::stepError(s, scale, h);
  };
  const double h = 0.8;
  const dop853::Stages<Oscillator> s = dop853::stages(y, harmonic(y), h, harmonic);
  const double true_error = (s.end - exactHarmonic(h)).norm();
  // The estimate bounds the 8th-order solution's error from above (it measures lower-order
  // embedded solutions' differences), within a few decades.
  EXPECT_GT(estimate(h), true_error);
  EXPECT_LT(estimate(h), 1e4 * true_error + 1e-16);
  EXPECT_GT(estimate(h) / estimate(h / 2), kEstimateRatio);
  // A linear rate of zero curvature: the embedded solutions agree, no error.
  auto constant = [](const Scalar&) { return Scalar(2.0); };
  const Scalar one(1.0);
  EXPECT_LE(dop853::stepError(dop853::stages(one, constant(one), 0.5, constant), Scalar(1.0), 0.5),
            kRoundoff);
}

TEST(Dop853, DenseOutputMatchesTheExactSolutionBetweenSteps) {
  // The cubic Hermite interpolant's error is h^4 / 384 max |y''''| at most: 1 for cos and sin.
  for (double h : {0.2, 0.1}) {
    const Oscillator y0 = exactHarmonic(1.0);
    const dop853::Stages<Oscillator> s = dop853::stages(y0, harmonic(y0), h, harmonic);
    const dop853::DenseOutput<Oscillator> dense{y0, harmonic(y0), s.end, s.rate_at_end, h};
    double largest = 0;
    for (double theta = 0; theta <= 1; theta += 0.05) {
      largest = std::max(largest,
                         (dense.at(theta) - exactHarmonic(1.0 + theta * h)).cwiseAbs().maxCoeff());
    }
    EXPECT_LE(largest, std::pow(h, 4) / 384 + kRoundoff) << h;
    EXPECT_GT(largest, std::pow(h, 4) / 384 / 10) << h;  // not better than its order says
    EXPECT_EQ(dense.at(0), y0);
    EXPECT_NEAR((dense.at(1) - s.end).norm(), 0, kRoundoff);
  }
}

TEST(Dop853, LocatesAnEventAtItsExactTime) {
  // x = cos t first reaches 0 at t = pi / 2, inside the step [1.5, 1.75].
  const double t0 = 1.5, h = 0.25;
  const Oscillator y0 = exactHarmonic(t0);
  const dop853::Stages<Oscillator> s = dop853::stages(y0, harmonic(y0), h, harmonic);
  auto event = [](const Oscillator& y) { return y.x(); };
  ASSERT_LT(event(s.end), 0);
  constexpr double kEventTolerance = 1e-15;
  Oscillator at;
  const double length =
      dop853::locateEvent(y0, harmonic(y0), h, s, harmonic, event, kEventTolerance, 60, &at);
  // The step's own error at h = 0.25 is about 1e-13: the event time is as exact as the step.
  EXPECT_NEAR(t0 + length, kPi / 2, 1e-12);
  EXPECT_LE(std::abs(event(at)), kEventTolerance);
  EXPECT_NEAR(at.y(), -1, 1e-12);
}

TEST(Dop853, LocatesAnEventOfADecayAtItsExactTime) {
  // y = e^-t crosses 0.3 at t = ln(10/3) = 1.204, inside the step [1, 1.25].
  auto decay = [](const Scalar& y) { return Scalar(-y[0]); };
  const double t0 = 1.0, h = 0.25;
  const Scalar y0(std::exp(-t0));
  const dop853::Stages<Scalar> s = dop853::stages(y0, decay(y0), h, decay);
  auto event = [](const Scalar& y) { return y[0] - 0.3; };
  Scalar at;
  const double length = dop853::locateEvent(y0, decay(y0), h, s, decay, event, 1e-14, 60, &at);
  EXPECT_NEAR(t0 + length, std::log(10.0 / 3.0), 1e-11);  // the step's own error: 1e-12
  EXPECT_LE(std::abs(at[0] - 0.3), 1e-14);
}

TEST(Dop853, HermiteRootFindsTheCubicsRoot) {
  // A line through (0, 1) and (1, -1): root 1/2.
  EXPECT_NEAR(dop853::hermiteRoot(1, -2, -1, -2), 0.5, 1e-14);
  // g(t) = (t - 0.3)(t - 2)(t + 1), positive at 0: root 0.3.
  auto g = [](double t) { return (t - 0.3) * (t - 2) * (t + 1); };
  auto dg = [](double t) { return (t - 2) * (t + 1) + (t - 0.3) * (t + 1) + (t - 0.3) * (t - 2); };
  // (Its Newton steps take a central difference for the slope, exact to about 1e-9.)
  EXPECT_NEAR(dop853::hermiteRoot(g(0), dg(0), g(1), dg(1)), 0.3, 1e-12);
}

TEST(Dop853, StepFactorFollowsTheEighthRootWithinItsBounds) {
  EXPECT_DOUBLE_EQ(dop853::stepFactor(1, 0.9, 0.2, 5), 0.9);
  EXPECT_DOUBLE_EQ(dop853::stepFactor(256, 0.9, 0.2, 5), 0.45);
  EXPECT_EQ(dop853::stepFactor(0, 0.9, 0.2, 5), 5);
  EXPECT_EQ(dop853::stepFactor(1e300, 0.9, 0.2, 5), 0.2);
  EXPECT_EQ(dop853::stepFactor(std::numeric_limits<double>::quiet_NaN(), 0.9, 0.2, 5), 0.2);
}

TEST(Dop853, CombinedErrorWeighsTheFifthOrderDifference) {
  // |h| e5^2 / sqrt(n (e5^2 + 0.01 e3^2)): with e3 = 0 it is |h| e5 / sqrt(n).
  EXPECT_DOUBLE_EQ(dop853::combinedError(4, 0, 4, -0.5), 0.5);
  EXPECT_DOUBLE_EQ(dop853::combinedError(1, 300, 1, 1), 0.5);
  EXPECT_EQ(dop853::combinedError(0, 0, 3, 1), 0);
}

}  // namespace
}  // namespace baize::physics
