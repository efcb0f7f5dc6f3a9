#include "physics/ball_ball_impact.h"

#include <Eigen/Geometry>
#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

#include "physics/dop853.h"
#include "physics/value_text.h"

// Derivations (both models).
//
// Local frame: n (line of centres, 1 -> 2), t = z x n, z; (n, t, z) is right-handed. Ball 1 touches
// ball 2 at r1 = R n from its centre, ball 2 at r2 = -R n. Slip of ball 1's surface relative to
// ball 2's at the contact: g = (v1 + w1 x r1) - (v2 + w2 x r2) = (v1 - v2) + R (w1 + w2) x n, with
// (w x n) = (0, w_z, -w_t) in (n, t, z), so
//   g_n = v1n - v2n (the approach speed), g_t = v1t - v2t + R (w1z + w2z), g_z = -R (w1t + w2t).
//
// Impulse-to-velocity map. An impulse J on ball 1 at r1 (and -J on ball 2 at r2) changes
//   v1 by J/m1, w1 by R n x J / I1,   v2 by -J/m2, w2 by (-R n) x (-J) / I2 = R n x J / I2,
// and the slip by dg = J (1/m1 + 1/m2) + R^2 (1/I1 + 1/I2) ((n x J) x n). (n x J) x n is the
// tangential part of J and R^2 / I = 5 / (2 m), so with mu* = m1 m2 / (m1 + m2):
//   dg_n = J_n / mu*,   dg_tangential = (7/2) J_tangential / mu*   (free balls).
// The normal impulse does not change the tangential slip, and friction does not change g_n.
//
// FrictionalInelastic. Newton's law g_n' = -e g_n gives the normal impulse P = mu* (1 + e) g_n.
// The friction impulse opposes the slip g_s = (g_t, g_z): J_s = -lambda g_s / |g_s| with
// lambda = min(mu P, (2/7) mu* |g_s|); the cap is the impulse that brings the free-body slip to
// zero. Kinetic energy changes by J . (g_before + g_after) / 2 summed over the contact, which is
// -(1 - e^2) mu* g_n^2 / 2 - lambda (|g_s| + |g_s'|) / 2 <= 0, and removing v_z afterwards can only
// lower it further. The balls are treated as free during the impulse (as in Alciatore's analysis);
// afterwards the vertical part of the friction impulse has changed w_t of both balls and its
// vertical velocity is removed, so the vertical slip left equals the removed v_z difference, O(mu)
// small.
//
// Mathavan2014. P is the normal impulse at the ball-ball contact; it only grows. Per unit dP:
//   on ball 1: -n (normal) + f (friction, f = -mu_b (0, g_t, g_z) / |g_s| while slipping),
//   on ball 2: +n - f, plus at each ball's cloth contact C = -R z a normal N_i z and a friction
//   T_i.
// Vertical momentum. Weight gives no impulse in the instantaneous limit and the ball-ball normal is
// horizontal, so the only vertical impulse the impact makes is the friction's f_z: down on ball 1
// when f_z < 0, down on ball 2 when f_z > 0. The table can only push, so it answers with
// N1 = max(0, -f_z), N2 = max(0, f_z); the other ball is pushed up by |f_z| and, in this model that
// keeps both balls on the table, its vertical velocity is dropped (reported, not applied). Without
// spin about t (g_z = 0) the table takes no impulse at all and the cloth plays no part. Cloth slip
// of ball i: s_i = v_i + w_i x (-R z) = (v_n - R w_t, v_t + R w_n); T_i = -mu_s N_i s_i / |s_i|.
// Rates (m dv/dP in (n, t); I dw/dP in (n, t, z)); z x T = (-T_t, T_n, 0), n x f = (0, -f_z, f_t):
//   m1 dv1/dP = (-1 + T1n, f_t + T1t),   I1 dw1/dP = R (T1t, -f_z - T1n, f_t),
//   m2 dv2/dP = (+1 + T2n, -f_t + T2t),  I2 dw2/dP = R (T2t, -f_z - T2n, f_t).
// Ball-ball slip rate: dg_t/dP = (7/2) f_t / mu* + T1t/m1 - T2t/m2,
//                      dg_z/dP = (5/2) f_z / mu* + (5/2) (T1n/m1 + T2n/m2)
// (v_z is held, so f_z acts through the spins only: 5/2, not 7/2).
// Stick at the ball-ball contact: with g_s = 0 and friction f, N and T are linear in |f_z| and the
// stick condition dg_s/dP = 0 reads (7/2) f_t / mu* = -(T terms), (5/2 / mu* - O(mu_s)) f_z = 0, so
// f_z = 0, hence N = T = 0, hence f_t = 0: once the slip vanishes the contact rolls with no
// friction for the rest of the impact, and no slipping solution can leave g_s = 0 (friction
// opposing a new slip direction d gives dg_s/dP . d < 0). The integrator therefore switches
// friction off for good when |g_s| falls below a floor far under the integration error. The cloth
// contact cannot stick during the impact: with f = 0 the driving rate of s_i has a normal part
// |(+-1 + (5/2) f_z)| / m_i >= (1 - 5/2 mu_b) / m_i, while cloth friction changes s_i at most by
// (7/2) mu_s mu_b / m_i; validation requires mu_b (5/2 + 7/2 mu_s) < 1. A loaded cloth slip can
// pass through zero; at zero the friction points against the driving rate, the way the slip is
// about to go. Normal approach: dg_n/dP = -1/mu* + T1n/m1 - T2n/m2 <= -(1 - mu_s mu_b) / mu* < 0,
// so compression ends (g_n = 0) at a finite P. Energetic restitution: W(P) = integral g_n dP grows
// to W_c during compression and the impact ends when W = (1 - e^2) W_c. Frictionless it gives g_n'
// = -e g_n exactly. Kinetic energy: friction dissipates (f . g_s <= 0, T_i . s_i <= 0), the held
// vertical velocity does no work, and the normal force returns e^2 of what it absorbed, so energy
// never grows.
//
// Integration. Adaptive Dormand-Prince 8(5,3) in P (the generic pair of dop853.h) with error
// control relative to the speed scale,
// except for g_n and W, whose errors are measured against the approach g_n(0) and mu* g_n(0)^2:
// g_n is integrated on its own, not taken as v1n - v2n, which on a grazing contact at ball speeds
// is round-off (the approach may be 1e-100 m/s, kMinApproachSpeed_mps, beside m/s speeds); the
// impact then takes as few steps as a head-on one, its rates barely changing over its small
// impulse. The end of compression and of restitution are located to 1e-12 of their scales by the
// pair's event location (dop853::locateEvent: a guess from the step's dense output, then the
// Illinois method on the length of the last step, each trial one full step from the step's
// start). The steps are also shortened so that a decreasing slip (ball-ball, or a loaded cloth
// contact) is approached by at most 90 % of its predicted distance per step, so the non-smooth
// points are reached, not jumped over. The RHS is smooth between those points, so the result
// converges at the tolerance.

