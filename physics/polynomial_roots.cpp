#include "physics/polynomial_roots.h"

#include <algorithm>
#include <climits>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <sstream>
#include <stdexcept>
#include <string>

namespace baize::physics {
namespace {

constexpr double kUnitRoundoff = 0x1p-53;  // u: half the gap between 1 and the next double

// Keeps the error bound positive where the sum of magnitudes underflows: subnormal arithmetic has
// an absolute, not a relative, rounding error (half of denorm_min per operation, 8 operations).
constexpr double kUnderflowFloor = 8 * std::numeric_limits<double>::denorm_min();

// Newton has converged when its step is at most 2 ulps of the iterate (relative 4u): the next step
// would only move the root within the rounding of its own evaluation.
constexpr double kNewtonConvergedRelativeStep = 4 * kUnitRoundoff;

// Refinement: every kProgressWindow steps the bracket loses half its doubles or a bisection
// follows, which leaves at most 2/3 of them (see bisectionPoint). From at most 2^64 doubles,
// adjacent ones are reached within (kProgressWindow + 1) * 110 steps; the cap is a margin above
// that, never the stop.
constexpr int kProgressWindow = 4;
constexpr int kMaxRefinementSteps = 600;

// A bracket whose ends differ by at most this factor (same sign) is bisected at its arithmetic
// midpoint; a wider one at its median double, which closes in on a root near 0 as fast as on any.
constexpr double kArithmeticBisectionMaxRatio = 4;

// log2 of kMaxIntervalMagnitude.
constexpr int kMaxIntervalExponent = 128;

enum class Mode { AllRoots, FirstRoot, FirstClosingRoot };

struct Polynomial {
  std::array<double, 5> c{};  // lowest power first
  int degree = -1;  // highest power with a nonzero coefficient; -1 for the zero polynomial
};

Polynomial makePolynomial(const std::array<double, 5>& c) {
  Polynomial p;
  p.c = c;
  for (int i = 4; i >= 0; --i) {
    if (c[i] != 0) {
      p.degree = i;
      break;
    }
  }
  return p;
}

// The search runs on polynomials of a fixed degree D (the degree of the given one, then of its
// derivatives): Horner's rule and the loops over coefficients unroll, and nothing tests the degree
// again. The arithmetic is that of a runtime degree, operation for operation.
template <int D>
struct Fixed {
  static_assert(D >= 0 && D <= 4);
  std::array<double, D + 1> c;  // lowest power first; c[D] != 0
};

template <int D>
Fixed<D> fixedOf(const Polynomial& p) {
  Fixed<D> f;
  for (int i = 0; i <= D; ++i) f.c[i] = p.c[i];
  return f;
}

template <int D>
Fixed<D - 1> derivative(const Fixed<D>& p) {
  static constexpr double kPower[5] = {0, 1, 2, 3, 4};  // i as a double: read, not converted
  Fixed<D - 1> d;
  for (int i = 1; i <= D; ++i) d.c[i - 1] = kPower[i] * p.c[i];  // never 0 when c_i is not
  return d;
}

// Horner's rule, with the running sum of magnitudes sum |c_i| |t|^i for the error bound.
template <int D>
PolynomialValue evaluate(const Fixed<D>& p, double t) {
  double value = p.c[D];
  double magnitude = std::abs(value);
  const double abs_t = std::abs(t);
  for (int i = D - 1; i >= 0; --i) {
    value = value * t + p.c[i];
    magnitude = magnitude * abs_t + std::abs(p.c[i]);
  }
  return {value, kPolynomialErrorUnitRoundoffs * kUnitRoundoff * magnitude + kUnderflowFloor};
}

// The same for a polynomial of any degree (the zero polynomial: 0 within the underflow floor).
PolynomialValue evaluate(const Polynomial& p, double t) {
  switch (p.degree) {
    case 0: return evaluate(fixedOf<0>(p), t);
    case 1: return evaluate(fixedOf<1>(p), t);
    case 2: return evaluate(fixedOf<2>(p), t);
    case 3: return evaluate(fixedOf<3>(p), t);
    case 4: return evaluate(fixedOf<4>(p), t);
    default: return {0.0, kUnderflowFloor};
  }
}

// A piece end: where it is, the computed value, and its sign with values inside the error bound
// counted as zero.
// Left uninitialized by default (no member initializers): collectRoots() keeps an array of them per
// call and reads only the ones it wrote; zeroing all of them cost a tenth of a search.
struct Sample {
  double t;
  double value;
  int sign;  // -1, 0 (within rounding of zero) or +1
};

template <int D>
Sample sampleAt(const Fixed<D>& p, double t) {
  const PolynomialValue v = evaluate(p, t);
  const int sign = std::abs(v.value) <= v.error_bound ? 0 : (v.value > 0 ? 1 : -1);
  return {t, v.value, sign};
}

// Doubles mapped to integers in the same order, so that the midpoint of two integers is the median
// double of a bracket: bisection then halves the count of doubles left and always terminates, and a
// bracket like [0, 1] closes in on a tiny root as fast as on one near 1. +0 and -0 both map to 0.
std::int64_t orderedIndex(double x) {
  std::int64_t bits;
  std::memcpy(&bits, &x, sizeof bits);
  return bits >= 0 ? bits : std::numeric_limits<std::int64_t>::min() - bits;
}

double fromOrderedIndex(std::int64_t index) {
  const std::int64_t bits = index >= 0 ? index : std::numeric_limits<std::int64_t>::min() - index;
  double x;
  std::memcpy(&x, &bits, sizeof x);
  return x;
}

std::uint64_t doublesBetween(double lo, double hi) {
  return static_cast<std::uint64_t>(orderedIndex(hi)) -
         static_cast<std::uint64_t>(orderedIndex(lo));
}

double orderedMidpoint(double lo, double hi) {
  const std::int64_t a = orderedIndex(lo);
  const std::int64_t b = orderedIndex(hi);
  return fromOrderedIndex((a >> 1) + (b >> 1) +
                          (a & b & 1));  // floor((a + b) / 2) without overflow
}

// The point splitting [lo, hi] (lo < hi, at least one double strictly inside). Each choice leaves
// at most 2/3 of the bracket's doubles on either side: 0 when the ends have opposite signs (the
// doubles crowd near 0), the arithmetic midpoint when they are within a factor of 4 (the density of
// doubles changes by at most 4 across the bracket), the median double otherwise.
double bisectionPoint(double lo, double hi) {
  if (lo < 0 && hi > 0) return 0.0;
  const double small = std::min(std::abs(lo), std::abs(hi));
  const double large = std::max(std::abs(lo), std::abs(hi));
  if (small > 0 && large <= kArithmeticBisectionMaxRatio * small) {
    const double mid = lo + 0.5 * (hi - lo);
    if (mid > lo && mid < hi) return mid;
  }
  return orderedMidpoint(lo, hi);
}

// The root of p in [lo, hi], given computed values of opposite signs (neither zero) at the ends.
// A Newton step is taken when it lands inside the bracket and moves at most half as far as the step
// before it (so a converging Newton iteration runs on); otherwise the bracket is bisected. Newton
// alone may approach from one side and leave the far end where it is, so every kProgressWindow
// steps the bracket must have lost half its doubles, or the next step is a bisection: the search
// always ends, at adjacent doubles at the latest.
template <int D>
double refineBracketedRoot(const Fixed<D>& p, const Fixed<D - 1>& dp, double lo, double value_lo,
                           double hi, double value_hi) {
  const bool rising = value_lo < 0;
  // First guess: where the chord crosses zero (exact for a straight line), or for a quadratic its
  // root in the bracket from the closed form (Newton then only polishes it).
  double x = lo + (hi - lo) * (value_lo / (value_lo - value_hi));
  if constexpr (D == 2) {
    const double a = p.c[2], b = p.c[1], c = p.c[0];
    const double discriminant = b * b - 4 * a * c;
    if (discriminant >= 0) {
      // The cancellation-free pair: q = -(b + sign(b) sqrt(D)) / 2, roots q / a and c / q.
      const double q = -0.5 * (b + std::copysign(std::sqrt(discriminant), b));
      for (const double root : {q / a, c / q}) {
        if (root > lo && root < hi) x = root;
      }
    }
  }
  if (!(x > lo && x < hi)) x = bisectionPoint(lo, hi);
  double previous_move = hi - lo;
  std::uint64_t count_at_window_start = doublesBetween(lo, hi);
  int steps_in_window = 0;
  for (int step = 0; step < kMaxRefinementSteps; ++step) {
    const PolynomialValue at_x = evaluate(p, x);
    const double value = at_x.value;
    if (value == 0) return x;
    if ((value < 0) == rising) {
      lo = x;
      value_lo = value;
    } else {
      hi = x;
      value_hi = value;
    }
    const std::uint64_t count = doublesBetween(lo, hi);
    if (count <= 1) break;
    // A zero slope gives an infinite or NaN step, which the inside test rejects.
    const double newton = x - value / evaluate(dp, x).value;
    const double move = std::abs(newton - x);
    const bool inside = newton > lo && newton < hi;
    // Converged: x lies in the rounding band of p, where further steps would only follow the
    // rounding noise, or the step is down to ulps.
    if (std::abs(value) <= at_x.error_bound || move <= kNewtonConvergedRelativeStep * std::abs(x)) {
      if (inside && std::abs(evaluate(p, newton).value) < std::abs(value)) return newton;
      return x;
    }
    bool use_newton = inside && move <= 0.5 * previous_move;
    if (++steps_in_window == kProgressWindow) {
      if (count > count_at_window_start / 2) use_newton = false;
      count_at_window_start = count;
      steps_in_window = 0;
    }
    if (use_newton) {
      previous_move = move;
      x = newton;
    } else {
      x = bisectionPoint(lo, hi);
      previous_move = hi - lo;  // after a bisection, any Newton step inside the bracket may follow
    }
  }
  return std::abs(value_lo) <= std::abs(value_hi) ? lo : hi;
}

// Roots found in increasing order, each once. A quartic has at most 5 piece ends and 4 pieces, each
// giving at most one root.
struct RootList {
  static constexpr int kCapacity = 9;
  std::array<double, kCapacity> values;  // the first `count` are set (not zeroed: see Sample)
  int count = 0;
  void add(double t) {
    if (count < kCapacity && (count == 0 || t > values[count - 1])) values[count++] = t;
  }
};

// In FirstClosingRoot mode: is the zero-valued piece end `j` an instant at which the gap closes?
template <int D>
bool closesAt(const Fixed<D>& dp, const Sample* ends, int count, int j) {
  if (count == 1) {  // a single instant: closing unless clearly rising there
    const PolynomialValue slope = evaluate(dp, ends[0].t);
    return slope.value <= slope.error_bound;
  }
  if (j == 0) return ends[1].sign <= 0;  // touching at the start: closing unless it rises
  if (j == count - 1) return ends[j - 1].sign >= 0;  // reaching zero at the end: unless from below
  return !(ends[j - 1].sign < 0 && ends[j + 1].sign > 0);  // interior: unless rising through zero
}

// Roots of p (degree D >= 1) in [a, b], a <= b.
template <int D>
RootList collectRoots(const Fixed<D>& p, double a, double b, Mode mode) {
  RootList roots;
  const Fixed<D - 1> dp = derivative(p);

  // Piece ends: a, the critical points inside (a, b), b. p is monotone on each piece. A line has
  // no critical points: two ends.
  constexpr int kMaxEnds = D >= 2 ? RootList::kCapacity + 2 : 2;
  std::array<Sample, kMaxEnds> ends;
  if constexpr (D == 1) ends = {};  // cheap for two; spares GCC 12 a false -Wmaybe-uninitialized
  int count = 0;
  ends[count++] = sampleAt(p, a);
  if constexpr (D >= 2) {
    if (a < b) {
      const RootList critical = collectRoots(dp, a, b, Mode::AllRoots);
      for (int i = 0; i < critical.count; ++i) {
        const double t = critical.values[i];
        if (t > ends[count - 1].t && t < b) ends[count++] = sampleAt(p, t);
      }
    }
  }
  if (b > a) ends[count++] = sampleAt(p, b);

  const bool first_only = mode != Mode::AllRoots;
  // The zero end j was reported already: as the crossing that led into its band, or as the zero end
  // just before it.
  bool reached = false;
  for (int j = 0; j < count; ++j) {
    const Sample& end = ends[j];
    if (end.sign == 0) {
      if (!reached && (mode != Mode::FirstClosingRoot || closesAt(dp, ends.data(), count, j))) {
        roots.add(end.t);
        if (first_only) return roots;
      }
      reached = true;  // a zero end right after it lies in the same band: the same root
      continue;
    }
    if (mode == Mode::FirstClosingRoot && j == 0 && end.sign < 0) {
      // Overlapping at the start: an event now unless the gap is opening.
      const bool opening = count == 1 ? evaluate(dp, a).value > 0 : ends[1].value > end.value;
      if (!opening) {
        roots.add(a);
        return roots;
      }
    }
    if (mode == Mode::FirstClosingRoot && j > 0 && end.sign < 0 && j + 1 < count &&
        ends[j + 1].value < end.value) {
      // Still overlapping where an opening gap turns back to closing (it started overlapping and
      // never opened past zero): touching and approaching from here on.
      roots.add(end.t);
      return roots;
    }
    if (j + 1 < count) {
      const Sample& next = ends[j + 1];
      // p crosses zero inside the piece when the next end has the other sign, or lies within the
      // rounding band of zero with a computed value of the other sign: then the crossing is where p
      // enters the band, possibly well before the end (the band around a triple root is wide).
      const bool crosses = next.sign != 0 ? next.sign != end.sign
                                          : next.value != 0 && (next.value > 0) != (end.sign > 0);
      const bool wanted = mode != Mode::FirstClosingRoot || end.sign > 0;
      if (crosses && wanted) {
        roots.add(refineBracketedRoot(p, dp, end.t, end.value, next.t, next.value));
        if (first_only) return roots;
        reached = next.sign == 0;
        continue;
      }
    }
    reached = false;
  }
  return roots;
}

// Roots of p (not the zero polynomial) in [a, b], a <= b: the search at p's degree.
RootList collectRoots(const Polynomial& p, double a, double b, Mode mode) {
  switch (p.degree) {
    case 1: return collectRoots(fixedOf<1>(p), a, b, mode);
    case 2: return collectRoots(fixedOf<2>(p), a, b, mode);
    case 3: return collectRoots(fixedOf<3>(p), a, b, mode);
    case 4: return collectRoots(fixedOf<4>(p), a, b, mode);
    default: return RootList{};  // a nonzero constant
  }
}

std::string show(double value) {
  std::ostringstream out;
  out.precision(17);
  out << value;
  return out.str();
}

// The messages for rejected input, in functions of their own: the checks below run for every
// prediction and stay a few comparisons when they do not build strings inline.
[[noreturn]] void rejectCoefficient(int i, double value) {
  throw std::invalid_argument("polynomial coefficient c" + std::to_string(i) + " = " + show(value) +
                              " is not allowed: every coefficient must be a finite number");
}

[[noreturn]] void rejectInterval(double t_lo, double t_hi) {
  if (!std::isfinite(t_lo)) {
    throw std::invalid_argument("root search interval start t_lo = " + show(t_lo) +
                                " is not allowed: it must be a finite number");
  }
  if (!std::isfinite(t_hi)) {
    throw std::invalid_argument("root search interval end t_hi = " + show(t_hi) +
                                " is not allowed: it must be a finite number");
  }
  if (std::abs(t_lo) > kMaxIntervalMagnitude || std::abs(t_hi) > kMaxIntervalMagnitude) {
    const bool start = std::abs(t_lo) > kMaxIntervalMagnitude;
    throw std::invalid_argument(
        std::string("root search interval ") + (start ? "start t_lo = " : "end t_hi = ") +
        show(start ? t_lo : t_hi) + " is not allowed: both ends must lie in [-2^128, 2^128] = [-" +
        show(kMaxIntervalMagnitude) + ", " + show(kMaxIntervalMagnitude) + "]");
  }
  throw std::invalid_argument("root search interval start t_lo = " + show(t_lo) +
                              " is not allowed: it must not exceed the end t_hi = " + show(t_hi));
}

void validateCoefficients(const PolynomialCoefficients& c) {
  for (int i = 0; i < 5; ++i) {
    if (!std::isfinite(c[i])) rejectCoefficient(i, c[i]);
  }
}

// (Not finite fails the magnitude test too: NaN compares false, so it is tested as "not within".)
void validateInterval(double t_lo, double t_hi) {
  const bool within = std::abs(t_lo) <= kMaxIntervalMagnitude &&
                      std::abs(t_hi) <= kMaxIntervalMagnitude;
  if (!within || t_lo > t_hi) rejectInterval(t_lo, t_hi);
}

bool isZero(const PolynomialCoefficients& c) {
  return std::all_of(c.begin(), c.end(), [](double x) { return x == 0; });
}

// p divided by a power of two so that its largest coefficient lies in [0.5, 1): exact (no rounding,
// so no root moves), except that a coefficient over 2^1074 times smaller than the largest
// underflows. Huge and tiny coefficients then neither overflow nor lose precision in the search.
Polynomial normalizedPolynomial(const PolynomialCoefficients& c) {
  // The exponents straight from the bits (frexp and ldexp are library calls, and this runs for
  // every prediction); the results are the same.
  auto exponentOf = [](double x) {  // |x| in [2^(e-1), 2^e), as frexp gives it
    std::uint64_t bits;
    std::memcpy(&bits, &x, sizeof bits);
    const int biased = static_cast<int>((bits >> 52) & 0x7ff);
    if (biased != 0) return biased - 1022;
    int exponent;  // subnormal
    std::frexp(x, &exponent);
    return exponent;
  };
  // The largest exponent is the largest magnitude's: one exponent to take instead of five.
  double largest = 0;
  for (double x : c) largest = std::max(largest, std::abs(x));
  const int largest_exponent = largest != 0 ? exponentOf(largest) : INT_MIN;
  std::array<double, 5> scaled{};
  const int scale_biased = 1023 - largest_exponent;  // the bits of 2^-largest_exponent
  if (scale_biased >= 1 && scale_biased <= 2046) {
    const std::uint64_t bits = static_cast<std::uint64_t>(scale_biased) << 52;
    double scale;
    std::memcpy(&scale, &bits, sizeof scale);
    for (int i = 0; i < 5; ++i) scaled[i] = c[i] * scale;  // exact, as ldexp (or rounded alike)
  } else {
    for (int i = 0; i < 5; ++i) {
      if (c[i] != 0) scaled[i] = std::ldexp(c[i], -largest_exponent);
    }
  }
  return makePolynomial(scaled);
}

// An integer K with every root of p (degree >= 0, not zero) inside [-2^K, 2^K], K >= 0: Fujiwara's
// bound 2 max_k |c_(n-k) / c_n|^(1/k), rounded up to a power of two from the coefficients'
// exponents alone, so that it cannot overflow.
int rootMagnitudeExponentBound(const Polynomial& p) {
  int leading_exponent;
  std::frexp(p.c[p.degree], &leading_exponent);  // |c_n| >= 2^(leading_exponent - 1)
  int bound = 0;
  for (int k = 1; k <= p.degree; ++k) {
    const double c = p.c[p.degree - k];
    if (c == 0) continue;
    int exponent;
    std::frexp(c, &exponent);                                    // |c| < 2^exponent
    const int ratio_exponent = exponent - leading_exponent + 1;  // |c / c_n| < 2^ratio_exponent
    // ceil(ratio_exponent / k), then the factor 2.
    const int root_exponent =
        (ratio_exponent >= 0 ? (ratio_exponent + k - 1) / k : -((-ratio_exponent) / k)) + 1;
    bound = std::max(bound, root_exponent);
  }
  return bound;
}

RootSearchResult firstOf(const RootList& roots) {
  if (roots.count == 0) return {};
  return {RootOutcome::Root, roots.values[0]};
}

void rejectZeroPolynomial() {
  throw std::invalid_argument(
      "polynomial with every coefficient 0 is not allowed here: every t is a root of it");
}

}  // namespace

double evaluatePolynomial(const PolynomialCoefficients& coefficients, double t) {
  return evaluate(makePolynomial(coefficients), t).value;
}

PolynomialValue evaluatePolynomialWithErrorBound(const PolynomialCoefficients& coefficients,
                                                 double t) {
  return evaluate(makePolynomial(coefficients), t);
}

RootSearchResult smallestRootInInterval(const PolynomialCoefficients& coefficients, double t_lo,
                                        double t_hi) {
  validateCoefficients(coefficients);
  validateInterval(t_lo, t_hi);
  if (isZero(coefficients)) return {RootOutcome::Root, t_lo};
  return firstOf(collectRoots(normalizedPolynomial(coefficients), t_lo, t_hi, Mode::FirstRoot));
}

RootSearchResult firstClosingRoot(const PolynomialCoefficients& coefficients, double t_lo,
                                  double t_hi) {
  validateCoefficients(coefficients);
  validateInterval(t_lo, t_hi);
  if (isZero(coefficients)) return {RootOutcome::Root, t_lo};  // touching throughout
  return firstOf(
      collectRoots(normalizedPolynomial(coefficients), t_lo, t_hi, Mode::FirstClosingRoot));
}

std::vector<double> rootsInInterval(const PolynomialCoefficients& coefficients, double t_lo,
                                    double t_hi) {
  validateCoefficients(coefficients);
  validateInterval(t_lo, t_hi);
  if (isZero(coefficients)) rejectZeroPolynomial();
  const RootList roots =
      collectRoots(normalizedPolynomial(coefficients), t_lo, t_hi, Mode::AllRoots);
  return {roots.values.begin(), roots.values.begin() + roots.count};
}

std::vector<double> realRoots(const PolynomialCoefficients& coefficients) {
  validateCoefficients(coefficients);
  if (isZero(coefficients)) rejectZeroPolynomial();
  const Polynomial p = normalizedPolynomial(coefficients);
  const int exponent_bound = rootMagnitudeExponentBound(p);
  if (exponent_bound <= kMaxIntervalExponent) {
    // Every root lies in one interval the search can take: one search, nothing split.
    const double bound = std::ldexp(1.0, exponent_bound);
    const RootList roots = collectRoots(p, -bound, bound, Mode::AllRoots);
    return {roots.values.begin(), roots.values.begin() + roots.count};
  }
  // A tiny leading coefficient puts a root beyond 2^128: roots up to 2^128 directly, larger ones as
  // t = 1/s for the roots s of the reversed polynomial s^n p(1/s) with 0 < |s| < 2^-128. A root
  // within rounding of +-2^128 itself may then be reported from both sides.
  const double split = kMaxIntervalMagnitude;
  const RootList inner = collectRoots(p, -split, split, Mode::AllRoots);
  PolynomialCoefficients reversed{};
  for (int i = 0; i <= p.degree; ++i) reversed[i] = p.c[p.degree - i];
  const RootList outer =
      collectRoots(normalizedPolynomial(reversed), -1 / split, 1 / split, Mode::AllRoots);
  std::vector<double> roots(inner.values.begin(), inner.values.begin() + inner.count);
  for (int i = 0; i < outer.count; ++i) {
    const double s = outer.values[i];
    if (s == 0 || std::abs(s) >= 1 / split) continue;
    const double t = 1 / s;
    if (std::isfinite(t)) roots.push_back(t);  // beyond ~1.8e308 a root has no double
  }
  std::sort(roots.begin(), roots.end());
  return roots;
}

}  // namespace baize::physics
