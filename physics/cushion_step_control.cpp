#include "physics/cushion_step_control.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>

namespace baize::physics::cushion_exact {

// A step (in tau) may span at most this many of a slipping slip's turning scales |u| / |du/dtau|
// at its start (turningScaleStep): about the distance to the solution's nearest complex
// singularity, where the slip would vanish, and beyond it the embedded estimate is no guide. A
// nose slip passing 7e-4 m/s from zero (a quarter of s0) on a grippy cloth was crossed in one step
// of 1.2 turning scales, grown threefold after a step whose estimate read near zero; its estimate
// read 900 times below its true error, and the impact ended 1.7e-9 V0 off. With this cap none of
// 72,000 grippy impacts lies above 5e-10 V0 (5 did, the largest 9.7e-10), nor with caps of 0.8 to
// 1.25 any of 18,000 of them; 1.5 left 25 of the 72,000, 3 of them above 1e-9, and 0.5 costs 8 %
// more evaluations on the impacts of play (docs/cushion-solvers.md, "Steps capped at a slip's
// turning scale").
constexpr double kTurningScaleSteps = 1.0;
// Step-size control of the embedded pair: the smallest factor of a step over the last (the safety
// factor and the largest growth are the options', ExactStepControl).
constexpr double kStepMinFactor = 1.0 / 3;
// After a contact changes its law (held, released, stuck, slipping again) the next step covers at
// least this fraction of the first step's impulse: the step before was sized for the law that
// ended, often cut short to land on the change (to 1e-9 of the impulse where an approaching slip
// was landed on), and the controller grew it back threefold per step (the growth limit: 15 steps in
// one stick-slip impact of play). The step's bounds and the error control then apply as to any
// step. 1, 0.1 and 0.01 gave 381.0, 380.2 and 381.0 evaluations per impact of play (384.9
// without), the largest error at most 3.3e-10 V0 at each.
constexpr double kRestartStepFraction = 0.1;
// A held law's step is cut to end where its error is predicted to reach this fraction of the
// limit (inside the looseness either side, so that the end is due at the next step's start), its
// rate of turn probed over this fraction of the impulse scale (far above the 1e-10 rad to which
// phi* is solved, far below the impact).
constexpr double kCreepEndAim = 0.75;
constexpr double kCreepTurnProbe = 1e-3;
// extrapolatedRoot's Newton iterations: the limit, and the convergence test in rounding units of
// the root (a few: the cubic's rounding).
constexpr int kMaxExtrapolationIterations = 20;
constexpr double kExtrapolationConvergenceUlps = 4;

// x^(-1/8) within 0.21 %, for the step controller (which needs no more: its safety factor is
// 10 %). Three square roots and a division took about 60 cycles in the chain of dependent
// operations that runs from a step's error to the next step's first stage, at every step; this
// takes about 25. A double's bits read as an integer are about 2^52 (log2 x + 1023), so those of
// x^(-1/8) are about (1 + 1/8) 1023 2^52 less an eighth of x's (within 3 %), and one Newton step
// on y^-8 = x, y (9 - x y^8) / 8, leaves it within 0.41 % below (centred: 0.21 % either way).
// Integer and IEEE operations only: the same bits on every machine. x is kept within
// [1e-300, 1e300], where y^8 neither overflows nor underflows.
static_assert(dop853::kErrorOrder == 8, "inverseEighthRoot stands for the power -1 / kErrorOrder");
double inverseEighthRoot(double x) {
  x = std::clamp(x, 1e-300, 1e300);
  constexpr std::int64_t kOne = std::int64_t{1023} << 52;  // the bits of 1.0
  constexpr std::int64_t kCentre = std::int64_t{7} << 45;  // balances the first guess's error
  // 1/8 of the Newton step, times 1.00203: the step leaves the root up to 0.406 % low, never high,
  // so this centres the result's error.
  constexpr double kNewtonEighth = 0.125 * 1.00203;
  std::int64_t bits;
  std::memcpy(&bits, &x, sizeof bits);
  const std::int64_t guess_bits = kOne + (kOne >> 3) - (bits >> 3) - kCentre;
  double y;
  std::memcpy(&y, &guess_bits, sizeof y);
  const double y2 = y * y, y4 = y2 * y2;
  return y * (9 - x * (y4 * y4)) * kNewtonEighth;
}

double stepFactor(double error, const ExactStepControl& control) {
  if (error == 0) return control.max_growth;
  if (!(error > 0)) return kStepMinFactor;  // NaN: that step failed; try a shorter one
  // The estimate is 8th order; most steps lie at the floor of the error share, where dividing by
  // the share leaves that order (above the floor it is one lower, which the safety factor covers).
  return std::clamp(control.safety * inverseEighthRoot(error), kStepMinFactor, control.max_growth);
}

// The root in (0, limit] of the cubic through value g0 > 0 and slope d0 < 0 at 0 and value gp and
// slope dp at -H < 0 (an event function extrapolated from the last step across the next): Newton
// from the linear guess, kept where the cubic falls. Returns false when it finds none there.
bool extrapolatedRoot(double gp, double dp, double g0, double d0, double H, double limit,
                      double* root) {
  if (!(g0 > 0) || !(d0 < 0) || !(H > 0) || !(limit > 0)) return false;
  double t = -g0 / d0;
  if (!(t <= 2 * limit)) return false;  // far beyond the step: nothing to aim at yet
  const double b = (d0 + dp + 2 * (gp - g0) / H) / (H * H);
  const double a = ((gp - g0) / H + d0 + b * H * H) / H;
  for (int it = 0; it < kMaxExtrapolationIterations; ++it) {
    const double value = g0 + t * (d0 + t * (a + t * b));
    const double slope = d0 + t * (2 * a + 3 * b * t);
    if (!(slope < 0)) return false;
    const double next = t - value / slope;
    if (!(next > 0)) return false;
    const bool converged = std::abs(next - t) <= kExtrapolationConvergenceUlps * kEpsilon * next;
    t = next;
    if (converged) break;
  }
  if (!(t <= limit)) return false;
  *root = t;
  return true;
}

StepControl::StepControl(const CushionParams& params, const BallVelocity& incoming,
                         const ExactSolverOptions& options)
    : ImpactRates(params, incoming, options), step_control_(options.step_control) {
  // See slipDirectionStep: the cloth's friction at its largest is mu_s (s + c mu_w). (A
  // frictionless contact never slips with friction: its bound is never read.)
  const std::array<double, 2> direction_rate = {
      3.5 * mu_[0] * inverse_mass_, 3.5 * (mu_[1] * (s_ + c_ * mu_[0])) * inverse_mass_};
  const double time_constants = step_control_.slip_direction_time_constants;
  for (int k = 0; k < 2; ++k) {
    // (A rate of a subnormal friction coefficient would overflow the quotient.)
    direction_time_scale_[k] =
        direction_rate[k] > time_constants / std::numeric_limits<double>::max()
            ? time_constants / direction_rate[k]
            : std::numeric_limits<double>::infinity();
  }
}

// The shortest step (tau) after a contact changes its law, at rate k1 (kRestartStepFraction); 0
// where the rate does not advance P.
double StepControl::restartStep(const State& k1) const {
  return k1[kP] > 0 ? kRestartStepFraction * kFirstStepFraction * M_ * vy0_ / k1[kP] : 0.0;
}

// The longest step (tau) that spans kTurningScaleSteps of each slipping contact's turning scale
// |u| / |du/dtau| at rate k1. An approaching slip falls along its line and is landed on instead;
// a receding one grows away from the zero that sets its turning scale, which lies behind the
// step (without that cap for it: 381.4 evaluations per impact of play instead of 384.9, the
// largest error 3.5e-10 V0 instead of 3.3e-10; the spinning and grippy sets the same).
double StepControl::turningScaleStep(const std::array<Eigen::Vector2d, 2>& u,
                                     const State& k1) const {
  const std::array<Eigen::Vector2d, 2> change = slipChanges(k1);
  double step = std::numeric_limits<double>::infinity();
  for (int k = 0; k < 2; ++k) {
    if (!slipping(k) || contacts_[k].approaching || contacts_[k].receding) continue;
    const double speed = change[k].norm();
    if (speed > 0) step = std::min(step, kTurningScaleSteps * u[k].norm() / speed);
  }
  return step;
}

// The longest step (tau) that spans ExactStepControl::slip_direction_time_constants of each
// slipping contact's slip direction's time constant; infinite when no contact slips with friction
// along its slip. Across
// its direction a slip u moves under its own friction at up to 7/2 mu / M per unit P (the largest
// entry of the contacts' inverse effective mass, times M), which turns it at that over |u|;
// dP/dtau = sigma turns the |u| of its own factor into |u| + s0 (a receding slip has none: its
// |u| stays), and the other contact's factor |u'| / (|u'| + s0) in sigma slows it. The cloth's
// friction is mu_s q with q at most s + c mu_w. (One division per contact: the step runs between
// a step's last rate and the next step's first stage, where each division's latency is waited
// for.)
double StepControl::slipDirectionStep(const std::array<Eigen::Vector2d, 2>& u) const {
  double step = std::numeric_limits<double>::infinity();
  for (int k = 0; k < 2; ++k) {
    if (!slipping(k) || contacts_[k].approaching) continue;
    const int other = 1 - k;
    const double own = direction_time_scale_[k] * (u[k].norm() + factorSlip(k));
    if (!regularized(other)) {
      step = std::min(step, own);
      continue;
    }
    const double speed = u[other].norm();  // a zero other slip stops the turning: no bound
    if (speed > 0) step = std::min(step, own * (speed + regularizing_slip_) / speed);
  }
  return step;
}

// The step (in tau) after which held contact k, sliding along phi*, is predicted to have used
// kCreepEndAim of its held law's room, so that its end falls due at the next step's start
// instead of being crossed and located with a trial step. The misalignment grows as |u| times
// phi*'s turn since the slip lay along it: m(t) = m0 + beta t (|u0| + g t / 2), with g the
// slip's growth and beta phi*'s turn per unit tau (from phi* a little further along the path);
// the size term grows as |u0| + g t. Infinite when nothing can be predicted.
double StepControl::heldLawStep(int k, const State& z, const State& k1) const {
  const double none = std::numeric_limits<double>::infinity();
  if (!(k1[kP] > 0)) return none;
  if (lagCorrected(k)) return none;  // its end is located (t^3, in locate)
  const std::array<Eigen::Vector2d, 2> u = slips(z);
  const Laws here = lawsAt(u, nullptr);
  if (here.stick[k]) return none;
  const double nudge = kCreepTurnProbe * impulse_scale_ / k1[kP];  // tau
  const Laws there = lawsAt(slips(z + nudge * k1), nullptr);
  if (there.stick[k]) return none;
  const double beta = std::abs(std::atan2(cross(here.direction[k], there.direction[k]),
                                          here.direction[k].dot(there.direction[k]))) /
                      nudge;
  const double growth = slipRate(k, frictionFor(here)).norm() * k1[kP];  // m/s per unit tau
  if (!(growth > 0)) return none;
  const double size = u[k].norm(), misalignment = std::abs(cross(u[k], here.direction[k]));
  const double aim = kCreepEndAim * creep_error_limit_;
  const double by_size = (aim / creep_error_limit_ * regularizing_slip_ - size) / growth;
  double by_turn = none;
  if (beta > 0) {  // root of (g beta / 2) t^2 + (|u0| beta) t + (m0 - aim) = 0
    const double a = 0.5 * growth * beta, b = size * beta, c = misalignment - aim;
    by_turn = c < 0 ? (-b + std::sqrt(b * b - 4 * a * c)) / (2 * a) : 0;
  }
  const double t = std::min(by_size, by_turn);
  return t > 0 ? t : none;
}

// The step (tau) that takes approaching contact k's slip to where its zero is located, at the
// rate dz/dtau = k1: its slip falls linearly in P, so the step lands there (to rounding and the
// slow change of the other contact) and the event is due at the next step's start instead of
// being crossed, past which the slip's friction reverses. Infinite if it does not fall.
double StepControl::approachStep(int k, const State& z, const State& k1) const {
  const Eigen::Vector2d& line = contacts_[k].approach_direction;
  const double fall = -line.dot(slipChanges(k1)[k]);
  const double left = line.dot(slip(k, z)) - kApproachLanding * vanished_slip_;
  if (!(fall > 0) || !(left > 0)) return std::numeric_limits<double>::infinity();
  return left / fall;
}

double StepControl::cappedStep(const std::array<Eigen::Vector2d, 2>& u, const State& k1, double h) {
  if (std::isfinite(release_step_cap_)) {  // in tau, at the pace the rate sets here
    h = std::min(h, release_step_cap_ / k1[kP]);
    release_step_cap_ = std::numeric_limits<double>::infinity();
  }
  h = std::min(h, slipDirectionStep(u));
  return std::min(h, turningScaleStep(u, k1));
}

// Predictive control (Gustafsson): where the accepted steps' errors follow a trend (a slip
// shrinking toward zero makes the right step shrink by a steady ratio) the next step follows it
// too, instead of overshooting into a rejection every other step. The step after one accepted
// after a rejection does not grow (Hairer's rule): the stretch that was rejected lies just ahead,
// and the retry's small error only says that the shortened step stopped short of it. (Only the
// main loop's rejections count, not event location's trial steps; an event landed on between the
// rejection and the next accepted step does not clear it.) Rate evaluations per impact against
// the exact solver at 1e-14, with and without the rule: at the
// default, 251.8 and 252.5 on the 7,755 impacts of the benches' first 3000 random single shots,
// 428.2 and 430.5 on the 2,209 of them the default path's table leaves; at the default path's
// fallback, 223.4 and 226.8 on those 2,209, the largest errors the same.
double StepControl::acceptedStepFactor(double h, double error) {
  double factor = stepFactor(error);
  if (previous_error_ > 0 && error > 0) {
    // (Two estimated roots: within 0.41 %, far inside the safety factors' margins of 10 and 20 %.)
    const double trend =
        (h / previous_step_) / inverseEighthRoot(previous_error_) * inverseEighthRoot(error);
    factor = std::clamp(factor * trend, kStepMinFactor, step_control_.max_growth);
  }
  if (after_rejection_) factor = std::min(factor, 1.0);
  after_rejection_ = false;
  previous_step_ = h;
  previous_error_ = error;
  return factor;
}

double StepControl::rejectedStepFactor(double error) {
  after_rejection_ = true;
  return stepFactor(error);
}

}  // namespace baize::physics::cushion_exact
