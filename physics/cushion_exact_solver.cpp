#include "physics/cushion_exact_solver.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

// How the solver works (derivation in docs/cushion.md).
//
// Write a = -(friction impulse rate at I) in the basis (x, Y') and b = -(friction impulse rate at C) in
// (x, y), both per unit of P. While both contacts slip, a = mu_w (cos Phi, sin Phi) and
// b = mu_s q (cos Phi', sin Phi') with q = sin th + cos th a_y (eq. 8). Every velocity is linear in
// P and in the integrals A = int a dP and B = int b dP (impulseResponse), and so are the slips:
//
//   u_I(P) = u_I(0) - (1/M) [ 7/2 A_x + (1 - 5s/2) B_x ,  (s^2 + 5/2) A_y + (5/2 - s) B_y - s c P ]
//   u_C(P) = u_C(0) - (1/M) [ (1 - 5s/2) A_x + 7/2 B_x ,  c P + (5/2 - s) A_y + 7/2 B_y ]
//
// (s = sin th, c = cos th; the 4x4 matrix is the inverse effective mass of the two contacts.) So the
// whole impact is the 5-dimensional system y = (A_x, A_y, B_x, B_y, W) with dy/dP = (a, b, c v_y).
//
// A contact is either slipping (friction mu along its slip) or held (its slip has vanished): a held
// contact's friction is whatever keeps its slip rate zero (a linear solve), saturated on its friction
// cone when that is more than the cone allows, which is the sliding-mode (Filippov) friction and
// makes the contact slip off continuously. The right side is smooth between these changes, and the
// system is integrated with the Dormand-Prince 5(4) pair:
// - a slipping contact's slip is approached without ever stepping across its zero (beyond it friction
//   flips and no error estimate means anything): each step stops short of the linearly predicted
//   zero, and a slip below the vanishing threshold is held;
// - a held contact whose slip has grown past a few times that threshold slips again;
// - the ends of compression (v_y = 0) and of restitution (W = (1 - e^2) W_c, eq. 17b) are located by
//   Newton's method on the step length, each trial a full Runge-Kutta step.

