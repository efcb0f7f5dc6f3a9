#include "physics/cushion_event_location.h"

#include <algorithm>
#include <cmath>

namespace baize::physics::cushion_exact {

// An event is located when its function is this small against its scale times the tolerance...
constexpr double kEventResidualFraction = 1e-4;
// ...or when the bracket on the step length is this many rounding units wide. A phase end missed
// by a correction shorter than this fraction of the trial step is reached by a second-order step
// from the trial's end, if that step's error estimate (Euler's, which bounds Heun's) stays below
// this fraction of the tolerance.
constexpr double kPolishStepFraction = 1e-3;
constexpr double kPolishErrorFraction = 1e-3;
constexpr double kEventBracketUlps = 8;
// A phase end predicted within the next step (extrapolated from the last accepted step) is
// aimed at: the step is cut to end there, and from where it ends, short or past by about 1e-4 of
// it, third-order steps land on it (Newton's method on their length). They may reach at most this
// fraction of the step away (beyond, the step counts as an ordinary one, or the event is located
// with trial steps), their embedded error must stay below the second fraction of the tolerance
// (so that they add nothing measurable to the step's error), and a few of them must land.
constexpr double kLandingShiftFraction = 1e-2;
constexpr double kLandingErrorFraction = 1e-2;
constexpr int kMaxLandingSteps = 3;
// The phase-end functions are sums of terms of their scale (v_y0, the compression work), so their
// rounding is a few units of that: at tolerances below about 3.6e-11 (the default among them)
// kEventResidualFraction asks for less than this many units, within which a landing counts as
// reached.
constexpr double kEventRoundingUlps = 16;
// Logic guards, far above what the bounded equations need (an impact takes tens of steps and a few
// contact changes).
constexpr int kMaxEventIterations = 60;
// A cone event's slope along the state's interpolant across the step that crossed it, by a
// central difference over this share of the step either side: its truncation error is of the
// order of the share squared, its rounding about 1e-10 of the slope.
constexpr double kInterpolantSlopeShare = 1e-6;

// A cone event's trials (see locate): the first where its margin crosses zero along the cubic
// Hermite interpolant of the state over the step that crossed it (regula falsi on the
// interpolant, margin evaluations only), the second Newton's with the interpolant's slope there,
// the next the secant through the last two accurate trials. A trial outside the bracket is
// replaced by the bracket's own (in locate).
class ConeTrials {
 public:
  template <typename Margin>
  double first(const State& z, const State& k1, const Step& full, double h, double g_start,
               double g_end, const Margin& margin) {
    const dop853::DenseOutput<State> dense{z, k1, full.z, full.rate_at_end, h};
    // (To the bracket's width: the trials that follow polish it.)
    const double share = dop853::denseRoot(dense, g_start, g_end, margin, 0.0, kMaxEventIterations);
    const double ahead = margin(dense.at(share + kInterpolantSlopeShare));
    const double behind = margin(dense.at(share - kInterpolantSlopeShare));
    interpolant_slope_ = (ahead - behind) / (2 * kInterpolantSlopeShare * h);
    return share * h;
  }
  // The trial after an accurate one of this length, where the margin is g (-1: none).
  double next(double tried, double g) {
    double trial = -1;
    if (last_ >= 0 && g != last_g_)
      trial = tried - g * (tried - last_) / (g - last_g_);
    else if (interpolant_slope_ < 0)
      trial = tried - g / interpolant_slope_;
    last_ = tried;
    last_g_ = g;
    return trial;
  }

