#include "physics/dop853.h"

namespace baize::physics::dop853 {

double combinedError(double fifth_squared, double third_squared, int n, double h) {
  double denominator = fifth_squared + kThirdOrderWeight * third_squared;
  if (!(denominator > 0)) return 0;
  return std::abs(h) * fifth_squared / std::sqrt(n * denominator);
}

double stepFactor(double error, double safety, double min_factor, double max_factor) {
  if (error == 0) return max_factor;
  if (!(error > 0)) return min_factor;  // NaN: that step failed; try a shorter one
  return std::clamp(safety * std::pow(error, -1 / kErrorOrder), min_factor, max_factor);
}

// Newton on hermiteRoot's cubic: the convergence test (in the share of the step; far below any
// step's resolution, far above rounding of a cubic on [0, 1]) and a guard on the iterations
// (Newton converges in about five; after 40 bisections the bracket is 1e-12 of the step, and the
// first guess it gives is refined by the trial steps anyway).
constexpr double kHermiteRootTolerance = 1e-14;
constexpr int kMaxHermiteIterations = 40;

double hermiteRoot(double g0, double d0, double g1, double d1) {
  auto value = [&](double t) {
    const double h00 = (1 + 2 * t) * (1 - t) * (1 - t), h10 = t * (1 - t) * (1 - t);
    const double h01 = t * t * (3 - 2 * t), h11 = t * t * (t - 1);
    return h00 * g0 + h10 * d0 + h01 * g1 + h11 * d1;
  };
  auto slope = [&](double t) {
    const double s00 = 6 * t * (t - 1), s10 = (1 - t) * (1 - 3 * t);
    const double s01 = 6 * t * (1 - t), s11 = t * (3 * t - 2);
    return s00 * g0 + s10 * d0 + s01 * g1 + s11 * d1;
  };
  double lo = 0, hi = 1, t = g0 / (g0 - g1);
  for (int it = 0; it < kMaxHermiteIterations; ++it) {
    const double v = value(t);
    if (v == 0) return t;
    (v > 0 ? lo : hi) = t;
    const double d = slope(t);
    double next = d != 0 ? t - v / d : 0.5 * (lo + hi);
    // Converged: the step is within rounding of the root. (Tested before the bracket, which the
    // iterate itself has just become one end of: a step that rounds back onto it is no reason to
    // bisect away from it.)
    if (std::abs(next - t) < kHermiteRootTolerance) return t;
    if (!(next > lo && next < hi)) next = 0.5 * (lo + hi);
    if (hi - lo < kHermiteRootTolerance) return next;
    t = next;
  }
  return t;
}

}  // namespace baize::physics::dop853