namespace baize::physics {
namespace {

using State = Eigen::Matrix<double, 5, 1>;  // (A_x, A_y, B_x, B_y: N s; W: J)
enum : int { kAx = 0, kAy = 1, kBx = 2, kBy = 3, kWork = 4 };

// A slip below this fraction of (tolerance x velocity scale) has vanished and the contact is held.
// Taking it as zero moves the result by about that much: the remaining impulse to its true zero is
// about M |u| / (7/2 mu), over which friction of any direction changes the velocities by less than |u|.
constexpr double kHeldSlipFraction = 1;
// A slip below this multiple of the vanishing threshold that grew over the last step although friction
// could hold it is chattering: Coulomb friction that can hold a contact makes its slip shrink, so the
// growth is friction overshooting about zero, the discrete picture of a contact that sticks. It is
// held.
constexpr double kChatterSlipMultiple = 1000;
// A held contact slips again once its slip exceeds this multiple of the vanishing threshold. Below it
// a held contact whose friction saturates slides on the edge of its cone with a slip so small that its
// direction is stiff; the saturated friction already describes that sliding, with the direction of
// the friction it needs, and the gap keeps contacts from flickering between the two states.
constexpr double kReleaseSlipMultiple = 1000;
// Steps toward a vanishing slip stop this fraction short of its linearly predicted zero; each step
// then cuts the slip by about this factor.
constexpr double kAimShortMin = 1e-3;
// When such a step fails the error test the slip turns as it vanishes: stop further short, by this
// factor up to the maximum, instead of shrinking the step blindly.
constexpr double kAimShortGrowth = 8;
constexpr double kAimShortMax = 0.5;
// An event is located when its function is this small against its scale times the tolerance...
constexpr double kEventResidualFraction = 1e-3;
// ...or when the bracket on the step length is this many rounding units of P wide.
constexpr double kEventBracketUlps = 8;
// Step-size control of the embedded pair: safety factor and bounds on the change per step.
constexpr double kStepSafety = 0.9;
constexpr double kStepMinFactor = 0.2;
constexpr double kStepMaxFactor = 5.0;
// First step as a fraction of M v_y0, the scale of the whole normal impulse.
constexpr double kFirstStepFraction = 0.05;
// Logic guards, far above anything the bounded equations need (a typical impact takes 10-60 steps).
constexpr int kMaxSteps = 100000;
constexpr int kMaxEventIterations = 60;

constexpr double kEpsilon = 2.220446049250313e-16;

// Dormand-Prince 5(4) coefficients (Dormand & Prince 1980).
constexpr double c2 = 1.0 / 5, c3 = 3.0 / 10, c4 = 4.0 / 5, c5 = 8.0 / 9;
constexpr double a21 = 1.0 / 5;
constexpr double a31 = 3.0 / 40, a32 = 9.0 / 40;
constexpr double a41 = 44.0 / 45, a42 = -56.0 / 15, a43 = 32.0 / 9;
constexpr double a51 = 19372.0 / 6561, a52 = -25360.0 / 2187, a53 = 64448.0 / 6561,
                 a54 = -212.0 / 729;
constexpr double a61 = 9017.0 / 3168, a62 = -355.0 / 33, a63 = 46732.0 / 5247, a64 = 49.0 / 176,
                 a65 = -5103.0 / 18656;
constexpr double b1 = 35.0 / 384, b3 = 500.0 / 1113, b4 = 125.0 / 192, b5 = -2187.0 / 6784,
                 b6 = 11.0 / 84;
// Fifth-order weights minus the embedded fourth-order ones: the local error estimate.
constexpr double e1 = 35.0 / 384 - 5179.0 / 57600, e3 = 500.0 / 1113 - 7571.0 / 16695,
                 e4 = 125.0 / 192 - 393.0 / 640, e5 = -2187.0 / 6784 + 92097.0 / 339200,
                 e6 = 11.0 / 84 - 187.0 / 2100, e7 = -1.0 / 40;

struct ContactState {
  bool frictionless = false;
  ContactMode mode = ContactMode::Slip;                  // Stick: held (see the top of the file)
  Eigen::Vector2d direction = Eigen::Vector2d::UnitX();  // last slip direction, for a slip of exactly 0
  double aim_short = kAimShortMin;                       // see kAimShortMin
  Eigen::Vector2d previous_slip = Eigen::Vector2d::Zero();  // at the start of the last accepted step
};

struct Friction {
  Eigen::Vector2d a = Eigen::Vector2d::Zero();  // at I, per unit P, along the slip
  Eigen::Vector2d b = Eigen::Vector2d::Zero();  // at C, per unit P, along the slip
};

struct Step {
  State y;
  State rate_at_end;  // FSAL: the rate at the step's end, reused as the next step's first stage
  double error = 0;   // scaled error norm; <= 1 accepts
};

double stepFactor(double error) {
  if (!(error > 0)) return kStepMaxFactor;
  return std::clamp(kStepSafety * std::pow(error, -0.2), kStepMinFactor, kStepMaxFactor);
}

class ExactImpact {
 public:
  ExactImpact(const CushionParams& params, const BallVelocity& incoming, const ExactSolverOptions& options)
      : params_(params), incoming_(incoming), options_(options) {
    s_ = contactSinTheta(params);
    c_ = std::sqrt(1 - s_ * s_);
    M_ = params.mass_kg;
    mu_ = {params.cushion_friction, params.cloth_friction};
    slip0_ = {cushionSlip(params, incoming), clothSlip(params, incoming)};
    vy0_ = incoming.v.y();
    velocity_scale_ = incoming.v.norm() + params.radius_m * incoming.w.norm();
    const double impulse_scale = M_ * velocity_scale_;
    for (int i = 0; i < 4; ++i) error_scale_[i] = options.tolerance * impulse_scale;
    error_scale_[kWork] = options.tolerance * impulse_scale * velocity_scale_;
    held_slip_ = kHeldSlipFraction * options.tolerance * velocity_scale_;
    for (int k = 0; k < 2; ++k) contacts_[k].frictionless = mu_[k] == 0;
    // The inverse effective mass of the two contacts (see the top of the file), times M.
    const double coupling_x = 1 - 2.5 * s_, coupling_y = 2.5 - s_;
    delassus_ << 3.5, 0, coupling_x, 0,  //
        0, s_ * s_ + 2.5, 0, coupling_y,     //
        coupling_x, 0, 3.5, 0,               //
        0, coupling_y, 0, 3.5;
  }

