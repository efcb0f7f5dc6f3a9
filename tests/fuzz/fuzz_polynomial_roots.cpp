// Fuzz target: the root finders of physics/polynomial_roots.h on arbitrary coefficients and
// intervals (NaN, infinities, huge, tiny, subnormal; double and nearly double roots built from
// factors). Every call returns or throws std::invalid_argument, and throws exactly when the input
// breaks the documented rules. A returned root lies in the interval and is a root: p is within its
// rounding bound there or changes sign within a few ulps. No root is missed: p sampled on a grid
// never changes sign (beyond its rounding bound) where no root was reported.
#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <stdexcept>
#include <string>
#include <vector>

#include "physics/polynomial_roots.h"
#include "tests/fuzz/fuzz_support.h"

namespace {

using baize::fuzz::check;
using baize::physics::PolynomialCoefficients;

// A root refined to "the step is down to ulps" may sit this many ulps from where the computed p
// changes sign or enters its rounding band.
constexpr int kRootUlps = 4;
// Grid points per interval for the "no root is missed" check.
constexpr int kGridPoints = 64;

// The coefficients times an exact power of two that brings the largest below 1, as the finders do
// themselves: evaluating these cannot overflow for |t| <= kMaxIntervalMagnitude.
PolynomialCoefficients normalized(PolynomialCoefficients c) {
  double largest = 0;
  for (double x : c) largest = std::max(largest, std::abs(x));
  if (largest == 0) return c;
  int exponent = 0;
  std::frexp(largest, &exponent);
  for (double& x : c) x = std::ldexp(x, -exponent);
  return c;
}

// The sign of p(t), 0 when the value lies within its rounding bound.
int sign(const PolynomialCoefficients& p, double t) {
  const auto v = baize::physics::evaluatePolynomialWithErrorBound(p, t);
  if (std::abs(v.value) <= v.error_bound) return 0;
  return v.value > 0 ? 1 : -1;
}

// t is a root of p as the rounding allows: p is within its bound at t, or changes sign within
// kRootUlps ulps of t.
bool isRoot(const PolynomialCoefficients& p, double t) {
  if (sign(p, t) == 0) return true;
  double below = t, above = t;
  for (int i = 0; i < kRootUlps; ++i) {
    below = std::nextafter(below, -INFINITY);
    above = std::nextafter(above, INFINITY);
  }
  const int s_below = sign(p, below), s_above = sign(p, above);
  return s_below == 0 || s_above == 0 || s_below != s_above;
}

// The grid points [lo, hi] of the "no missed root" checks.
std::vector<double> grid(double lo, double hi) {
  std::vector<double> t(kGridPoints + 1);
  for (int i = 0; i <= kGridPoints; ++i)
    t[i] = lo + (hi - lo) * (static_cast<double>(i) / kGridPoints);
  t[kGridPoints] = hi;
  return t;
}

bool anyRootIn(const std::vector<double>& roots, double a, double b) {
  for (double r : roots) {
    if (r >= a && r <= b) return true;
  }
  return false;
}

std::string describe(const PolynomialCoefficients& c, double lo, double hi) {
  char text[256];
  std::snprintf(text, sizeof text, "c = {%a, %a, %a, %a, %a} on [%a, %a]", c[0], c[1], c[2], c[3],
                c[4], lo, hi);
  return text;
}

// Coefficients from the input: either directly (any values) or as leading * prod (t - r_i) with
// roots that may coincide or nearly coincide (double and nearly double roots) and leading
// coefficients that may vanish.
PolynomialCoefficients coefficientsFrom(baize::fuzz::FuzzInput& in) {
  PolynomialCoefficients c{};
  if (in.byte() % 2 == 0) {
    for (double& x : c) {
      const double mantissa = in.value(1.0);  // read before the exponent: a fixed byte order
      x = std::ldexp(mantissa, in.integer(-70, 70));
    }
    return c;
  }
  const int degree = in.integer(0, 4);
  double roots[4];
  for (int i = 0; i < degree; ++i) {
    const int how = i == 0 ? 0 : in.byte() % 3;
    if (how == 1) {
      roots[i] = roots[i - 1];  // a double root
    } else if (how == 2) {      // a nearly double root, a few ulps to far apart
      roots[i] = roots[i - 1] +
                 std::ldexp(roots[i - 1] == 0 ? 1.0 : std::abs(roots[i - 1]), -in.integer(1, 60));
    } else {
      roots[i] = in.value(4.0);
    }
  }
  c = {in.value(1.0), 0, 0, 0, 0};    // the leading coefficient, multiplied out below
  for (int i = 0; i < degree; ++i) {  // c <- c * (t - r_i)
    for (int k = i + 1; k >= 1; --k) c[k] = c[k - 1] - roots[i] * c[k];
    c[0] = -roots[i] * c[0];
  }
  return c;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  namespace phys = baize::physics;
  baize::fuzz::FuzzInput in(data, size);
  const PolynomialCoefficients c = coefficientsFrom(in);
  const double lo = in.value(4.0);
  const double hi = in.byte() % 4 == 0 ? in.value(4.0) : lo + std::abs(in.value(4.0));

  bool finite_coefficients = true, zero = true;
  for (double x : c) {
    finite_coefficients = finite_coefficients && std::isfinite(x);
    zero = zero && x == 0;
  }
  const bool valid_interval = std::isfinite(lo) && std::isfinite(hi) && lo <= hi &&
                              std::abs(lo) <= phys::kMaxIntervalMagnitude &&
                              std::abs(hi) <= phys::kMaxIntervalMagnitude;
  const bool valid = finite_coefficients && valid_interval;
  const std::string where = describe(c, lo, hi);
  const PolynomialCoefficients p = normalized(c);

  // realRoots: every real root.
  try {
    const std::vector<double> roots = phys::realRoots(c);
    check(finite_coefficients && !zero, "realRoots accepted an invalid polynomial: " + where);
    for (std::size_t i = 0; i < roots.size(); ++i) {
      check(std::isfinite(roots[i]), "realRoots returned a non-finite root: " + where);
      check(i == 0 || roots[i - 1] < roots[i], "realRoots not increasing: " + where);
      if (std::abs(roots[i]) <= phys::kMaxIntervalMagnitude) {
        check(isRoot(p, roots[i]), "realRoots returned a non-root: " + where);
      }
    }
  } catch (const std::invalid_argument&) {
    check(!finite_coefficients || zero, "realRoots refused a valid polynomial: " + where);
  }

  // rootsInInterval: every root in [lo, hi]; none missed between grid points of opposite sign.
  std::vector<double> roots;
  try {
    roots = phys::rootsInInterval(c, lo, hi);
    check(valid && !zero, "rootsInInterval accepted invalid input: " + where);
    for (std::size_t i = 0; i < roots.size(); ++i) {
      check(roots[i] >= lo && roots[i] <= hi, "rootsInInterval root outside: " + where);
      check(i == 0 || roots[i - 1] < roots[i], "rootsInInterval not increasing: " + where);
      check(isRoot(p, roots[i]), "rootsInInterval returned a non-root: " + where);
    }
    const std::vector<double> t = grid(lo, hi);
    for (int i = 0; i < kGridPoints; ++i) {
      const int a = sign(p, t[i]), b = sign(p, t[i + 1]);
      if (a * b < 0) {
        check(anyRootIn(roots, t[i], t[i + 1]), "rootsInInterval missed a sign change: " + where);
      }
    }
  } catch (const std::invalid_argument&) {
    check(!valid || zero, "rootsInInterval refused valid input: " + where);
    if (!valid) {
      // The other finders refuse the same input.
      bool threw = false;
      try {
        phys::smallestRootInInterval(c, lo, hi);
      } catch (const std::invalid_argument&) {
        threw = true;
      }
      check(threw, "smallestRootInInterval accepted invalid input: " + where);
      threw = false;
      try {
        phys::firstClosingRoot(c, lo, hi);
      } catch (const std::invalid_argument&) {
        threw = true;
      }
      check(threw, "firstClosingRoot accepted invalid input: " + where);
      return 0;
    }
  }

  // smallestRootInInterval: the first of those roots (the zero polynomial: lo).
  const phys::RootSearchResult smallest = phys::smallestRootInInterval(c, lo, hi);
  if (zero) {
    check(smallest.outcome == phys::RootOutcome::Root && smallest.time == lo,
          "the zero polynomial's smallest root is not t_lo: " + where);
  } else if (smallest.outcome == phys::RootOutcome::Root) {
    check(smallest.time >= lo && smallest.time <= hi, "smallest root outside: " + where);
    check(isRoot(p, smallest.time), "smallestRootInInterval returned a non-root: " + where);
    check(!roots.empty() && roots.front() == smallest.time,
          "smallestRootInInterval disagrees with rootsInInterval: " + where);
  } else {
    check(std::isinf(smallest.time), "NoRoot with a finite time: " + where);
    check(roots.empty(), "smallestRootInInterval missed a root rootsInInterval found: " + where);
  }

  // firstClosingRoot: at the event the gap is closed (within rounding); no falling crossing of
  // zero on the grid before it.
  const phys::RootSearchResult closing = phys::firstClosingRoot(c, lo, hi);
  const double end = closing.outcome == phys::RootOutcome::Root ? closing.time : hi;
  if (closing.outcome == phys::RootOutcome::Root) {
    check(closing.time >= lo && closing.time <= hi, "closing root outside: " + where);
    double t = closing.time;
    bool closed = sign(p, t) <= 0;
    for (int i = 0; i < kRootUlps && !closed; ++i) {
      t = std::nextafter(t, INFINITY);
      closed = sign(p, t) <= 0;
    }
    check(closed, "firstClosingRoot returned a time where the gap is open: " + where);
  } else {
    check(std::isinf(closing.time), "NoRoot with a finite time: " + where);
  }
  const std::vector<double> t = grid(lo, hi);
  for (int i = 0; i < kGridPoints && t[i + 1] < end; ++i) {
    check(!(sign(p, t[i]) > 0 && sign(p, t[i + 1]) < 0),
          "firstClosingRoot missed an earlier closing: " + where);
  }
  return 0;
}
