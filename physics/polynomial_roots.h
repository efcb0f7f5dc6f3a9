// Real roots of real polynomials of degree at most 4, for event times: when two sliding balls touch
// (a quartic in t), when a ball reaches a straight cushion line (a quadratic), a circular jaw or a
// pocket's capture circle (a quartic).
//
// The finders are total: every call returns an outcome (or a list), never a number that might be
// garbage, and they never miss a root that exists. A point where the computed value of p lies
// within the rounding error bound of zero (see kPolynomialErrorUnitRoundoffs) counts as a root.
// That is how tangent contacts (double roots, where p touches zero without changing sign) and
// nearly double roots are caught: "touching" is an event, never a miss.
//
// Method. Roots are isolated by recursion on the derivative: the roots of p' (one degree lower,
// found the same way) cut the interval into pieces on which p is monotone. A piece whose ends have
// values of opposite sign holds exactly one root, refined by a safeguarded Newton iteration with
// bisection until the step is down to ulps or p lies within its rounding band (no later step could
// be trusted). A piece end whose value lies within the error bound is itself a root (at a critical
// point: a double root); if its computed value has the other sign, p crosses into the band earlier
// and that crossing is the root. The coefficients are first divided by a power of two
// (exact) so that the largest is below 1: huge and tiny coefficients neither overflow nor change
// the answer.
//
// Units: t is whatever the caller's time is (the engine uses s); the coefficients carry the
// matching units. Everything is deterministic: the same input gives the same output bit for bit.
#pragma once

#include <array>
#include <limits>
#include <vector>

namespace baize::physics {

// p(t) = c[0] + c[1] t + c[2] t^2 + c[3] t^3 + c[4] t^4, lowest power first. A polynomial of lower
// degree leaves its top coefficients 0; a vanishing leading coefficient simply lowers the degree.
using PolynomialCoefficients = std::array<double, 5>;

// The rounding error bound used to decide whether a computed value of p is zero, in units of
// u * sum_i |c_i| |t|^i (u = 2^-53, the unit roundoff). Horner's rule for degree <= 4 makes at most
// 4 multiplications and 4 additions, each of relative error <= u on the running magnitude: 8. One
// more for the coefficients themselves having been rounded once when the caller formed them, and
// one for the rounding in computing the bound: 10.
inline constexpr double kPolynomialErrorUnitRoundoffs = 10.0;

// A value of p and the bound on its rounding error: |value - exact p(t)| <= error_bound.
struct PolynomialValue {
  double value = 0;
  double error_bound =
      0;  // kPolynomialErrorUnitRoundoffs * u * sum_i |c_i| |t|^i (+ underflow floor)
};

// p(t) by Horner's rule.
double evaluatePolynomial(const PolynomialCoefficients& coefficients, double t);

// p(t) by Horner's rule with its rounding error bound (see kPolynomialErrorUnitRoundoffs).
PolynomialValue evaluatePolynomialWithErrorBound(const PolynomialCoefficients& coefficients,
                                                 double t);

// Interval ends must lie in [-2^128, 2^128] (about 3.4e38), far beyond any time the engine uses:
// with the coefficients normalized below 1, every term |c_i| |t|^i then stays below 2^512 and
// nothing overflows. (realRoots has no such limit: it finds roots beyond 2^128 through the reversed
// polynomial.)
inline constexpr double kMaxIntervalMagnitude = 0x1p128;

enum class RootOutcome { Root, NoRoot };

// The result of a root search. `time` is the root when outcome == Root and +infinity otherwise, so
// that a result used without checking its outcome can never produce an early event.
struct RootSearchResult {
  RootOutcome outcome = RootOutcome::NoRoot;
  double time = std::numeric_limits<double>::infinity();
};

// The smallest root of p in the closed interval [t_lo, t_hi] (t_lo == t_hi allowed), or NoRoot.
// A root at (or within rounding of) either end counts. A double root counts. The zero polynomial
// has every t as a root: the answer is t_lo. The root is as accurate as the rounding of p allows:
// within (error bound / |p'|) of the exact root of the given coefficients, a few ulps where p is
// well conditioned (measured: at most 4.3 u sum |c_i| |r|^i / |p'(r)| over 100000 random quartics).
// Near a double root the answer lies where |p| is within its rounding bound.
// Throws std::invalid_argument if a coefficient or an end is not finite, an end lies beyond
// kMaxIntervalMagnitude, or t_lo > t_hi.
RootSearchResult smallestRootInInterval(const PolynomialCoefficients& coefficients, double t_lo,
                                        double t_hi);

// For a gap function p (positive while two things are apart: a squared distance minus the squared
// contact distance, a signed distance to a line): the first time in [t_lo, t_hi] at which the gap
// closes. That is the smallest root at which p is not rising: p falls through zero, p touches zero
// (a double root, grazing contact), or p starts at or below zero (within rounding) and does not
// rise from there (touching or overlapping and approaching: an event now), or p starts below zero,
// rises without reaching it and turns back (a contact that never separated starts closing again:
// an event where it turns). Roots where p rises through zero (separation), and a start at zero
// followed by a rise (touching and separating) are skipped, so an engine that resolved a contact at
// t_lo does not find it again. Same input rules as above.
RootSearchResult firstClosingRoot(const PolynomialCoefficients& coefficients, double t_lo,
                                  double t_hi);

// Every root of p in [t_lo, t_hi], increasing, each reported once (a double root once; two roots
// closer than the rounding of p can separate may be reported once). Throws std::invalid_argument
// for the zero polynomial (every t is a root) and for the inputs rejected above.
std::vector<double> rootsInInterval(const PolynomialCoefficients& coefficients, double t_lo,
                                    double t_hi);

// Every real root of p (linear to quartic), increasing, each reported once, as above. Roots too
// large to represent as a double (beyond about 1.8e308, possible only with a tiny leading
// coefficient) are left out. Throws std::invalid_argument for a coefficient that is not finite and
// for the zero polynomial.
std::vector<double> realRoots(const PolynomialCoefficients& coefficients);

}  // namespace baize::physics