  CushionImpactResult run();

 private:
  Eigen::Vector2d slip(int k, double P, const State& y) const {
    const Eigen::Vector4d response = delassus_ * Eigen::Vector4d(y[kAx], y[kAy], y[kBx], y[kBy]);
    if (k == 0) return slip0_[0] - Eigen::Vector2d(response[0], response[1] - s_ * c_ * P) / M_;
    return slip0_[1] - Eigen::Vector2d(response[2], response[3] + c_ * P) / M_;
  }

  double normalVelocity(double P, const State& y) const {  // v_y
    return vy0_ - (c_ * P - s_ * y[kAy] + y[kBy]) / M_;
  }

  Eigen::Vector2d slipDirection(int k, const Eigen::Vector2d& u) const {
    const double speed = u.norm();
    return speed > 0 ? Eigen::Vector2d(u / speed) : contacts_[k].direction;
  }

  // Friction per unit P for the current contact states, given both slips.
  Friction friction(const Eigen::Vector2d& slip_I, const Eigen::Vector2d& slip_C) const {
    const bool held_I = !contacts_[0].frictionless && contacts_[0].mode == ContactMode::Stick;
    const bool held_C = !contacts_[1].frictionless && contacts_[1].mode == ContactMode::Stick;
    const double s = s_, c = c_;
    Friction f;
    if (held_I && held_C) {  // both held: the x pair gives 0, the y pair a 2x2 solve
      const double det = 3.5 * (s * s + 2.5) - (2.5 - s) * (2.5 - s);
      f.a.y() = c * (2.5 + 2.5 * s) / det;
      f.b.y() = -f.a.y();
    } else if (held_I) {  // the cloth slips (or is frictionless); its force couples through q = s + c a_y
      const Eigen::Vector2d g = contacts_[1].frictionless
                                    ? Eigen::Vector2d::Zero()
                                    : Eigen::Vector2d(mu_[1] * slipDirection(1, slip_C));
      f.a.y() = (s * c - (2.5 - s) * s * g.y()) / ((s * s + 2.5) + (2.5 - s) * c * g.y());
      const double table_rate = s + c * f.a.y();
      f.a.x() = -(1 - 2.5 * s) * table_rate * g.x() / 3.5;
      f.b = table_rate * g;
    } else {
      if (!contacts_[0].frictionless) f.a = mu_[0] * slipDirection(0, slip_I);
      if (held_C) {
        f.b = Eigen::Vector2d(-(1 - 2.5 * s) * f.a.x() / 3.5, -(c + (2.5 - s) * f.a.y()) / 3.5);
      } else if (!contacts_[1].frictionless) {
        f.b = mu_[1] * (s + c * f.a.y()) * slipDirection(1, slip_C);
      }
    }
    // A held contact whose friction cannot hold it gets the most its cone gives, along the friction
    // it needs: it then slips off continuously.
    if (held_I && f.a.norm() > mu_[0]) f.a *= mu_[0] / f.a.norm();
    if (held_C) {
      const double limit = mu_[1] * (s + c * f.a.y());
      if (f.b.norm() > limit) f.b *= limit / f.b.norm();
    }
    return f;
  }

  // d(slip_k)/dP for friction rates r (the first four components of a rate).
  Eigen::Vector2d slipRate(int k, const State& r) const {
    const Eigen::Vector4d response = delassus_ * Eigen::Vector4d(r[kAx], r[kAy], r[kBx], r[kBy]);
    if (k == 0) return -Eigen::Vector2d(response[0], response[1] - s_ * c_) / M_;
    return -Eigen::Vector2d(response[2], response[3] + c_) / M_;
  }

  State rate(double P, const State& y) {
    ++evaluations_;
    const Friction f = friction(slip(0, P, y), slip(1, P, y));
    State r;
    r << f.a.x(), f.a.y(), f.b.x(), f.b.y(), c_ * normalVelocity(P, y);
    return r;
  }

