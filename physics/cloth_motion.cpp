#include "physics/cloth_motion.h"

#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

#include "physics/value_text.h"

namespace baize::physics {
namespace {

// A sequence of states only moves forward (sliding, rolling, spinning, stationary), so a lone ball
// changes state at most three times; the loop in advance() allows one more as a margin.
constexpr int kMaxStateChanges = 4;

// sqrt is correctly rounded on every IEEE machine, std::hypot is not: same input, same output.
double length(const Eigen::Vector2d& a) { return std::sqrt(a.x() * a.x() + a.y() * a.y()); }

// z x a for a vector a in the table plane.
Eigen::Vector2d zCross(const Eigen::Vector2d& a) { return {-a.y(), a.x()}; }

Eigen::Vector2d slipOf(const ClothParams& params, const BallState& ball) {
  const double r = params.radius_m;
  return {ball.velocity.x() - r * ball.angular_velocity.y(),
          ball.velocity.y() + r * ball.angular_velocity.x()};
}

MotionState classify(const ClothParams& params, const BallState& ball) {
  if (length(slipOf(params, ball)) > kSlipSpeedEpsilon_mps) return MotionState::Sliding;
  if (length(ball.velocity.head<2>()) > kSpeedEpsilon_mps) return MotionState::Rolling;
  if (std::abs(ball.angular_velocity.z()) > kSpinEpsilon_radps) return MotionState::Spinning;
  return MotionState::Stationary;
}

double slidingDeceleration(const ClothParams& p) { return p.sliding_friction * p.gravity_mps2; }
double rollingDeceleration(const ClothParams& p) { return p.rolling_friction * p.gravity_mps2; }

double durationOf(const ClothParams& params, const BallState& ball, MotionState state) {
  switch (state) {
    case MotionState::Sliding:
      return 2 * length(slipOf(params, ball)) / (7 * slidingDeceleration(params));
    case MotionState::Rolling:
      return length(ball.velocity.head<2>()) / rollingDeceleration(params);
    case MotionState::Spinning:
      return std::abs(ball.angular_velocity.z()) / spinDeceleration(params);
    case MotionState::Stationary:
      break;
  }
  return std::numeric_limits<double>::infinity();
}

PositionQuadratic quadraticOf(const ClothParams& params, const BallState& ball, MotionState state) {
  PositionQuadratic r;
  r.constant_m = ball.position;
  if (state == MotionState::Sliding) {
    const Eigen::Vector2d slip = slipOf(params, ball);
    r.linear_mps = ball.velocity.head<2>();
    r.quadratic_mps2 = (-0.5 * slidingDeceleration(params) / length(slip)) * slip;
  } else if (state == MotionState::Rolling) {
    const Eigen::Vector2d v = ball.velocity.head<2>();
    r.linear_mps = v;
    r.quadratic_mps2 = (-0.5 * rollingDeceleration(params) / length(v)) * v;
  }
  return r;
}

// w_z after dt: its magnitude falls linearly and stays at 0 once there.
double spinAfter(const ClothParams& params, double spin_radps, double dt_s) {
  const double magnitude = std::abs(spin_radps) - spinDeceleration(params) * dt_s;
  return magnitude > 0 ? std::copysign(magnitude, spin_radps) : 0.0;
}

BallState withinState(const ClothParams& params, const BallState& ball, MotionState state,
                      double duration_s, double dt_s) {
  const bool at_end = dt_s == duration_s;
  BallState next;
  next.position = quadraticOf(params, ball, state).at(dt_s);
  Eigen::Vector2d v = Eigen::Vector2d::Zero();
  Eigen::Vector2d w_xy = Eigen::Vector2d::Zero();
  switch (state) {
    case MotionState::Sliding: {
      const Eigen::Vector2d v0 = ball.velocity.head<2>();
      if (at_end) {
        // v = (5/7) v0 + (2/7) R w0 x z, then locked to rolling: no drift from the slip's rounding.
        const Eigen::Vector2d w0_cross_z(ball.angular_velocity.y(), -ball.angular_velocity.x());
        v = (5.0 / 7.0) * v0 + (2.0 / 7.0) * params.radius_m * w0_cross_z;
        w_xy = zCross(v) / params.radius_m;
      } else {
        const Eigen::Vector2d slip = slipOf(params, ball);
        const Eigen::Vector2d slip_direction = slip / length(slip);
        const double a = slidingDeceleration(params);
        v = v0 - (a * dt_s) * slip_direction;
        w_xy = ball.angular_velocity.head<2>() +
               (2.5 * a / params.radius_m * dt_s) * zCross(slip_direction);
      }
      break;
    }
    case MotionState::Rolling:
      if (!at_end) {
        const Eigen::Vector2d v0 = ball.velocity.head<2>();
        v = v0 - (rollingDeceleration(params) * dt_s / length(v0)) * v0;
        w_xy = zCross(v) / params.radius_m;  // rolling: u = v + R z x w = 0
      }
      break;
    case MotionState::Spinning:
    case MotionState::Stationary:
      break;  // the centre stands still and w_xy = 0 (within the thresholds; now exactly)
  }
  next.velocity = {v.x(), v.y(), 0.0};
  const double spin = at_end && state == MotionState::Spinning
                          ? 0.0
                          : spinAfter(params, ball.angular_velocity.z(), dt_s);
  next.angular_velocity = {w_xy.x(), w_xy.y(), spin};
  return next;
}

void validateInputs(const ClothParams& params, const BallState& ball) {
  validateClothParams(params);
  validateBallState(ball);
}

}  // namespace

ClothParams poolCloth() { return ClothParams{}; }

ClothParams snookerCloth() {
  ClothParams p;
  p.radius_m = 0.02625;
  p.sliding_friction = 0.212;
  p.rolling_friction = 0.0128;
  p.spinning_friction = 22.0 * 2.0 * p.radius_m / (5.0 * p.gravity_mps2);
  return p;
}

void validateClothParams(const ClothParams& p) {
  requireFinite("ball radius R (m)", p.radius_m);
  requireFinite("gravity g (m/s^2)", p.gravity_mps2);
  requireFinite("cloth sliding friction mu_s", p.sliding_friction);
  requireFinite("cloth rolling friction mu_r", p.rolling_friction);
  requireFinite("cloth spinning friction mu_sp", p.spinning_friction);
  if (!(p.radius_m > 0)) rejectValue("ball radius R (m)", p.radius_m, "it must be > 0");
  if (!(p.gravity_mps2 > 0)) rejectValue("gravity g (m/s^2)", p.gravity_mps2, "it must be > 0");
  // Zero friction would make a state last forever (and one near zero longer than event times can
  // be solved for); 1 and above is not cloth. The text is built only on a refusal: this check runs
  // on every call of the motion functions.
  const auto low = [] { return valueText(kMinClothFriction); };
  if (!(p.sliding_friction >= kMinClothFriction && p.sliding_friction < 1)) {
    rejectValue("cloth sliding friction mu_s", p.sliding_friction,
                "it must lie in [" + low() + ", 1)");
  }
  if (!(p.rolling_friction >= kMinClothFriction && p.rolling_friction < p.sliding_friction)) {
    rejectValue("cloth rolling friction mu_r", p.rolling_friction,
                "it must lie in [" + low() + ", mu_s) = [" + low() + ", " +
                    valueText(p.sliding_friction) +
                    "): rolling resistance is far below sliding friction");
  }
  if (!(p.spinning_friction >= kMinClothFriction && p.spinning_friction < 1)) {
    rejectValue("cloth spinning friction mu_sp", p.spinning_friction,
                "it must lie in [" + low() + ", 1)");
  }
}

double spinDeceleration(const ClothParams& p) {
  return 2.5 * p.spinning_friction * p.gravity_mps2 / p.radius_m;
}

void validateBallState(const BallState& ball) {
  static const char* const position[] = {"ball position x (m)", "ball position y (m)"};
  static const char* const velocity[] = {"ball velocity v_x (m/s)", "ball velocity v_y (m/s)",
                                         "ball velocity v_z (m/s)"};
  static const char* const spin[] = {"ball angular velocity w_x (rad/s)",
                                     "ball angular velocity w_y (rad/s)",
                                     "ball angular velocity w_z (rad/s)"};
  for (int i = 0; i < 2; ++i) requireFinite(position[i], ball.position[i]);
  for (int i = 0; i < 3; ++i) {
    requireFinite(velocity[i], ball.velocity[i]);
    requireFinite(spin[i], ball.angular_velocity[i]);
  }
  if (ball.velocity.z() != 0) {
    rejectValue("ball velocity v_z (m/s)", ball.velocity.z(), "a ball on the cloth has v_z = 0");
  }
}

const char* motionStateName(MotionState state) {
  switch (state) {
    case MotionState::Sliding:
      return "sliding";
    case MotionState::Rolling:
      return "rolling";
    case MotionState::Spinning:
      return "spinning";
    case MotionState::Stationary:
      return "stationary";
  }
  return "unknown";
}

Eigen::Vector3d contactSlip(const ClothParams& params, const BallState& ball) {
  const Eigen::Vector2d u = slipOf(params, ball);
  return {u.x(), u.y(), 0.0};
}

MotionState motionState(const ClothParams& params, const BallState& ball) {
  validateInputs(params, ball);
  return classify(params, ball);
}

double timeToStateChange(const ClothParams& params, const BallState& ball) {
  validateInputs(params, ball);
  return durationOf(params, ball, classify(params, ball));
}

PositionQuadratic positionQuadratic(const ClothParams& params, const BallState& ball) {
  validateInputs(params, ball);
  return quadraticOf(params, ball, classify(params, ball));
}

CurrentMotion currentMotion(const ClothParams& params, const BallState& ball) {
  validateInputs(params, ball);
  const MotionState state = classify(params, ball);
  return {state, durationOf(params, ball, state), quadraticOf(params, ball, state)};
}

BallState advanceWithinKnownState(const ClothParams& params, const BallState& ball,
                                  MotionState state, double duration_s, double dt_s) {
  if (!(dt_s >= 0 && dt_s <= duration_s && std::isfinite(dt_s))) {
    rejectValue("time step dt (s)", dt_s,
                std::string("it must lie in [0, ") + valueText(duration_s) +
                    "], the time the ball stays " + motionStateName(state));
  }
  return withinState(params, ball, state, duration_s, dt_s);
}

BallState advanceWithinState(const ClothParams& params, const BallState& ball, double dt_s) {
  validateInputs(params, ball);
  const MotionState state = classify(params, ball);
  return advanceWithinKnownState(params, ball, state, durationOf(params, ball, state), dt_s);
}

BallState advance(const ClothParams& params, const BallState& ball, double dt_s) {
  validateInputs(params, ball);
  if (!(dt_s >= 0 && std::isfinite(dt_s))) {
    rejectValue("time step dt (s)", dt_s, "it must be a finite number >= 0");
  }
  BallState current = ball;
  double remaining = dt_s;
  for (int change = 0; change <= kMaxStateChanges; ++change) {
    const MotionState state = classify(params, current);
    const double duration = durationOf(params, current, state);
    if (remaining < duration) return withinState(params, current, state, duration, remaining);
    current = withinState(params, current, state, duration, duration);
    remaining -= duration;  // >= 0: remaining >= duration
  }
  return current;  // unreachable: a stationary state lasts forever
}

double timeToRest(const ClothParams& params, const BallState& ball) {
  validateInputs(params, ball);
  BallState current = ball;
  double elapsed = 0;
  for (int change = 0; change <= kMaxStateChanges; ++change) {
    const MotionState state = classify(params, current);
    if (state == MotionState::Stationary) return elapsed;
    const double duration = durationOf(params, current, state);
    current = withinState(params, current, state, duration, duration);
    elapsed += duration;
  }
  return elapsed;  // unreachable: every state but rest ends within kMaxStateChanges
}

double specificKineticEnergy(const ClothParams& params, const BallState& ball) {
  const double r = params.radius_m;
  return 0.5 * ball.velocity.squaredNorm() + 0.2 * r * r * ball.angular_velocity.squaredNorm();
}

}  // namespace baize::physics