namespace baize::physics {
namespace {

// Dimensionless tolerances of the Mathavan integrator, all relative to the problem's scales.
// Event residuals, relative to the approach speed and to the compression work: far above
// round-off (~1e-16) yet far below the step error allowed.
constexpr double kEventTolerance = 1e-12;
// A slip below this fraction of the speed scale counts as zero (stick / direction from the rates).
constexpr double kSlipFloor = 1e-11;
// Fraction of the predicted distance to a slip zero that one step may cover.
constexpr double kApproachFraction = 0.9;
// Guards against a logic error; a typical impact takes a few dozen steps.
constexpr long kMaxSteps = 200000;
constexpr int kMaxEventIterations = 100;
// First step, as a fraction of mu* g_n(0) (the compression's impulse), which the controller then
// adapts: over 4000 random impacts 0.05, 0.2, 0.5 and 1 took 152, 137, 143 and 127 evaluations, the
// largest error 4.9e-11, 3.4e-11, 4.7e-11 and 7.1e-11 of the approach speed.
constexpr double kFirstStepFraction = 0.2;
// Step-size control of the Dormand-Prince 8(5,3) pair: safety factor and bounds on the change per
// step.
constexpr double kStepSafety = 0.9;
constexpr double kStepMinFactor = 0.1;
constexpr double kStepMaxFactor = 5;

struct Frame {
  Eigen::Vector3d n, t, z;
};

Frame frameOf(const Eigen::Vector3d& line_of_centres) {
  Eigen::Vector3d n(line_of_centres.x(), line_of_centres.y(), 0.0);
  n /= n.norm();
  return {n, Eigen::Vector3d(-n.y(), n.x(), 0.0), Eigen::Vector3d::UnitZ()};
}

// State of the Mathavan integration in the local frame (n, t, z), plus accumulated impulses.
enum Index : int {
  kV1n,
  kV1t,
  kW1n,
  kW1t,
  kW1z,
  kV2n,
  kV2t,
  kW2n,
  kW2t,
  kW2z,
  // g_n = (v1 - v2) . n, m/s, integrated as a state of its own: on a grazing contact the approach
  // (down to kMinApproachSpeed_mps) is far below the round-off of v1n - v2n at m/s ball speeds.
  kApproach,
  kWork,  // W, J: work of the normal force at the ball-ball contact
  kTable1,
  kTable2,  // table normal impulses, N s
  kLift1,
  kLift2,  // upward friction impulses not answered by the table (dropped), N s
  kFrictionT,
  kFrictionZ,  // friction impulse on ball 1 at the ball-ball contact, N s
  kStateSize
};
using State = Eigen::Matrix<double, kStateSize, 1>;

struct Model {
  double R, m1, m2, I1, I2, mu_b, mu_s;
  double slip_floor_mps;
};

double slipT(const Model& m, const State& y) {
  return y[kV1t] - y[kV2t] + m.R * (y[kW1z] + y[kW2z]);
}
double slipZ(const Model& m, const State& y) { return -m.R * (y[kW1t] + y[kW2t]); }

// Direction of the cloth friction's opposite: the slip's, or at zero slip the way it is driven.
Eigen::Vector2d clothSlipDirection(const Eigen::Vector2d& slip, const Eigen::Vector2d& driving,
                                   double floor) {
  const double s = slip.norm();
  if (s > floor) return slip / s;
  const double d = driving.norm();
  return d > 0 ? Eigen::Vector2d(driving / d) : Eigen::Vector2d::Zero();
}

void rates(const Model& m, const State& y, bool rolling, State& dy) {
  const double R = m.R;
  const double g_t = slipT(m, y), g_z = slipZ(m, y);
  const double g = std::hypot(g_t, g_z);
  double f_t = 0, f_z = 0;
  if (!rolling && g > 0) {
    f_t = -m.mu_b * g_t / g;
    f_z = -m.mu_b * g_z / g;
  }
  const double N1 = std::max(0.0, -f_z), N2 = std::max(0.0, f_z);
  const Eigen::Vector2d s1(y[kV1n] - R * y[kW1t], y[kV1t] + R * y[kW1n]);
  const Eigen::Vector2d s2(y[kV2n] - R * y[kW2t], y[kV2t] + R * y[kW2n]);
  // Rates of s_i without the cloth friction (see the derivation at the top).
  const Eigen::Vector2d a1((-1 + 2.5 * f_z) / m.m1, f_t / m.m1);
  const Eigen::Vector2d a2((1 + 2.5 * f_z) / m.m2, -f_t / m.m2);
  Eigen::Vector2d T1 = Eigen::Vector2d::Zero(), T2 = Eigen::Vector2d::Zero();
  if (N1 > 0) T1 = -m.mu_s * N1 * clothSlipDirection(s1, a1, m.slip_floor_mps);
  if (N2 > 0) T2 = -m.mu_s * N2 * clothSlipDirection(s2, a2, m.slip_floor_mps);
  const double k1 = R / m.I1, k2 = R / m.I2;
  dy[kV1n] = (-1 + T1.x()) / m.m1;
  dy[kV1t] = (f_t + T1.y()) / m.m1;
  dy[kW1n] = k1 * T1.y();
  dy[kW1t] = k1 * (-f_z - T1.x());
  dy[kW1z] = k1 * f_t;
  dy[kV2n] = (1 + T2.x()) / m.m2;
  dy[kV2t] = (-f_t + T2.y()) / m.m2;
  dy[kW2n] = k2 * T2.y();
  dy[kW2t] = k2 * (-f_z - T2.x());
  dy[kW2z] = k2 * f_t;
  dy[kApproach] = dy[kV1n] - dy[kV2n];
  dy[kWork] = y[kApproach];
  dy[kTable1] = N1;
  dy[kTable2] = N2;
  dy[kLift1] = std::max(0.0, f_z);
  dy[kLift2] = std::max(0.0, -f_z);
  dy[kFrictionT] = f_t;
  dy[kFrictionZ] = f_z;
}

// Largest step that covers at most kApproachFraction of the predicted distance to a zero of a
// decreasing slip: |s| / (-d|s|/dP).
double approachLimit(const Eigen::Vector2d& slip, const Eigen::Vector2d& slip_rate, double floor) {
  const double s = slip.norm();
  if (s <= floor) return std::numeric_limits<double>::infinity();
  const double rate = slip.dot(slip_rate) / s;
  return rate < 0 ? kApproachFraction * s / -rate : std::numeric_limits<double>::infinity();
}

struct MathavanOutcome {
  State y;
  double P_final = 0, P_compression = 0, W_compression = 0;
  std::optional<double> rolling_from;
  long evaluations = 0;
};

double stepLimit(const Model& m, const State& y, const State& dy, bool rolling) {
  const double R = m.R;
  double limit = std::numeric_limits<double>::infinity();
  if (!rolling) {
    const Eigen::Vector2d g(slipT(m, y), slipZ(m, y));
    const Eigen::Vector2d g_rate(dy[kV1t] - dy[kV2t] + R * (dy[kW1z] + dy[kW2z]),
                                 -R * (dy[kW1t] + dy[kW2t]));
    limit = std::min(limit, approachLimit(g, g_rate, m.slip_floor_mps));
  }
  if (dy[kTable1] > 0) {
    const Eigen::Vector2d s(y[kV1n] - R * y[kW1t], y[kV1t] + R * y[kW1n]);
    const Eigen::Vector2d s_rate(dy[kV1n] - R * dy[kW1t], dy[kV1t] + R * dy[kW1n]);
    limit = std::min(limit, approachLimit(s, s_rate, m.slip_floor_mps));
  }
  if (dy[kTable2] > 0) {
    const Eigen::Vector2d s(y[kV2n] - R * y[kW2t], y[kV2t] + R * y[kW2n]);
    const Eigen::Vector2d s_rate(dy[kV2n] - R * dy[kW2t], dy[kV2t] + R * dy[kW2n]);
    limit = std::min(limit, approachLimit(s, s_rate, m.slip_floor_mps));
  }
  return limit;
}

bool slipVanished(const Model& m, const State& y) {
  return std::hypot(slipT(m, y), slipZ(m, y)) <= m.slip_floor_mps;
}

MathavanOutcome integrateAdaptive(const Model& m, const State& y0, double speed_scale,
                                  double restitution, double tolerance) {
  const double mu_red = m.m1 * m.m2 / (m.m1 + m.m2);
  const double approach = y0[kApproach];
  const double P_scale = mu_red * approach;
  // Each component's allowed error per step (tolerance times its scale).
  State allowed = State::Constant(speed_scale);
  for (int i : {kW1n, kW1t, kW1z, kW2n, kW2t, kW2z}) allowed[i] = speed_scale / m.R;
  // The normal approach and the normal work decide the ends of compression and restitution, so
  // their error is measured against the approach itself (a grazing contact's is tiny), not
  // against the ball speeds.
  allowed[kApproach] = approach;
  allowed[kWork] = mu_red * approach * approach;
  for (int i : {kTable1, kTable2, kLift1, kLift2, kFrictionT, kFrictionZ}) {
    allowed[i] = mu_red * speed_scale;
  }
  allowed *= tolerance;

  MathavanOutcome out;
  State y = y0;
  double P = 0;
  bool rolling = slipVanished(m, y);
  if (rolling) out.rolling_from = 0.0;
  bool compressing = true;
  double work_target = 0;
  double h = kFirstStepFraction * P_scale;
  const auto rate = [&](const State& s) {
    State dy;
    rates(m, s, rolling, dy);
    ++out.evaluations;
    return dy;
  };
  State k1 = rate(y);

  // Event functions, positive before the event and scaled by the impact's own size so that grazing
  // impacts are resolved as finely as head-on ones: g_n / g_n(0) while compressing, then the work
  // still to be returned over W_c.
  double compression_work = 0;
  auto event = [&](const State& s) {
    return compressing ? s[kApproach] / approach : (s[kWork] - work_target) / compression_work;
  };

  for (long n = 0;; ++n) {
    if (n == kMaxSteps) throw std::logic_error("Mathavan ball-ball integration did not terminate");
    const double h_try = std::min(h, stepLimit(m, y, k1, rolling));
    const dop853::Stages<State> step = dop853::stages(y, k1, h_try, rate);
    const double error = dop853::stepError(step, allowed, h_try);
    const double factor = dop853::stepFactor(error, kStepSafety, kStepMinFactor, kStepMaxFactor);
    if (!(error <= 1)) {  // also catches NaN
      h = h_try * factor;
      continue;
    }
    State y1 = step.end;
    double h_taken = h_try;
    const bool event_hit = event(y1) <= kEventTolerance;
    if (event_hit) {
      h_taken = dop853::locateEvent(y, k1, h_try, step, rate, event, kEventTolerance,
                                    kMaxEventIterations, &y1);
    }
    y = y1;
    P += h_taken;
    bool laws_changed = event_hit;
    if (!rolling && slipVanished(m, y)) {
      rolling = true;
      out.rolling_from = P;
      laws_changed = true;
    }
    if (event_hit) {
      if (compressing) {
        compressing = false;
        out.P_compression = P;
        out.W_compression = y[kWork];
        compression_work = y[kWork];
        work_target = (1 - restitution * restitution) * y[kWork];
        if (event(y) <= kEventTolerance) break;  // e = 0: nothing is returned
      } else {
        break;
      }
    }
    // The last stage's rate is the next step's first unless the step was cut short at an event or
    // the contact started rolling there.
    k1 = laws_changed ? rate(y) : step.rate_at_end;
    h = h_try * factor;
  }
  out.y = y;
  out.P_final = P;
  return out;
}

// The paper's scheme: explicit Euler with rates frozen over each increment, trapezoidal work.
MathavanOutcome integrateEuler(const Model& m, const State& y0, double restitution, int steps) {
  const double mu_red = m.m1 * m.m2 / (m.m1 + m.m2);
  const double dP = (1 + restitution) * mu_red * y0[kApproach] / steps;
  MathavanOutcome out;
  State y = y0, dy;
  double P = 0, work_target = 0;
  bool rolling = slipVanished(m, y), compressing = true;
  if (rolling) out.rolling_from = 0.0;
  const long max_increments = 1000L * steps;
  for (long n = 0;; ++n) {
    if (n == max_increments)
      throw std::logic_error("Euler ball-ball integration did not terminate");
    rates(m, y, rolling, dy);
    ++out.evaluations;
    const double g_before = y[kApproach];
    for (int i = 0; i < kStateSize; ++i) y[i] += dP * dy[i];
    const double g_after = y[kApproach];
    y[kWork] += dP * ((g_before + g_after) / 2 - dy[kWork]);  // trapezoid instead of Euler
    P += dP;
    if (!rolling && slipVanished(m, y)) {
      rolling = true;
      out.rolling_from = P;
    }
    if (compressing && g_after <= 0) {
      compressing = false;
      out.P_compression = P;
      out.W_compression = y[kWork];
      work_target = (1 - restitution * restitution) * y[kWork];
    }
    if (!compressing && y[kWork] <= work_target) break;
  }
  out.y = y;
  out.P_final = P;
  return out;
}

}  // namespace

BallBallParams snookerMathavan2014Params() {
  BallBallParams p;
  p.model = BallBallModel::Mathavan2014;
  p.radius_m = 0.02625;
  p.mass1_kg = 0.1406;
  p.mass2_kg = 0.1406;
  p.restitution = 0.89;
  p.ball_friction = 0.05;
  p.cloth_friction = 0.212;
  return p;
}

void validateBallBallParams(const BallBallParams& p) {
  requireFinite("ball radius (m)", p.radius_m);
  requireFinite("ball 1 mass (kg)", p.mass1_kg);
  requireFinite("ball 2 mass (kg)", p.mass2_kg);
  requireFinite("ball-ball restitution e", p.restitution);
  if (!(p.radius_m >= kMinBallRadius_m && p.radius_m <= kMaxBallRadius_m)) {
    rejectValue("ball radius (m)", p.radius_m,
                "it must lie in [" + valueText(kMinBallRadius_m) + ", " +
                    valueText(kMaxBallRadius_m) + "]");
  }
  // Rules are worded only when a value breaks them: this runs before every impact.
  auto mass_rule = [] {
    return "it must lie in [" + valueText(kMinBallMass_kg) + ", " + valueText(kMaxBallMass_kg) +
           "]";
  };
  if (!(p.mass1_kg >= kMinBallMass_kg && p.mass1_kg <= kMaxBallMass_kg)) {
    rejectValue("ball 1 mass (kg)", p.mass1_kg, mass_rule());
  }
  if (!(p.mass2_kg >= kMinBallMass_kg && p.mass2_kg <= kMaxBallMass_kg)) {
    rejectValue("ball 2 mass (kg)", p.mass2_kg, mass_rule());
  }
  if (!(p.restitution >= 0 && p.restitution <= 1)) {
    rejectValue("ball-ball restitution e", p.restitution, "it must lie in [0, 1]");
  }
  switch (p.model) {
    case BallBallModel::FrictionalInelastic:
      if (p.friction_law == BallBallFrictionLaw::AlciatoreFit) {
        requireFinite("friction fit a", p.friction_fit_a);
        requireFinite("friction fit b", p.friction_fit_b);
        requireFinite("friction fit c (s/m)", p.friction_fit_c_s_per_m);
        if (!(p.friction_fit_a >= 0))
          rejectValue("friction fit a", p.friction_fit_a, "it must be >= 0");
        if (!(p.friction_fit_b >= 0))
          rejectValue("friction fit b", p.friction_fit_b, "it must be >= 0");
        if (!(p.friction_fit_c_s_per_m >= 0)) {
          rejectValue("friction fit c (s/m)", p.friction_fit_c_s_per_m, "it must be >= 0");
        }
        // mu at zero slip speed is a + b, the largest the fit gives.
        if (!(p.friction_fit_a + p.friction_fit_b < 1)) {
          rejectValue("friction fit a + b", p.friction_fit_a + p.friction_fit_b,
                      "the friction at zero slip speed must lie below 1");
        }
      } else if (p.friction_law == BallBallFrictionLaw::Constant) {
        requireFinite("ball-ball friction mu", p.constant_friction);
        if (!(p.constant_friction >= 0 && p.constant_friction < 1)) {
          rejectValue("ball-ball friction mu", p.constant_friction, "it must lie in [0, 1)");
        }
      } else {
        throw std::invalid_argument(
            "ball-ball friction law = " + std::to_string(static_cast<int>(p.friction_law)) +
            " is not allowed: it must be AlciatoreFit or Constant");
      }
      break;
    case BallBallModel::Mathavan2014: {
      requireFinite("ball-ball friction mu_b", p.ball_friction);
      requireFinite("cloth friction mu_s", p.cloth_friction);
      requireFinite("integration tolerance", p.tolerance);
      if (!(p.cloth_friction >= 0 && p.cloth_friction < 1)) {
        rejectValue("cloth friction mu_s", p.cloth_friction, "it must lie in [0, 1)");
      }
      // Keeps the cloth contacts slipping throughout the impact (see the derivation above).
      const double mu_b_limit = 1 / (2.5 + 3.5 * p.cloth_friction);
      if (!(p.ball_friction >= 0 && p.ball_friction < mu_b_limit)) {
        rejectValue("ball-ball friction mu_b", p.ball_friction,
                    "with mu_s = " + valueText(p.cloth_friction) + " it must lie in [0, " +
                        valueText(mu_b_limit) +
                        "), or a cloth contact could stick during the impact");
      }
      if (!(p.tolerance >= 1e-14 && p.tolerance <= 1e-3)) {
        rejectValue("integration tolerance", p.tolerance, "it must lie in [1e-14, 1e-3]");
      }
      if (p.fixed_steps < 0) {
        rejectValue("fixed Euler steps", p.fixed_steps,
                    "it must be >= 0 (0 selects the adaptive solver)");
      }
      break;
    }
    default:
      throw std::invalid_argument(
          "ball-ball model = " + std::to_string(static_cast<int>(p.model)) +
          " is not allowed: it must be FrictionalInelastic or Mathavan2014");
  }
}

double approachSpeed(const BallVelocity& ball1, const BallVelocity& ball2,
                     const Eigen::Vector3d& line_of_centres) {
  return (ball1.v - ball2.v).dot(line_of_centres);
}

void validateBallBallContact(const BallVelocity& ball1, const BallVelocity& ball2,
                             const Eigen::Vector3d& n) {
  const char* axes[] = {"x", "y", "z"};
  // Speeds and spins within the bounds of cushion_model.h (found by fuzzing: |v| = 1e306 m/s ran
  // the Euler scheme out of its increments).
  // Worded only when a value breaks them: this runs before every impact.
  auto speed_rule = [] {
    return "it must be a finite number of magnitude at most " + valueText(kMaxBallSpeed_mps);
  };
  auto spin_rule = [] {
    return "it must be a finite number of magnitude at most " + valueText(kMaxBallSpin_radps);
  };
  for (int i = 0; i < 3; ++i) {
    if (!(std::abs(ball1.v[i]) <= kMaxBallSpeed_mps)) {
      rejectValue(std::string("ball 1 v_") + axes[i] + " (m/s)", ball1.v[i], speed_rule());
    }
    if (!(std::abs(ball1.w[i]) <= kMaxBallSpin_radps)) {
      rejectValue(std::string("ball 1 w_") + axes[i] + " (rad/s)", ball1.w[i], spin_rule());
    }
    if (!(std::abs(ball2.v[i]) <= kMaxBallSpeed_mps)) {
      rejectValue(std::string("ball 2 v_") + axes[i] + " (m/s)", ball2.v[i], speed_rule());
    }
    if (!(std::abs(ball2.w[i]) <= kMaxBallSpin_radps)) {
      rejectValue(std::string("ball 2 w_") + axes[i] + " (rad/s)", ball2.w[i], spin_rule());
    }
    if (!std::isfinite(n[i])) {
      rejectValue(std::string("line of centres n_") + axes[i], n[i], "it must be a finite number");
    }
  }
  if (ball1.v.z() != 0)
    rejectValue("ball 1 v_z (m/s)", ball1.v.z(), "the ball must be on the table (0)");
  if (ball2.v.z() != 0)
    rejectValue("ball 2 v_z (m/s)", ball2.v.z(), "the ball must be on the table (0)");
  if (!(std::abs(n.norm() - 1) <= kLineOfCentresTolerance)) {
    rejectValue("line of centres |n|", n.norm(), "it must be a unit vector (within 1e-9)");
  }
  if (!(std::abs(n.z()) <= kLineOfCentresTolerance)) {
    rejectValue("line of centres n_z", n.z(),
                "balls on the table touch at their equators (0 within 1e-9)");
  }
  const double approach = approachSpeed(ball1, ball2, n);
  if (!(approach > 0)) {
    rejectValue(
        "approach speed (v1 - v2) . n (m/s)", approach,
        "the balls must approach along the line of centres (> 0); a separating or grazing pair "
        "needs no impact");
  }
  if (!(approach >= kMinApproachSpeed_mps)) {
    rejectValue("approach speed (v1 - v2) . n (m/s)", approach,
                "it must be at least " + valueText(kMinApproachSpeed_mps) +
                    " (a slower approach is no impact the solvers can resolve)");
  }
}

double ballBallFriction(const BallBallParams& params, double slip_speed_mps) {
  if (params.friction_law == BallBallFrictionLaw::Constant) return params.constant_friction;
  return params.friction_fit_a +
         params.friction_fit_b * std::exp(-params.friction_fit_c_s_per_m * slip_speed_mps);
}

Eigen::Vector3d contactSlip(const BallBallParams& params, const BallVelocity& ball1,
                            const BallVelocity& ball2, const Eigen::Vector3d& line_of_centres) {
  const Frame f = frameOf(line_of_centres);
  const double R = params.radius_m;
  const Eigen::Vector3d g = (ball1.v - ball2.v) + R * (ball1.w + ball2.w).cross(f.n);
  return g - g.dot(f.n) * f.n;
}

BallBallImpactResult resolveBallBallImpact(const BallBallParams& params, const BallVelocity& ball1,
                                           const BallVelocity& ball2,
                                           const Eigen::Vector3d& line_of_centres) {
  validateBallBallParams(params);
  validateBallBallContact(ball1, ball2, line_of_centres);
  const Frame f = frameOf(line_of_centres);
  const double R = params.radius_m, m1 = params.mass1_kg, m2 = params.mass2_kg;
  const double I1 = 0.4 * m1 * R * R, I2 = 0.4 * m2 * R * R;
  const double mu_red = m1 * m2 / (m1 + m2);
  const double e = params.restitution;

  // Local components (n, t, z).
  const double v1n = ball1.v.dot(f.n), v1t = ball1.v.dot(f.t);
  const double v2n = ball2.v.dot(f.n), v2t = ball2.v.dot(f.t);
  const Eigen::Vector3d w1(ball1.w.dot(f.n), ball1.w.dot(f.t), ball1.w.z());
  const Eigen::Vector3d w2(ball2.w.dot(f.n), ball2.w.dot(f.t), ball2.w.z());
  // The approach as validated (> 0), from the relative velocity: v1n - v2n would cancel to
  // round-off of the ball speeds (or to zero) on a grazing contact. n and f.n differ by at most
  // kLineOfCentresTolerance relative.
  const double g_n = approachSpeed(ball1, ball2, line_of_centres);

  BallBallImpactResult result;
  // Outgoing local state: v (n, t), w (n, t, z).
  Eigen::Vector2d v1_out, v2_out;
  Eigen::Vector3d w1_out, w2_out;
  if (params.model == BallBallModel::FrictionalInelastic) {
    const double P = mu_red * (1 + e) * g_n;
    const double g_t = v1t - v2t + R * (w1.z() + w2.z());
    const double g_z = -R * (w1.y() + w2.y());
    const double slip = std::hypot(g_t, g_z);
    double f_t = 0, f_z = 0;
    if (slip > 0) {
      const double limit = ballBallFriction(params, slip) * P;
      const double to_rolling = (2.0 / 7.0) * mu_red * slip;
      const double lambda = std::min(limit, to_rolling);
      if (to_rolling <= limit) result.contact_rolling_from_impulse_Ns = P;
      f_t = -lambda * g_t / slip;
      f_z = -lambda * g_z / slip;
    } else {
      result.contact_rolling_from_impulse_Ns = 0.0;
    }
    // J = (-P, f_t, f_z) on ball 1, -J on ball 2; R n x J = R (0, -f_z, f_t).
    v1_out = {v1n - P / m1, v1t + f_t / m1};
    v2_out = {v2n + P / m2, v2t - f_t / m2};
    const Eigen::Vector3d spin(0.0, -R * f_z, R * f_t);
    w1_out = w1 + spin / I1;
    w2_out = w2 + spin / I2;
    result.normal_impulse_Ns = P;
    result.compression_impulse_Ns = mu_red * g_n;
    result.compression_work_J = 0.5 * mu_red * g_n * g_n;
    result.contact_friction_impulse_Ns = f_t * f.t + f_z * f.z;
    result.table_normal_impulse_Ns[0] = std::max(0.0, -f_z);
    result.table_normal_impulse_Ns[1] = std::max(0.0, f_z);
    result.discarded_vertical_velocity_mps[0] = f_z / m1;
    result.discarded_vertical_velocity_mps[1] = -f_z / m2;
  } else {
    const double speed_scale =
        std::max({ball1.v.norm(), ball2.v.norm(), R * ball1.w.norm(), R * ball2.w.norm()});
    const Model model{
        R, m1, m2, I1, I2, params.ball_friction, params.cloth_friction, kSlipFloor * speed_scale};
    State y = State::Zero();
    y[kV1n] = v1n, y[kV1t] = v1t, y[kW1n] = w1.x(), y[kW1t] = w1.y(), y[kW1z] = w1.z();
    y[kV2n] = v2n, y[kV2t] = v2t, y[kW2n] = w2.x(), y[kW2t] = w2.y(), y[kW2z] = w2.z();
    y[kApproach] = g_n;
    const MathavanOutcome o = params.fixed_steps > 0
                                  ? integrateEuler(model, y, e, params.fixed_steps)
                                  : integrateAdaptive(model, y, speed_scale, e, params.tolerance);
    const State& z = o.y;
    v1_out = {z[kV1n], z[kV1t]};
    v2_out = {z[kV2n], z[kV2t]};
    w1_out = {z[kW1n], z[kW1t], z[kW1z]};
    w2_out = {z[kW2n], z[kW2t], z[kW2z]};
    result.normal_impulse_Ns = o.P_final;
    result.compression_impulse_Ns = o.P_compression;
    result.compression_work_J = o.W_compression;
    result.contact_friction_impulse_Ns = z[kFrictionT] * f.t + z[kFrictionZ] * f.z;
    result.table_normal_impulse_Ns[0] = z[kTable1];
    result.table_normal_impulse_Ns[1] = z[kTable2];
    result.discarded_vertical_velocity_mps[0] = (z[kLift1] - z[kTable1]) / m1;
    result.discarded_vertical_velocity_mps[1] = (z[kLift2] - z[kTable2]) / m2;
    result.contact_rolling_from_impulse_Ns = o.rolling_from;
    result.rhs_evaluations = o.evaluations;
  }
  result.ball1.v = v1_out.x() * f.n + v1_out.y() * f.t;
  result.ball2.v = v2_out.x() * f.n + v2_out.y() * f.t;
  result.ball1.w = w1_out.x() * f.n + w1_out.y() * f.t + w1_out.z() * f.z;
  result.ball2.w = w2_out.x() * f.n + w2_out.y() * f.t + w2_out.z() * f.z;
  return result;
}

}  // namespace baize::physics