  Step rungeKuttaStep(double P, const State& y, const State& k1, double h) {
    const State k2 = rate(P + c2 * h, y + h * (a21 * k1));
    const State k3 = rate(P + c3 * h, y + h * (a31 * k1 + a32 * k2));
    const State k4 = rate(P + c4 * h, y + h * (a41 * k1 + a42 * k2 + a43 * k3));
    const State k5 = rate(P + c5 * h, y + h * (a51 * k1 + a52 * k2 + a53 * k3 + a54 * k4));
    const State k6 = rate(P + h, y + h * (a61 * k1 + a62 * k2 + a63 * k3 + a64 * k4 + a65 * k5));
    Step step;
    step.y = y + h * (b1 * k1 + b3 * k3 + b4 * k4 + b5 * k5 + b6 * k6);
    step.rate_at_end = rate(P + h, step.y);
    const State error = h * (e1 * k1 + e3 * k3 + e4 * k4 + e5 * k5 + e6 * k6 + e7 * step.rate_at_end);
    step.error = error.cwiseAbs().cwiseQuotient(error_scale_).maxCoeff();
    return step;
  }

  // The phase-ending event: positive before it; v_y in compression, W - W_target in restitution.
  double phaseEvent(double P, const State& y) const {
    return compressing_ ? normalVelocity(P, y) : y[kWork] - work_target_;
  }
  double phaseEventSlope(const State& r) const {  // its derivative in P along the solution
    return compressing_ ? -(c_ - s_ * r[kAy] + r[kBy]) / M_ : r[kWork];
  }
  double phaseEventScale() const {
    return compressing_ ? velocity_scale_ : M_ * velocity_scale_ * velocity_scale_;
  }

  // Finds the step length in (0, h] that lands on the phase event, which the full step crossed:
  // safeguarded Newton on the length (each trial a full Runge-Kutta step, whose end rate gives the
  // slope), falling back to Illinois regula falsi. Returns false, with *length set to a shorter step
  // to take instead, when a trial breaks the error tolerance.
  bool locatePhaseEnd(double P, const State& y, const State& k1, double h, const Step& full, double* length,
                      Step* landed) {
    const double tolerance_g = kEventResidualFraction * options_.tolerance * phaseEventScale();
    double lo = 0, g_lo = phaseEvent(P, y);
    double hi = h, g_hi = phaseEvent(P + h, full.y);
    *length = h;
    *landed = full;
    if (g_lo <= tolerance_g) {  // due where the step starts
      *length = 0;
      landed->y = y;
      return true;
    }
    // Newton from the step start where the event function falls (at the start of restitution v_y,
    // its slope, is zero: then the secant).
    auto newton = [](double from, double g, double slope) {
      return slope < 0 ? from - g / slope : -1.0;  // -1: outside any bracket
    };
    double trial = newton(0, g_lo, phaseEventSlope(k1));
    int side = 0;
    for (int it = 0; it < kMaxEventIterations; ++it) {
      if (!(trial > lo && trial < hi) && g_lo > g_hi) trial = lo + (hi - lo) * (g_lo / (g_lo - g_hi));
      if (!(trial > lo && trial < hi)) trial = 0.5 * (lo + hi);
      const Step attempt = rungeKuttaStep(P, y, k1, trial);
      if (attempt.error > 1) {
        *length = trial * stepFactor(attempt.error);
        return false;
      }
      const double g = phaseEvent(P + trial, attempt.y);
      if (g <= tolerance_g) {  // at or past the event: a candidate landing
        hi = trial;
        g_hi = g;
        *length = trial;
        *landed = attempt;
        if (g >= -tolerance_g) return true;
        if (side == -1) g_lo *= 0.5;  // Illinois: keep one end from sticking
        side = -1;
      } else {
        lo = trial;
        g_lo = g;
        if (side == +1) g_hi *= 0.5;
        side = +1;
      }
      if (hi - lo <= kEventBracketUlps * kEpsilon * (P + h)) break;
      trial = newton(trial, g, phaseEventSlope(attempt.rate_at_end));  // replaced above if outside the bracket
    }
    return landed->error <= 1;
  }

