#include "physics/polynomial_roots.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>
#include <random>
#include <stdexcept>
#include <string>
#include <vector>

#include "tests/physics/fp_trap_support.h"
#include "tests/physics/rejection_test_support.h"

namespace baize::physics {
namespace {

using test::expectRejected;
using Coefficients = PolynomialCoefficients;

constexpr double kUnitRoundoff = 0x1p-53;
constexpr double kInfinity = std::numeric_limits<double>::infinity();

// Error of a computed root, in units of its condition u * sum_i |c_i| |r|^i / |p'(r)|: about 4 from
// forming the coefficients by multiplying out factors in double, 10 from the finder's rounding
// band, doubled for margin.
constexpr double kRootErrorInConditionUnits = 32;
// Added to every root tolerance: 4 ulps of the root itself, and an absolute floor for roots at 0,
// where the condition bound above vanishes.
constexpr double kRootUlpSlack = 8 * kUnitRoundoff;
constexpr double kRootAbsoluteSlack = 1e-300;
// A double root is located as a simple root of p', so it is as accurate as one (~1e-16); 1e-12
// leaves room for the critical point's own rounding band.
constexpr double kDoubleRootTolerance = 1e-12;

// ---- Building test polynomials ------------------------------------------------------------------

Coefficients multiply(const Coefficients& a, const Coefficients& b) {
  Coefficients product{};
  for (int i = 0; i < 5; ++i) {
    for (int j = 0; i + j < 5; ++j) product[i + j] += a[i] * b[j];
  }
  return product;
}

// leading * prod (t - r_i), at most 4 roots.
Coefficients fromRoots(double leading, const std::vector<double>& roots) {
  Coefficients p{leading, 0, 0, 0, 0};
  for (double r : roots) p = multiply(p, {-r, 1, 0, 0, 0});
  return p;
}

Coefficients scaledBy(const Coefficients& c, double factor) {
  Coefficients s = c;
  for (double& x : s) x *= factor;
  return s;
}

Coefficients derivativeOf(const Coefficients& c) { return {c[1], 2 * c[2], 3 * c[3], 4 * c[4], 0}; }

// The accuracy a root r of p can have: kRootErrorInConditionUnits rounding bands over the slope.
double conditionTolerance(const Coefficients& c, double r) {
  double magnitude = 0;
  for (int i = 4; i >= 0; --i) magnitude = magnitude * std::abs(r) + std::abs(c[i]);
  const double slope = std::abs(evaluatePolynomial(derivativeOf(c), r));
  return kRootErrorInConditionUnits * kUnitRoundoff * magnitude / slope +
         kRootUlpSlack * std::abs(r) + kRootAbsoluteSlack;
}

double logUniform(std::mt19937_64& rng, double lo, double hi) {
  return std::pow(10.0,
                  std::uniform_real_distribution<double>(std::log10(lo), std::log10(hi))(rng));
}

double randomSign(std::mt19937_64& rng) { return (rng() & 1) ? 1.0 : -1.0; }

// `count` roots uniform in [lo, hi], sorted, at least `separation` apart.
std::vector<double> separatedRoots(std::mt19937_64& rng, int count, double lo, double hi,
                                   double separation) {
  std::uniform_real_distribution<double> uniform(lo, hi);
  for (;;) {
    std::vector<double> roots(count);
    for (double& r : roots) r = uniform(rng);
    std::sort(roots.begin(), roots.end());
    bool separated = true;
    for (int i = 1; i < count; ++i) separated = separated && roots[i] - roots[i - 1] >= separation;
    if (separated) return roots;
  }
}

bool isRoot(const RootSearchResult& r) { return r.outcome == RootOutcome::Root; }

// ---- Products of known linear factors -----------------------------------------------------------

// Roots in [-10, 10], at least 0.05 apart: roots stay separable at double precision.
constexpr double kRandomRootRange = 10;
constexpr double kRandomRootSeparation = 0.05;

TEST(PolynomialRootsTest, FindsEveryRootOfRandomProductsOfLinearFactors) {
  std::mt19937_64 rng(1);
  for (int trial = 0; trial < 2000; ++trial) {
    const int degree = 1 + trial % 4;
    const std::vector<double> roots =
        separatedRoots(rng, degree, -kRandomRootRange, kRandomRootRange, kRandomRootSeparation);
    const Coefficients c = fromRoots(randomSign(rng) * logUniform(rng, 1e-3, 1e3), roots);

    const std::vector<double> found = realRoots(c);
    ASSERT_EQ(found.size(), roots.size()) << "trial " << trial;
    for (int i = 0; i < degree; ++i) {
      EXPECT_NEAR(found[i], roots[i], conditionTolerance(c, roots[i])) << "trial " << trial;
    }
    const std::vector<double> in_interval =
        rootsInInterval(c, -2 * kRandomRootRange, 2 * kRandomRootRange);
    ASSERT_EQ(in_interval.size(), roots.size()) << "trial " << trial;
    for (int i = 0; i < degree; ++i) {
      EXPECT_NEAR(in_interval[i], roots[i], conditionTolerance(c, roots[i])) << "trial " << trial;
    }
  }
}

TEST(PolynomialRootsTest, SmallestRootInRandomIntervalsOfRandomProducts) {
  std::mt19937_64 rng(2);
  std::uniform_real_distribution<double> end(-12, 12);
  int none = 0;
  for (int trial = 0; trial < 2000; ++trial) {
    const int degree = 1 + trial % 4;
    const std::vector<double> roots =
        separatedRoots(rng, degree, -kRandomRootRange, kRandomRootRange, kRandomRootSeparation);
    const Coefficients c = fromRoots(randomSign(rng) * logUniform(rng, 1e-3, 1e3), roots);
    // Interval ends clear of every root by more than its tolerance, so the answer is unambiguous.
    double lo = 0, hi = 0;
    for (bool clear = false; !clear;) {
      lo = end(rng);
      hi = end(rng);
      if (lo > hi) std::swap(lo, hi);
      clear = true;
      for (double r : roots) {
        const double tolerance = 2 * conditionTolerance(c, r);
        clear = clear && std::abs(r - lo) > tolerance && std::abs(r - hi) > tolerance;
      }
    }
    double expected = kInfinity;
    for (double r : roots) {
      if (r >= lo && r <= hi) expected = std::min(expected, r);
    }
    const RootSearchResult result = smallestRootInInterval(c, lo, hi);
    if (expected == kInfinity) {
      ++none;
      EXPECT_EQ(result.outcome, RootOutcome::NoRoot)
          << "trial " << trial << " found " << result.time;
      EXPECT_EQ(result.time, kInfinity);
    } else {
      ASSERT_TRUE(isRoot(result)) << "trial " << trial << " missed " << expected;
      EXPECT_NEAR(result.time, expected, conditionTolerance(c, expected)) << "trial " << trial;
    }
  }
  EXPECT_GT(none, 100);  // both outcomes were exercised
}

// ---- Double and nearly double roots -------------------------------------------------------------

TEST(PolynomialRootsTest, DoubleRootIsFoundAtTheCriticalPoint) {
  // (t - 1)^2 (t - 2)(t - 3) = t^4 - 7t^3 + 17t^2 - 17t + 6 (exact in double).
  const Coefficients c{6, -17, 17, -7, 1};
  const RootSearchResult first = smallestRootInInterval(c, 0, 5);
  ASSERT_TRUE(isRoot(first));
  EXPECT_NEAR(first.time, 1, kDoubleRootTolerance);

  const std::vector<double> roots = realRoots(c);
  ASSERT_EQ(roots.size(), 3u);  // the double root once
  EXPECT_NEAR(roots[0], 1, kDoubleRootTolerance);
  EXPECT_NEAR(roots[1], 2, conditionTolerance(c, 2));
  EXPECT_NEAR(roots[2], 3, conditionTolerance(c, 3));

  const RootSearchResult after = smallestRootInInterval(c, 1.5, 5);
  ASSERT_TRUE(isRoot(after));
  EXPECT_NEAR(after.time, 2, conditionTolerance(c, 2));
}

TEST(PolynomialRootsTest, NearlyDoubleRootsAreSeparated) {
  // (t - 1)^2 - 1e-14: roots 1 -+ 1e-7, a dip ten times deeper than the rounding band of p
  // (4.4e-15).
  const Coefficients c{1 - 1e-14, -2, 1, 0, 0};
  // How far the roots may move: the rounding band of p (10 u * 4) over the slope 2e-7 at the roots,
  // plus the rounding of c0 (u) over the same slope.
  constexpr double kNearDoubleRootTolerance = 11 * kUnitRoundoff * 4 / 2e-7;
  const std::vector<double> roots = realRoots(c);
  ASSERT_EQ(roots.size(), 2u);
  EXPECT_NEAR(roots[0], 1 - 1e-7, kNearDoubleRootTolerance);
  EXPECT_NEAR(roots[1], 1 + 1e-7, kNearDoubleRootTolerance);
  const RootSearchResult first = smallestRootInInterval(c, 0, 2);
  ASSERT_TRUE(isRoot(first));
  EXPECT_NEAR(first.time, 1 - 1e-7, kNearDoubleRootTolerance);

  // Times (t - 2)(t - 3) the rounding band at t = 1 widens to 10 u * 48 = 5.3e-14, deeper than the
  // dip of 2e-14: the pair is one touch, reported once, never missed.
  const Coefficients shallow = multiply(c, {6, -5, 1, 0, 0});
  const std::vector<double> shallow_roots = realRoots(shallow);
  ASSERT_EQ(shallow_roots.size(), 3u);
  EXPECT_NEAR(shallow_roots[0], 1, 2e-7);  // within the pair
  // A dip of 2e-12, well below the band: two roots 1 -+ 1e-6, then 2 and 3.
  const Coefficients deep = multiply({1 - 1e-12, -2, 1, 0, 0}, {6, -5, 1, 0, 0});
  const std::vector<double> deep_roots = realRoots(deep);
  ASSERT_EQ(deep_roots.size(), 4u);
  EXPECT_NEAR(deep_roots[0], 1 - 1e-6, conditionTolerance(deep, 1 - 1e-6));
  EXPECT_NEAR(deep_roots[1], 1 + 1e-6, conditionTolerance(deep, 1 + 1e-6));
  EXPECT_NEAR(deep_roots[2], 2, conditionTolerance(deep, 2));
  EXPECT_NEAR(deep_roots[3], 3, conditionTolerance(deep, 3));
}

TEST(PolynomialRootsTest, NearTangencyWithinRoundingCountsAsTouch) {
  // (t - 1)^2 + 2^-52: no real root in exact arithmetic, but its minimum lies inside the rounding
  // band of p: a grazing contact that the finder must report, never miss.
  const Coefficients grazing{1 + 0x1p-52, -2, 1, 0, 0};
  const RootSearchResult touch = smallestRootInInterval(grazing, 0, 2);
  ASSERT_TRUE(isRoot(touch));
  EXPECT_NEAR(touch.time, 1, kDoubleRootTolerance);
  EXPECT_EQ(realRoots(grazing).size(), 1u);

  // (t - 1)^2 + 1e-12 stays clear of zero by far more than the band: no root.
  const Coefficients clear{1 + 1e-12, -2, 1, 0, 0};
  EXPECT_EQ(smallestRootInInterval(clear, 0, 2).outcome, RootOutcome::NoRoot);
  EXPECT_TRUE(realRoots(clear).empty());
}

TEST(PolynomialRootsTest, QuarticWithTwoDoubleRoots) {
  // (t - 1)^2 (t - 3)^2 = t^4 - 8t^3 + 22t^2 - 24t + 9 (exact).
  const Coefficients c{9, -24, 22, -8, 1};
  const std::vector<double> roots = realRoots(c);
  ASSERT_EQ(roots.size(), 2u);
  EXPECT_NEAR(roots[0], 1, kDoubleRootTolerance);
  EXPECT_NEAR(roots[1], 3, kDoubleRootTolerance);
  EXPECT_NEAR(smallestRootInInterval(c, 0, 4).time, 1, kDoubleRootTolerance);
  EXPECT_NEAR(smallestRootInInterval(c, 2, 4).time, 3, kDoubleRootTolerance);
  EXPECT_EQ(smallestRootInInterval(c, 1.5, 2.5).outcome, RootOutcome::NoRoot);
  // A triple root: (t - 2)^3 (t + 1) = t^4 - 5t^3 + 6t^2 + 4t - 8.
  const Coefficients triple{-8, 4, 6, -5, 1};
  const RootSearchResult first = smallestRootInInterval(triple, 0, 4);
  ASSERT_TRUE(isRoot(first));
  // A triple root is located to the cube root of the rounding band: (10 u * 80)^(1/3) ~ 5e-5.
  constexpr double kTripleRootTolerance = 1e-4;
  EXPECT_NEAR(first.time, 2, kTripleRootTolerance);
}

// ---- Degree drops, huge and tiny coefficients ---------------------------------------------------

TEST(PolynomialRootsTest, VanishingLeadingCoefficientLowersTheDegree) {
  // (t - 0.5)(t - 1.5)(t - 3) = t^3 - 5t^2 + 6.75t - 2.25 (exact).
  const Coefficients cubic{-2.25, 6.75, -5, 1, 0};
  const std::vector<double> expected{0.5, 1.5, 3};
  for (double leading : {0.0, 1e-300, -1e-300, 1e-310}) {
    Coefficients c = cubic;
    c[4] = leading;
    SCOPED_TRACE("c4 = " + std::to_string(leading));
    const RootSearchResult first = smallestRootInInterval(c, 0, 10);
    ASSERT_TRUE(isRoot(first));
    EXPECT_NEAR(first.time, 0.5, conditionTolerance(cubic, 0.5));
    const std::vector<double> in_interval = rootsInInterval(c, 0, 10);
    ASSERT_EQ(in_interval.size(), 3u);
    for (int i = 0; i < 3; ++i)
      EXPECT_NEAR(in_interval[i], expected[i], conditionTolerance(cubic, expected[i]));

    std::vector<double> all = realRoots(c);
    // The fourth root, near -c3/c4 - (0.5 + 1.5 + 3) by Vieta, is there when it can be represented.
    const double huge = leading == 0 ? 0 : -1 / leading - 5;
    if (std::isfinite(huge) && huge != 0) {
      ASSERT_EQ(all.size(), 4u);
      const auto it = leading > 0 ? all.begin() : all.end() - 1;
      EXPECT_NEAR(*it, huge, 1e-12 * std::abs(huge));
      all.erase(it);
    }
    ASSERT_EQ(all.size(), 3u);
    for (int i = 0; i < 3; ++i)
      EXPECT_NEAR(all[i], expected[i], conditionTolerance(cubic, expected[i]));
  }
  // Linear and constant.
  EXPECT_EQ(smallestRootInInterval({-1, 2, 0, 0, 0}, 0, 1).time, 0.5);
  EXPECT_EQ(realRoots({-1, 2, 0, 0, 0}), std::vector<double>{0.5});
  EXPECT_EQ(smallestRootInInterval({3, 0, 0, 0, 0}, -5, 5).outcome, RootOutcome::NoRoot);
  EXPECT_TRUE(realRoots({3, 0, 0, 0, 0}).empty());
  // A quadratic with a tiny leading coefficient: 1e-300 t^2 + 2t - 1, roots 0.5 and about -2e300.
  const std::vector<double> tiny_quadratic = realRoots({-1, 2, 1e-300, 0, 0});
  ASSERT_EQ(tiny_quadratic.size(), 2u);
  EXPECT_NEAR(tiny_quadratic[0], -2e300, 1e-12 * 2e300);
  EXPECT_NEAR(tiny_quadratic[1], 0.5, 4 * kUnitRoundoff);
}

TEST(PolynomialRootsTest, ScaledCoefficientsGiveTheSameRoots) {
  std::mt19937_64 rng(3);
  for (int trial = 0; trial < 500; ++trial) {
    const int degree = 1 + trial % 4;
    const std::vector<double> roots =
        separatedRoots(rng, degree, -kRandomRootRange, kRandomRootRange, kRandomRootSeparation);
    const Coefficients c = fromRoots(randomSign(rng) * logUniform(rng, 1e-3, 1e3), roots);
    const std::vector<double> reference = realRoots(c);
    ASSERT_EQ(reference.size(), roots.size());
    // Decimal scale factors round every coefficient once more: the roots move within their
    // condition.
    for (double factor : {1e200, 1e-200}) {
      const std::vector<double> scaled = realRoots(scaledBy(c, factor));
      ASSERT_EQ(scaled.size(), reference.size()) << "trial " << trial << " factor " << factor;
      for (size_t i = 0; i < scaled.size(); ++i) {
        EXPECT_NEAR(scaled[i], reference[i], 2 * conditionTolerance(c, roots[i]));
      }
      const RootSearchResult a = smallestRootInInterval(c, -12, 12);
      const RootSearchResult b = smallestRootInInterval(scaledBy(c, factor), -12, 12);
      ASSERT_TRUE(isRoot(a) && isRoot(b));
      EXPECT_NEAR(a.time, b.time, 2 * conditionTolerance(c, roots[0]));
    }
    // Powers of two scale exactly: the answers are identical bit for bit.
    for (double factor : {0x1p600, 0x1p-600}) {
      EXPECT_EQ(realRoots(scaledBy(c, factor)), reference);
      EXPECT_EQ(rootsInInterval(scaledBy(c, factor), -12, 12), rootsInInterval(c, -12, 12));
    }
  }
}

TEST(PolynomialRootsTest, TinyAndHugeRootsKeepTheirRelativePrecision) {
  // (t - 1e150)(t - 1e-150) = t^2 - 1e150 t + 1 (1e150 + 1e-150 rounds to 1e150, the roots' sum).
  const std::vector<double> roots = realRoots({1, -1e150, 1, 0, 0});
  ASSERT_EQ(roots.size(), 2u);
  EXPECT_NEAR(roots[0], 1e-150, 8 * kUnitRoundoff * 1e-150);
  EXPECT_NEAR(roots[1], 1e150, 8 * kUnitRoundoff * 1e150);
  const RootSearchResult tiny = smallestRootInInterval({-1e-200, 1, 0, 0, 0}, 0, 1);
  ASSERT_TRUE(isRoot(tiny));
  EXPECT_NEAR(tiny.time, 1e-200, 4 * kUnitRoundoff * 1e-200);
  // An interval of astronomical length still finds the root near 1 of t^2 - 3t + 2.
  const RootSearchResult wide = smallestRootInInterval({2, -3, 1, 0, 0}, 0, 1e38);
  ASSERT_TRUE(isRoot(wide));
  EXPECT_NEAR(wide.time, 1, 4 * kUnitRoundoff);
}

// ---- No roots and roots at the interval ends ----------------------------------------------------

TEST(PolynomialRootsTest, NoRootWhenThereIsNone) {
  EXPECT_TRUE(realRoots({1, 0, 1, 0, 0}).empty());  // t^2 + 1
  EXPECT_TRUE(realRoots({4, 0, 5, 0, 1}).empty());  // (t^2 + 1)(t^2 + 4)
  const RootSearchResult none = smallestRootInInterval({4, 0, 5, 0, 1}, -100, 100);
  EXPECT_EQ(none.outcome, RootOutcome::NoRoot);
  EXPECT_EQ(none.time, kInfinity);  // never an early event if used unchecked
  // Roots exist, outside the interval: (t - 1)(t - 2)(t - 3)(t - 4) on [4.5, 10] and [-3, 0.9].
  const Coefficients c = fromRoots(1, {1, 2, 3, 4});
  EXPECT_EQ(smallestRootInInterval(c, 4.5, 10).outcome, RootOutcome::NoRoot);
  EXPECT_EQ(smallestRootInInterval(c, -3, 0.9).outcome, RootOutcome::NoRoot);
  EXPECT_EQ(smallestRootInInterval(c, 2.1, 2.9).outcome, RootOutcome::NoRoot);
  EXPECT_TRUE(rootsInInterval(c, 2.1, 2.9).empty());
}

TEST(PolynomialRootsTest, RootsAtTheIntervalEndsCount) {
  // (t - 0.5)(t - 2) = t^2 - 2.5t + 1 (exact): p is exactly 0 at both roots.
  const Coefficients c{1, -2.5, 1, 0, 0};
  EXPECT_EQ(smallestRootInInterval(c, 0.5, 1).time, 0.5);
  EXPECT_EQ(smallestRootInInterval(c, 0, 0.5).time, 0.5);
  EXPECT_EQ(smallestRootInInterval(c, 1, 2).time, 2);
  EXPECT_EQ(smallestRootInInterval(c, 2, 3).time, 2);
  EXPECT_EQ(smallestRootInInterval(c, 2, 2).time, 2);  // a single instant
  EXPECT_EQ(smallestRootInInterval(c, 1, 1).outcome, RootOutcome::NoRoot);
  EXPECT_EQ(rootsInInterval(c, 0.5, 2), (std::vector<double>{0.5, 2}));
  // A root one ulp beyond the end lies inside the rounding band there (10 u * 2 at t = 1): it
  // counts, at the end. Far beyond the band it does not.
  const Coefficients just_outside{-(1 + 0x1p-52), 1, 0, 0, 0};
  EXPECT_EQ(smallestRootInInterval(just_outside, 0, 1).time, 1);
  EXPECT_EQ(smallestRootInInterval({-(1 + 1e-12), 1, 0, 0, 0}, 0, 1).outcome, RootOutcome::NoRoot);
  // A quartic root at the end, reached through refinement elsewhere: (t - 1)(t - 2)(t - 3)(t - 4).
  const Coefficients quartic = fromRoots(1, {1, 2, 3, 4});
  EXPECT_EQ(smallestRootInInterval(quartic, 1, 1.5).time, 1);
  EXPECT_EQ(smallestRootInInterval(quartic, 3.5, 4).time, 4);
}

// ---- Closing roots of a gap function ------------------------------------------------------------

TEST(PolynomialRootsTest, FirstClosingRootSkipsSeparation) {
  // Gap (t - 0.5)(t - 2): closes at 0.5, opens at 2.
  const Coefficients gap{1, -2.5, 1, 0, 0};
  EXPECT_EQ(firstClosingRoot(gap, 0, 3).time, 0.5);
  EXPECT_EQ(firstClosingRoot(gap, 0.5, 3).time, 0.5);                     // touching, approaching
  EXPECT_EQ(firstClosingRoot(gap, 0.5, 0.5).time, 0.5);                   // an instant, approaching
  EXPECT_EQ(firstClosingRoot(gap, 1, 3).time, 1);                         // overlapping, closing
  EXPECT_EQ(firstClosingRoot(gap, 1.5, 3).outcome, RootOutcome::NoRoot);  // overlapping, opening
  EXPECT_EQ(firstClosingRoot(gap, 2, 3).outcome, RootOutcome::NoRoot);    // touching, separating
  EXPECT_EQ(firstClosingRoot(gap, 2, 2).outcome, RootOutcome::NoRoot);    // an instant, separating
  EXPECT_EQ(smallestRootInInterval(gap, 1.5, 3).time, 2);                 // (which is a root)
  // Overlapping and closing further: an event now.
  EXPECT_EQ(firstClosingRoot({-1, -1, 0, 0, 0}, 0, 1).time, 0);
  // Grazing (a double root) counts; touching at the start and then opening does not.
  const Coefficients graze{1, -2, 1, 0, 0};  // (t - 1)^2
  EXPECT_NEAR(firstClosingRoot(graze, 0, 2).time, 1, kDoubleRootTolerance);
  EXPECT_EQ(firstClosingRoot(graze, 1, 2).outcome, RootOutcome::NoRoot);
  // Gap (t - 1)(t - 2)(t - 3)(t - 4), positive before 1: closes at 1 and again at 3.
  const Coefficients quartic = fromRoots(1, {1, 2, 3, 4});
  EXPECT_NEAR(firstClosingRoot(quartic, 0, 5).time, 1, conditionTolerance(quartic, 1));
  EXPECT_NEAR(firstClosingRoot(quartic, 1.5, 5).time, 3, conditionTolerance(quartic, 3));
  EXPECT_EQ(firstClosingRoot(quartic, 3.5, 5).time, 3.5);  // overlapping, still closing (min ~3.62)
  EXPECT_EQ(firstClosingRoot(quartic, 3.7, 5).outcome, RootOutcome::NoRoot);
}

TEST(PolynomialRootsTest, FirstClosingRootCatchesAnOverlapThatTurnsBackBeforeOpening) {
  // Gap -(t - 1)^2 - 1e-6: overlapping throughout, opening until t = 1, closing after it. The
  // contact never separated, so where it turns back is an event (touching and approaching).
  const Coefficients turns_back{-1 - 1e-6, 2, -1, 0, 0};
  EXPECT_NEAR(firstClosingRoot(turns_back, 0, 3).time, 1, 1e-9);
  EXPECT_EQ(firstClosingRoot(turns_back, 0, 0.5).outcome, RootOutcome::NoRoot);  // still opening
  // Opening past zero first: the event is where it closes again through zero, not the turn.
  const Coefficients opens{-0.5, 0, 4, -4, 1};  // (t^2 - 2t)^2 - 0.5: opens at 0.46, peaks at 1
  const double closes = 1 + std::sqrt(1 - std::sqrt(0.5));  // t^2 - 2t = -sqrt(0.5) again
  EXPECT_NEAR(firstClosingRoot(opens, 0, 3).time, closes, conditionTolerance(opens, closes));
}

// ---- Inputs
// ---------------------------------------------------------------------------------------

TEST(PolynomialRootsTest, ZeroPolynomial) {
  const Coefficients zero{};
  const RootSearchResult r = smallestRootInInterval(zero, 2, 3);
  EXPECT_EQ(r.outcome, RootOutcome::Root);
  EXPECT_EQ(r.time, 2);
  EXPECT_EQ(firstClosingRoot(zero, 2, 3).time, 2);
  EXPECT_THROW(realRoots(zero), std::invalid_argument);
  EXPECT_THROW(rootsInInterval(zero, 0, 1), std::invalid_argument);
}

TEST(PolynomialRootsTest, BadInputIsRejected) {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  expectRejected([&] { smallestRootInInterval({1, nan, 0, 0, 0}, 0, 1); }, "c1 = nan");
  expectRejected([&] { realRoots({1, 0, 0, 0, kInfinity}); }, "c4 = inf");
  expectRejected([&] { smallestRootInInterval({1, 1, 0, 0, 0}, 2, 1); }, "t_lo = 2");
  expectRejected([&] { firstClosingRoot({1, 1, 0, 0, 0}, 0, kInfinity); }, "t_hi = inf");
  expectRejected([&] { rootsInInterval({1, 1, 0, 0, 0}, nan, 1); }, "t_lo = nan");
  expectRejected([&] { smallestRootInInterval({1, 1, 0, 0, 0}, 0, 1e39); }, "t_hi = 9.99");
}

// ---- Floating-point exceptions ------------------------------------------------------------------

// p times the exact power of two that brings its largest coefficient below 1 (what the finders do
// themselves): evaluating it cannot overflow anywhere in [-kMaxIntervalMagnitude,
// kMaxIntervalMagnitude], so a root can be checked even where the given coefficients would
// overflow.
Coefficients normalizedByAPowerOfTwo(Coefficients c) {
  double largest = 0;
  for (double x : c) largest = std::max(largest, std::abs(x));
  int exponent = 0;
  std::frexp(largest, &exponent);
  for (double& x : c) x = std::ldexp(x, -exponent);
  return c;
}

// A reported root is genuine: p lies within its rounding band there, or changes sign across it
// within kRootCheckUlps ulps either side (Newton stops when its step is down to ulps).
constexpr int kRootCheckUlps = 4;
bool isWithinRounding(const Coefficients& c, double t) {
  const Coefficients p = normalizedByAPowerOfTwo(c);
  auto sign = [&](double x) {
    const PolynomialValue v = evaluatePolynomialWithErrorBound(p, x);
    return std::abs(v.value) <= v.error_bound ? 0 : (v.value > 0 ? 1 : -1);
  };
  double below = t, above = t;
  for (int i = 0; i < kRootCheckUlps; ++i) {
    below = std::nextafter(below, -kInfinity);
    above = std::nextafter(above, kInfinity);
  }
  return sign(t) == 0 || sign(below) == 0 || sign(above) == 0 || sign(below) != sign(above);
}

// Every finder on the hard cases of this file and a few more extreme ones (subnormal and huge
// coefficients, ends at the interval limit, roots beyond 2^128) with invalid operations, division
// by zero and overflow trapped: no path may produce a NaN or an infinity on the way to an answer.
// The answers are then checked: roots in the interval, within rounding, as many as expected.
TEST(PolynomialRootsTest, HardCasesRaiseNoFloatingPointException) {
  constexpr double kSubnormal = std::numeric_limits<double>::denorm_min();
  constexpr double kLimit = kMaxIntervalMagnitude;
  struct Case {
    const char* name;
    Coefficients c;
    double lo, hi;
    int roots_in_interval;  // distinct roots rootsInInterval must report
  };
  const Case cases[] = {
      {"double root (t-1)^2 (t-2)(t-3)", {6, -17, 17, -7, 1}, 0, 5, 3},
      {"two double roots (t-1)^2 (t-3)^2", {9, -24, 22, -8, 1}, 0, 4, 2},
      {"triple root (t-2)^3 (t+1)", {-8, 4, 6, -5, 1}, -2, 4, 2},
      {"quadruple root (t-1)^4", {1, -4, 6, -4, 1}, 0, 2, 1},
      {"nearly double root, dip 1e-14", {1 - 1e-14, -2, 1, 0, 0}, 0, 2, 2},
      {"grazing within rounding", {1 + 0x1p-52, -2, 1, 0, 0}, 0, 2, 1},
      {"vanishing leading coefficient (subnormal)", {-2.25, 6.75, -5, 1, kSubnormal}, 0, 10, 3},
      {"subnormal coefficients only", {-kSubnormal, 2 * kSubnormal, 0, 0, 0}, 0, 1, 1},
      // 1e308 (t - 1)(t + 1)(t - 0.5): near the largest double.
      {"huge coefficients", {0.5e308, -1e308, -0.5e308, 1e308, 0}, -2, 2, 3},
      // Roots 1e-150 and 1e150; the second lies beyond the interval's limit.
      {"huge and tiny mixed", {1, -1e150, 1, 0, 0}, 0, 1e38, 1},
      {"interval at the magnitude limit", {-1, 0, 1, 0, 0}, -kLimit, kLimit, 2},
      {"quartic at the magnitude limit", {1, 0, 0, 0, 1e300}, -kLimit, kLimit, 0},
      {"tiny leading coefficient, root near -2e300", {-1, 2, 1e-300, 0, 0}, 0, 1, 1},
      {"an instant at a double root", {1, -2, 1, 0, 0}, 1, 1, 1},
      {"constant", {3, 0, 0, 0, 0}, -5, 5, 0},
  };
  for (const Case& k : cases) {
    SCOPED_TRACE(k.name);
    std::vector<double> all, in_interval;
    RootSearchResult smallest, closing;
    {
      test::FloatingPointTraps traps;
      all = realRoots(k.c);
      in_interval = rootsInInterval(k.c, k.lo, k.hi);
      smallest = smallestRootInInterval(k.c, k.lo, k.hi);
      closing = firstClosingRoot(k.c, k.lo, k.hi);
    }
    EXPECT_EQ(static_cast<int>(in_interval.size()), k.roots_in_interval);
    for (double r : in_interval) {
      EXPECT_TRUE(r >= k.lo && r <= k.hi && isWithinRounding(k.c, r)) << "root " << r;
    }
    for (double r : all) {
      EXPECT_TRUE(std::isfinite(r)) << r;
      if (std::abs(r) <= kLimit) {
        EXPECT_TRUE(isWithinRounding(k.c, r)) << "root " << r;
      }
    }
    EXPECT_EQ(isRoot(smallest), !in_interval.empty());
    if (isRoot(smallest)) {
      EXPECT_EQ(smallest.time, in_interval.front());
    }
    if (isRoot(closing)) {
      EXPECT_TRUE(closing.time >= k.lo && closing.time <= k.hi) << closing.time;
    }
  }
}

// ---- The error bound
// ------------------------------------------------------------------------------

TEST(PolynomialRootsTest, ErrorBoundBoundsTheEvaluationError) {
  static_assert(std::numeric_limits<long double>::digits >= 64,
                "the reference evaluation needs a wider type than double");
  std::mt19937_64 rng(4);
  std::uniform_real_distribution<double> unit(-1, 1);
  double worst_ratio = 0;
  for (int trial = 0; trial < 20000; ++trial) {
    Coefficients c;
    for (double& x : c) x = unit(rng) * logUniform(rng, 1e-3, 1e3);
    const double t = unit(rng) * 10;
    long double exact = 0;
    for (int i = 4; i >= 0; --i) exact = exact * t + c[i];
    const PolynomialValue v = evaluatePolynomialWithErrorBound(c, t);
    const double error = static_cast<double>(std::abs(static_cast<long double>(v.value) - exact));
    EXPECT_LE(error, v.error_bound) << "trial " << trial;
    worst_ratio = std::max(worst_ratio, error / v.error_bound);
  }
  // The bound is not vacuous: rounding errors reach a visible part of it.
  EXPECT_GT(worst_ratio, 0.01);
}

// ---- Brute force: a dense scan never finds a root the finder misses
// --------------------------------

// Random quartics on [0, 4] from families rich in the hard cases.
Coefficients randomQuartic(std::mt19937_64& rng, int family) {
  std::uniform_real_distribution<double> in_range(-1, 5);
  std::uniform_real_distribution<double> on_horizon(0, 4);
  const double leading = randomSign(rng) * logUniform(rng, 1e-2, 1e2);
  switch (family) {
    case 0:  // four simple real roots
      return fromRoots(leading, {in_range(rng), in_range(rng), in_range(rng), in_range(rng)});
    case 1:  // a double root and two simple ones
    {
      const double r = on_horizon(rng);
      return fromRoots(leading, {r, r, in_range(rng), in_range(rng)});
    }
    case 2:  // a nearly double root, dipping through zero or staying just clear of it
    {
      const double r = on_horizon(rng);
      const double offset = randomSign(rng) * logUniform(rng, 1e-16, 1e-3);
      const Coefficients near_double{r * r + offset, -2 * r, 1, 0, 0};
      const Coefficients rest = (rng() & 1) ? fromRoots(leading, {in_range(rng), in_range(rng)})
                                            : Coefficients{leading * 1.5, 0, leading, 0, 0};
      return multiply(near_double, rest);
    }
    case 3:  // two complex pairs close to the real axis: near-touches with no real root
    {
      Coefficients p{leading, 0, 0, 0, 0};
      for (int pair = 0; pair < 2; ++pair) {
        const double a = on_horizon(rng);
        const double b = logUniform(rng, 1e-9, 1);
        p = multiply(p, {a * a + b * b, -2 * a, 1, 0, 0});
      }
      return p;
    }
    case 4:  // a triple root and a simple one
    {
      const double r = on_horizon(rng);
      return fromRoots(leading, {r, r, r, in_range(rng)});
    }
    default:  // random coefficients
    {
      Coefficients c;
      for (double& x : c) x = leading * std::uniform_real_distribution<double>(-1, 1)(rng);
      return c;
    }
  }
}

TEST(PolynomialRootsTest, DenseScanFindsNoRootTheFinderMisses) {
  constexpr double kHorizon = 4.0;   // search [0, kHorizon]
  constexpr int kScanPoints = 4001;  // spacing 1e-3
  constexpr int kQuartics = 3000;
  // A scanned touch counts when the minimum of |p| found by the scan lies well inside the rounding
  // band (half of it), so that the finder's and the scan's different evaluation points cannot split
  // a knife-edge case.
  constexpr double kScanTouchFraction = 0.5;
  // The finder's root may lie after the scan cell that shows a root only inside the same rounding
  // band: around a multiple root |p| stays within its bound over a stretch (double root:
  // sqrt(band / |p''|) ~ 1e-7; nearly quadruple: (band / |c4|)^(1/4) ~ 3e-4), and a noisy sign
  // change seen by the scan and the root the finder reports may sit anywhere in it. The check
  // samples the stretch between them this densely; any sample clear of the band means a missed
  // root.
  constexpr int kBandSamples = 200;
  // A root the finder reports is genuine if |p| there is within twice its rounding band (the band
  // plus the slope times an ulp, itself below the band) or p changes sign across it.
  constexpr double kGenuineRootBands = 2;

  std::mt19937_64 rng(5);
  int scan_found = 0, scan_touches = 0, finder_only = 0, later_in_band = 0;
  for (int n = 0; n < kQuartics; ++n) {
    const Coefficients c = randomQuartic(rng, n % 6);
    const auto p = [&](double t) { return evaluatePolynomialWithErrorBound(c, t); };
    const auto scanTime = [&](int j) { return kHorizon * j / (kScanPoints - 1); };

    // The scan: the first cell with a sign change, or the first local minimum of |p| that a golden
    // section search brings inside the rounding band. It gives the latest time the first root may
    // have.
    double scan_first = kInfinity;
    bool scan_touch = false;
    if (std::abs(p(0).value) <= kScanTouchFraction * p(0).error_bound) scan_first = 0;
    double previous = p(0).value;
    for (int j = 1; j < kScanPoints && scan_first == kInfinity; ++j) {
      const double value = p(scanTime(j)).value;
      if (value == 0 || (value < 0) != (previous < 0)) {
        scan_first = scanTime(j);
        break;
      }
      const double next = j + 1 < kScanPoints ? p(scanTime(j + 1)).value : value;
      if (std::abs(value) <= std::abs(previous) && std::abs(value) <= std::abs(next)) {
        double lo = scanTime(j - 1), hi = scanTime(std::min(j + 1, kScanPoints - 1));
        const double golden = (std::sqrt(5.0) - 1) / 2;
        for (int k = 0; k < 100; ++k) {
          const double m1 = hi - golden * (hi - lo), m2 = lo + golden * (hi - lo);
          if (std::abs(p(m1).value) <= std::abs(p(m2).value))
            hi = m2;
          else
            lo = m1;
        }
        const PolynomialValue at_min = p(0.5 * (lo + hi));
        if (std::abs(at_min.value) <= kScanTouchFraction * at_min.error_bound) {
          scan_first = scanTime(std::min(j + 1, kScanPoints - 1));
          scan_touch = true;
        }
      }
      previous = value;
    }

    const RootSearchResult found = smallestRootInInterval(c, 0, kHorizon);
    if (scan_first != kInfinity) {
      ++scan_found;
      scan_touches += scan_touch;
      ASSERT_TRUE(isRoot(found)) << "quartic " << n << ": the scan found a root by " << scan_first;
      if (found.time > scan_first) {
        ++later_in_band;
        for (int k = 0; k <= kBandSamples; ++k) {
          const PolynomialValue between =
              p(scan_first + (found.time - scan_first) * k / kBandSamples);
          ASSERT_LE(std::abs(between.value), between.error_bound)
              << "quartic " << n << ": a root by " << scan_first << " missed, found " << found.time;
        }
      }
    }
    if (isRoot(found)) {
      finder_only += scan_first == kInfinity;
      const PolynomialValue at = p(found.time);
      const double before = p(std::nextafter(found.time, -kInfinity)).value;
      const double after = p(std::nextafter(found.time, kInfinity)).value;
      const bool genuine =
          std::abs(at.value) <= kGenuineRootBands * at.error_bound || (before < 0) != (after < 0);
      EXPECT_TRUE(genuine) << "quartic " << n << ": p(" << found.time << ") = " << at.value
                           << ", band " << at.error_bound;
      // The smallest root is the first of all roots, bit for bit.
      const std::vector<double> all = rootsInInterval(c, 0, kHorizon);
      ASSERT_FALSE(all.empty());
      EXPECT_EQ(all.front(), found.time) << "quartic " << n;
    }
  }
  // Every kind of case occurred: roots, touches found only by the minimum scan, and no roots.
  EXPECT_GT(scan_found, kQuartics / 2);
  EXPECT_GT(scan_touches, 50);
  EXPECT_LT(scan_found + finder_only, kQuartics);
  EXPECT_LT(later_in_band, kQuartics / 100);  // the band excuse stays rare
}

}  // namespace
}  // namespace baize::physics