 private:
  double interpolant_slope_ = 0;   // per unit tau; 0: none
  double last_ = -1, last_g_ = 0;  // the last accurate trial's length and margin (-1: none)
};

double EventLocation::eventValue(const Event& event, const State& z) const {
  if (event.phase_end) return compressing_ ? normalVelocity(z) : z[kWork] - work_target_;
  if (event.creep_end) return creepRoom(event.contact, z);
  if (event.approach_end) {
    return contacts_[event.contact].approach_direction.dot(slip(event.contact, z)) -
           kApproachLanding * vanished_slip_;
  }
  if (event.approach_off) {
    return creep_error_limit_ -
           std::abs(cross(contacts_[event.contact].approach_direction, slip(event.contact, z)));
  }
  return event.sign * neededMargin(event.contact, z);
}

double EventLocation::eventSlope(const Event& event, const State& r) const {
  if (!event.phase_end) return 0;
  return compressing_ ? -(c_ * r[kP] - s_ * r[kAy] + r[kBy]) * inverse_mass_ : r[kWork];
}

double EventLocation::eventTolerance(const Event& event) const {
  // The held law may end anywhere its error is of the order of its limit: located loosely.
  if (event.creep_end) return kCreepEndLooseness * creep_error_limit_;
  if (event.approach_end) return kApproachLooseness * vanished_slip_;
  if (event.approach_off) return kCreepEndLooseness * creep_error_limit_;
  if (!event.phase_end) return kEventResidualFraction * tolerance_;
  return kEventResidualFraction * tolerance_ * phaseEndScale();
}

// Finds the step length in [0, h] that lands on an event the full step crossed: Newton on the
// length where the event has a slope (each trial a full Runge-Kutta step, whose end rate gives
// the next slope), ConeTrials for a cone event, Illinois regula falsi otherwise. Returns false,
// with *length set to a shorter step to take instead, when a trial breaks the error tolerance.
bool EventLocation::locate(const Event& event, const State& z, const State& k1, double h,
                           const Step& full, double* length, Step* landed) {
  const double tolerance_g = eventTolerance(event);
  double lo = 0, g_lo = eventValue(event, z);
  double hi = h, g_hi = eventValue(event, full.z);
  *length = h;
  *landed = full;
  if (g_lo <= tolerance_g) {  // due where the step starts
    *length = 0;
    landed->z = z;
    landed->rate_at_end = k1;
    return true;
  }
  // Due where the step ends (a step cut to land on it, as an approaching slip's is): no trials.
  if (g_hi >= -tolerance_g && full.error <= 1) return true;
  auto newton = [](double from, double g, double slope) {
    return slope < 0 ? from - g / slope : -1.0;  // -1: outside any bracket, so not taken
  };
  // First guess: the root of the cubic through g and its slope at both ends of the full step (for
  // events with a slope), else Newton from the start.
  double trial = newton(0, g_lo, eventSlope(event, k1));
  const double slope_lo = eventSlope(event, k1), slope_hi = eventSlope(event, full.rate_at_end);
  if (event.phase_end && g_hi < 0)
    trial = h * dop853::hermiteRoot(g_lo, slope_lo * h, g_hi, slope_hi * h);
  // A cone event's margin has no slope from the rates and is far from linear in the step (regula
  // falsi from the step's ends took seven trials on the 9-ball break's stick): ConeTrials.
  ConeTrials cone_trials;
  if (event.cone() && g_hi < 0) {
    trial = cone_trials.first(z, k1, full, h, g_lo, g_hi,
                              [&](const State& y) { return eventValue(event, y); });
  }
  int side = 0;
  for (int it = 0; it < kMaxEventIterations; ++it) {
    // A held law's error grows as the square of the impulse from where the slip was zero (the
    // lag of a direction that turns at a steady rate): the root of g = A - B t^2 through the
    // bracket's ends, which regula falsi would approach only slowly from the far end.
    if (event.creep_end && g_lo > g_hi) {
      if (lagCorrected(event.contact)) {  // corrected for the lag: about t^3
        const double lo3 = lo * lo * lo, hi3 = hi * hi * hi;
        trial = std::cbrt(lo3 + g_lo * (hi3 - lo3) / (g_lo - g_hi));
      } else {
        trial = std::sqrt(lo * lo + g_lo * (hi * hi - lo * lo) / (g_lo - g_hi));
      }
    }
    if (!(trial > lo && trial < hi) && g_lo > g_hi) trial = lo + (hi - lo) * (g_lo / (g_lo - g_hi));
    if (!(trial > lo && trial < hi)) trial = 0.5 * (lo + hi);
    const Step attempt = rungeKuttaStep(z, k1, trial);
    const double g = eventValue(event, attempt.z);
    // A trial that ends past the event may break the tolerance only because of what lies past
    // it (a held contact's law changes there, which the step does not resolve): it still bounds
    // the event from above, though it cannot be a landing. One that ends before it was too long.
    const bool accurate = attempt.error <= 1;
    if (!accurate && !(g <= tolerance_g && trial > lo)) {
      *length = trial * stepFactor(attempt.error);
      return false;
    }
    Step polished;
    double shift = 0;
    if (accurate && polishOnto(event, attempt, trial, &shift, &polished)) {
      *length = trial + shift;
      *landed = polished;
      return true;
    }
    if (g <= tolerance_g) {  // at or past the event
      hi = trial;
      g_hi = g;
      if (accurate) {  // a candidate landing
        *length = trial;
        *landed = attempt;
        if (g >= -tolerance_g) return true;
      }
      if (side == -1) g_lo *= 0.5;  // Illinois: keep one end from sticking
      side = -1;
    } else {
      lo = trial;
      g_lo = g;
      if (side == +1) g_hi *= 0.5;
      side = +1;
    }
    if (hi - lo <= kEventBracketUlps * kEpsilon * h) break;
    // (After an inaccurate trial its slope is no guide: the trial, now the bracket's end, makes
    // the next one regula falsi.)
    if (accurate) {
      trial = event.cone() ? cone_trials.next(trial, g)
                           : newton(trial, g, eventSlope(event, attempt.rate_at_end));
    }
  }
  // (A landing beyond the bracket is none: a trial that broke the tolerance past the event
  // moved the bracket's end below it.)
  if (landed->error <= 1 && *length <= hi) return true;
  // Only the full step, which broke the tolerance, saw the event: it may lie beyond. Take the
  // longest accurate stretch before it and look again from there.
  *length = lo > 0 ? lo : h * stepFactor(full.error);
  return false;
}

// A phase end missed by a little: the Newton correction of the step length is then so short
// that a second-order step (Heun, one evaluation) from the trial's end covers it to the
// tolerance, instead of another whole step from the start. Returns false (nothing spent but
// that evaluation) when the correction is not that short or does not land on the event.
bool EventLocation::polishOnto(const Event& event, const Step& from, double trial, double* shift,
                               Step* polished) {
  if (!event.phase_end) return false;
  const double g = eventValue(event, from.z), tolerance_g = eventTolerance(event);
  const double slope = eventSlope(event, from.rate_at_end);
  if (std::abs(g) <= tolerance_g || !(slope < 0)) return false;
  *shift = -g / slope;
  if (!(std::abs(*shift) <= kPolishStepFraction * trial)) return false;
  const State& start_rate = from.rate_at_end;
  const State end_rate = rate(from.z + *shift * start_rate);
  // Half the change of rate over the shift bounds Euler's error, and Heun's is far below it.
  const State change = (0.5 * *shift) * (end_rate - start_rate);
  if (!(change.cwiseQuotient(error_scale_).cwiseAbs().maxCoeff() <= kPolishErrorFraction))
    return false;
  polished->z = from.z + (0.5 * *shift) * (start_rate + end_rate);
  polished->rate_at_end = end_rate;  // for trace sampling only: the caller recomputes the rate
  polished->error = from.error;
  return std::abs(eventValue(event, polished->z)) <= tolerance_g;
}

// From the end of a step aimed at the phase end (past it or short of it by a little): third-order
// steps (Bogacki-Shampine 3(2), the rate at the step's end reused as their first stage), each as
// long as Newton's correction says, until the phase-end function is within its tolerance or its
// rounding (kEventRoundingUlps). Returns false (with up to kMaxLandingSteps x 3 evaluations
// spent) when they would reach more than kLandingShiftFraction of the step away, or their error
// estimate exceeds kLandingErrorFraction of the tolerance: the step is then taken as it is.
bool EventLocation::landOnPhaseEnd(const Step& aimed, double h, double* shift, Step* landed) {
  const Event phase;
  const double reachable =
      std::max(eventTolerance(phase), kEventRoundingUlps * kEpsilon * phaseEndScale());
  State y = aimed.z, k = aimed.rate_at_end;
  double moved = 0;
  for (int it = 0;; ++it) {
    const double g = eventValue(phase, y);
    if (std::abs(g) <= reachable) break;
    const double slope = eventSlope(phase, k);
    if (it == kMaxLandingSteps || !(slope < 0)) return false;
    const double s = -g / slope;
    if (!(std::abs(moved + s) <= kLandingShiftFraction * h)) return false;
    const State k2 = rate(y + (0.5 * s) * k);
    const State k3 = rate(y + (0.75 * s) * k2);
    const State next = y + s * ((2.0 / 9) * k + (1.0 / 3) * k2 + (4.0 / 9) * k3);
    const State k4 = rate(next);
    const State error = s * ((2.0 / 9 - 7.0 / 24) * k + (1.0 / 3 - 0.25) * k2 +
                             (4.0 / 9 - 1.0 / 3) * k3 - 0.125 * k4);
    if (!(error.cwiseQuotient(error_scale_).cwiseAbs().maxCoeff() <= kLandingErrorFraction))
      return false;
    y = next;
    k = k4;
    moved += s;
  }
  *shift = moved;
  landed->z = y;
  landed->rate_at_end = k;
  landed->error = aimed.error;
  return true;
}

}  // namespace baize::physics::cushion_exact