  // Whether friction could hold contact k at (P, y) without saturating.
  bool canHold(int k, double P, const State& y) {
    const ContactMode saved = contacts_[k].mode;
    contacts_[k].mode = ContactMode::Stick;
    const Friction f = friction(slip(0, P, y), slip(1, P, y));
    contacts_[k].mode = saved;
    if (k == 0) return f.a.norm() < mu_[0];
    return f.b.norm() < mu_[1] * (s_ + c_ * f.a.y());
  }

  void setMode(int k, ContactMode mode, double P) {
    contacts_[k].mode = mode;
    result_.contact_changes.push_back({P, k == 0 ? Contact::Cushion : Contact::Cloth, mode});
  }

  // Holds a contact whose slip vanished. The slip left over (below the vanishing threshold) is
  // removed, so that if it slips again it starts from zero rather than from noise; this shifts the
  // slip by less than the threshold.
  void hold(int k, double P, const State& y) {
    const Eigen::Vector2d u = slip(k, P, y);
    if (u.norm() > 0) contacts_[k].direction = u.normalized();
    slip0_[k] -= u;
    setMode(k, ContactMode::Stick, P);
  }

  BallVelocity ballAt(double P, const State& y) const {
    const BallVelocity change = impulseResponse(params_, P, Eigen::Vector2d(y[kAx], y[kAy]),
                                                Eigen::Vector2d(y[kBx], y[kBy]));
    BallVelocity ball = incoming_;
    ball.v += change.v;
    ball.w += change.w;
    ball.v.z() = 0;  // held on the table by construction; removes rounding
    return ball;
  }

  void sample(double P, const State& y) {
    ImpactSample s;
    s.impulse_Ns = P;
    s.ball = ballAt(P, y);
    s.normal_work_J = y[kWork];
    s.cushion_slip = slip(0, P, y);
    s.cloth_slip = slip(1, P, y);
    result_.trace.push_back(s);
  }

  // Trace samples inside an accepted step (cubic Hermite through its ends; for plots only).
  void sampleInside(double P, const State& y0, const State& r0, double h, const State& y1, const State& r1) {
    const double spacing = options_.trace_spacing_Ns;
    for (double next = (std::floor(P / spacing) + 1) * spacing; next < P + h; next += spacing) {
      const double t = (next - P) / h;
      const double h00 = (1 + 2 * t) * (1 - t) * (1 - t), h10 = t * (1 - t) * (1 - t);
      const double h01 = t * t * (3 - 2 * t), h11 = t * t * (t - 1);
      sample(next, h00 * y0 + h10 * h * r0 + h01 * y1 + h11 * h * r1);
    }
  }

  const CushionParams params_;
  const BallVelocity incoming_;
  const ExactSolverOptions options_;
  double s_ = 0, c_ = 0, M_ = 0, vy0_ = 0, velocity_scale_ = 0;
  double held_slip_ = 0;  // m/s: a slip this small has vanished (kHeldSlipFraction)
  std::array<double, 2> mu_;
  std::array<Eigen::Vector2d, 2> slip0_;  // slips at P = 0, shifted by hold()
  Eigen::Matrix4d delassus_;
  State error_scale_;
  std::array<ContactState, 2> contacts_;
  bool compressing_ = true;
  double work_target_ = 0;
  long evaluations_ = 0;
  CushionImpactResult result_;
};

CushionImpactResult ExactImpact::run() {
  const bool tracing = options_.trace_spacing_Ns > 0;
  double P = 0;
  State y = State::Zero();
  for (int k = 0; k < 2; ++k) {
    if (contacts_[k].frictionless) continue;
    const Eigen::Vector2d u = slip(k, P, y);
    if (u.norm() <= held_slip_) {
      hold(k, P, y);
    } else {
      contacts_[k].direction = u.normalized();
      setMode(k, ContactMode::Slip, P);
    }
  }
  if (tracing) sample(P, y);

  State k1 = rate(P, y);
  double h = kFirstStepFraction * M_ * vy0_;
  for (int steps = 0;; ++steps) {
    if (steps == kMaxSteps) throw std::logic_error("exact cushion solver exceeded its step budget");
    // Contact changes due here: a vanished slip is held, a held slip that has grown slips again.
    bool changed = false;
    double length = h;
    int aimed = -1;  // the contact whose vanishing slip caps this step
    for (int k = 0; k < 2; ++k) {
      if (contacts_[k].frictionless) continue;
      const Eigen::Vector2d u = slip(k, P, y);
      const double speed = u.norm();
      if (contacts_[k].mode == ContactMode::Stick) {
        if (speed > kReleaseSlipMultiple * held_slip_) {
          contacts_[k].direction = u / speed;
          setMode(k, ContactMode::Slip, P);
          changed = true;
        }
        continue;
      }
      const bool chattering = speed <= kChatterSlipMultiple * held_slip_ &&
                              speed > contacts_[k].previous_slip.norm() && canHold(k, P, y);
      if (speed <= held_slip_ || chattering) {
        hold(k, P, y);
        changed = true;
        continue;
      }
      const double shrink_rate = -slipRate(k, k1).dot(u) / speed;  // -d|u|/dP
      if (shrink_rate > 0 && (1 - contacts_[k].aim_short) * speed < length * shrink_rate) {
        length = (1 - contacts_[k].aim_short) * speed / shrink_rate;
        aimed = k;
      }
    }
    if (changed) {
      k1 = rate(P, y);
      continue;
    }
    const Step step = rungeKuttaStep(P, y, k1, length);
    if (phaseEvent(P + length, step.y) > 0) {
      if (step.error > 1) {
        if (aimed >= 0 && contacts_[aimed].aim_short < kAimShortMax) {
          // The slip turns as it vanishes: stop further short of the predicted zero.
          contacts_[aimed].aim_short = std::min(kAimShortMax, contacts_[aimed].aim_short * kAimShortGrowth);
        } else {
          h = length * stepFactor(step.error);
        }
        continue;
      }
      if (aimed >= 0) {
        contacts_[aimed].aim_short = std::max(kAimShortMin, contacts_[aimed].aim_short / kAimShortGrowth);
      } else {
        h = length * stepFactor(step.error);
      }
      for (int k = 0; k < 2; ++k) contacts_[k].previous_slip = slip(k, P, y);
      if (tracing) sampleInside(P, y, k1, length, step.y, step.rate_at_end);
      P += length;
      y = step.y;
      k1 = step.rate_at_end;
      if (tracing) sample(P, y);
      continue;
    }
    // The step crosses the end of the phase (judged before the error, which may be large only
    // because of what lies beyond it).
    Step landed;
    double landed_length = 0;
    if (!locatePhaseEnd(P, y, k1, length, step, &landed_length, &landed)) {
      h = landed_length;
      continue;
    }
    if (tracing && landed_length > 0) sampleInside(P, y, k1, landed_length, landed.y, landed.rate_at_end);
    P += landed_length;
    y = landed.y;
    if (tracing) sample(P, y);
    if (!compressing_) {
      result_.final_impulse_Ns = P;
      result_.after = ballAt(P, y);
      break;
    }
    compressing_ = false;
    result_.compression_impulse_Ns = P;
    result_.compression_work_J = y[kWork];
    work_target_ = (1 - params_.restitution * params_.restitution) * y[kWork];  // eq. 17b
    k1 = landed.rate_at_end;
  }
  result_.rhs_evaluations = evaluations_;
  return std::move(result_);
}

}  // namespace

CushionImpactResult solveCushionImpactExact(const CushionParams& params, const BallVelocity& incoming,
                                            const ExactSolverOptions& options) {
  validateCushionParams(params);
  validateIncomingBall(incoming);
  if (!(options.tolerance >= 1e-15 && options.tolerance <= 1e-2)) {
    throw std::invalid_argument("exact solver tolerance = " + std::to_string(options.tolerance) +
                                " is not allowed: it must lie in [1e-15, 1e-2]");
  }
  if (!(options.trace_spacing_Ns >= 0) || !std::isfinite(options.trace_spacing_Ns)) {
    throw std::invalid_argument("trace spacing = " + std::to_string(options.trace_spacing_Ns) +
                                " N s is not allowed: it must be a finite number >= 0");
  }
  return ExactImpact(params, incoming, options).run();
}

}  // namespace baize::physics
