// A ball's motion on the cloth between events, in closed form (physics-notes section 2).
//
// Frame: the table frame, x and y on the table plane, z up. The ball touches the cloth at C, R
// below its centre. Units: SI (m, s, rad, m/s, rad/s, J/kg).
//
// The contact slip is u = v + R z x w = (v_x - R w_y, v_y + R w_x, 0): the velocity of the ball's
// surface at C. Sliding friction -mu_s m g u_hat acts at C, so
//   dv/dt = -mu_s g u_hat,   dw_xy/dt = (5 mu_s g / (2R)) z x u_hat    (torque (-R z) x F over
//   (2/5) m R^2)
// which makes du/dt = -(7/2) mu_s g u_hat: the slip keeps its direction and shrinks linearly,
// ending at t = 2|u0| / (7 mu_s g) with v = (5/7) v0 + (2/7) R w0 x z. A rolling ball (u = 0) slows
// at mu_r g with w_xy = z x v / R locked to v. Independently, in every state, |w_z| falls at 5
// mu_sp g / (2R) (the pivoting contact patch) until it reaches 0. Positions are quadratics in t.
//
// Pocketed balls are the engine's business; this module knows only the cloth.
#pragma once

#include <Eigen/Core>

namespace baize::physics {

// Cloth and ball constants of a table; they never change during a shot. Defaults: pool.
struct ClothParams {
  double radius_m = 0.028575;      // R: pool ball, 57.15 mm diameter
  double gravity_mps2 = 9.81;      // g
  double sliding_friction = 0.2;   // mu_s, ball sliding on cloth (pool cloth 0.15-0.4)
  double rolling_friction = 0.01;  // mu_r: a rolling ball slows at mu_r g (pool 0.005-0.015)
  // mu_sp: |w_z| falls at 5 mu_sp g / (2R). Chosen so that this is 10 rad/s^2 (pool: 5-15 rad/s^2).
  double spinning_friction = 10.0 * 2.0 * 0.028575 / (5.0 * 9.81);
};

// Pool cloth (the defaults above).
ClothParams poolCloth();

// Snooker cloth: R = 26.25 mm, mu_s = 0.212, mu_r = 0.0128 (rolling deceleration 0.1256 m/s^2,
// measured 0.124-0.126), mu_sp so that spin falls at 22 rad/s^2.
ClothParams snookerCloth();

// The smallest cloth friction coefficient accepted: a ball at the largest speed accepted (1e3 m/s)
// then stops within about 1e8 s, well inside the range the root finder solves event times in;
// 1e-300 put a state's end at 1e300 s, beyond it.
inline constexpr double kMinClothFriction = 1e-6;

// Throws std::invalid_argument naming the value and the allowed range unless every parameter is
// finite, R and g are > 0, kMinClothFriction <= mu_s < 1, kMinClothFriction <= mu_r < mu_s
// (rolling resistance below sliding friction) and kMinClothFriction <= mu_sp < 1.
void validateClothParams(const ClothParams& params);

// Deceleration of |w_z|, rad/s^2: 5 mu_sp g / (2R).
double spinDeceleration(const ClothParams& params);

// A ball on the cloth. The velocity is 3D for the impact models; its z component is 0 on the cloth.
struct BallState {
  Eigen::Vector2d position = Eigen::Vector2d::Zero();  // centre (x, y) on the table plane, m
  Eigen::Vector3d velocity = Eigen::Vector3d::Zero();  // centre velocity, m/s; z = 0
  Eigen::Vector3d angular_velocity = Eigen::Vector3d::Zero();  // rad/s
};

// Throws std::invalid_argument unless every component is finite and velocity.z is 0.
void validateBallState(const BallState& ball);

enum class MotionState {
  Sliding,     // the contact slips: |u| > kSlipSpeedEpsilon_mps
  Rolling,     // no slip, the centre moves: |v| > kSpeedEpsilon_mps
  Spinning,    // only w_z: |w_z| > kSpinEpsilon_radps
  Stationary,  // nothing moves
};

const char* motionStateName(MotionState state);

// Classification thresholds. Every transition is computed exactly and the state is then set exactly
// (rolling with w_xy = z x v / R; v = 0 and w_xy = 0 when it stops; w_z = 0), so the thresholds
// only absorb rounding: a few ulps of speeds up to ~20 m/s, about 1e-14 m/s. They sit five orders
// above that, and low enough that misjudging a state changes nothing visible: a slip of 1e-9 m/s
// ends within 2e-9 / (7 mu_s g) < 1e-9 s; a speed of 1e-9 m/s stops within 1e-9 / (mu_r g), under
// 1e-6 s, after under 1e-15 m; a spin of 1e-9 rad/s stops within 1e-9 s.
// |u| at or below this: not sliding.
inline constexpr double kSlipSpeedEpsilon_mps = 1e-9;
// |v| at or below this (and not sliding): not rolling; the centre is set at rest.
inline constexpr double kSpeedEpsilon_mps = 1e-9;
// |w_z| at or below this (and nothing else moving): stationary.
inline constexpr double kSpinEpsilon_radps = 1e-9;

// The functions below that take a ball check the parameters and the ball first
// (validateClothParams, validateBallState), except contactSlip and specificKineticEnergy, which
// only compute.

// Contact slip u = v + R z x w, m/s (z component 0).
Eigen::Vector3d contactSlip(const ClothParams& params, const BallState& ball);

MotionState motionState(const ClothParams& params, const BallState& ball);

// Time until the motion state changes, s: sliding ends at 2|u0| / (7 mu_s g), rolling at
// |v0| / (mu_r g), spinning at |w_z0| / spinDeceleration. +infinity when stationary. (Spin running
// out while the ball slides or rolls is not a change of state: w_z is clamped at 0 in closed form.)
double timeToStateChange(const ClothParams& params, const BallState& ball);

// Position during the current state: r(t) = constant + linear t + quadratic t^2 for t in
// [0, timeToStateChange], in m, m/s and m/s^2; each a 2D vector (x, y). The engine builds its
// contact polynomials from these.
struct PositionQuadratic {
  Eigen::Vector2d constant_m = Eigen::Vector2d::Zero();
  Eigen::Vector2d linear_mps = Eigen::Vector2d::Zero();
  Eigen::Vector2d quadratic_mps2 = Eigen::Vector2d::Zero();

  Eigen::Vector2d at(double t_s) const {
    return constant_m + (linear_mps + quadratic_mps2 * t_s) * t_s;
  }
};

PositionQuadratic positionQuadratic(const ClothParams& params, const BallState& ball);

// A ball's motion until its state changes, from one check of the parameters and the ball: what
// motionState, timeToStateChange and positionQuadratic give, for a caller that needs all three.
struct CurrentMotion {
  MotionState state = MotionState::Stationary;
  double duration_s = 0;  // timeToStateChange
  PositionQuadratic path;
};
CurrentMotion currentMotion(const ClothParams& params, const BallState& ball);

// advanceWithinState for a ball whose motion state and its duration the caller has from
// currentMotion() on this ball (they are used as given: the ball is not checked again).
BallState advanceWithinKnownState(const ClothParams& params, const BallState& ball,
                                  MotionState state, double duration_s, double dt_s);

// The state dt_s later, for 0 <= dt_s <= timeToStateChange (closed form). At dt_s equal to that
// time the next state is set exactly: rolling after sliding, v = 0 and w_xy = 0 after rolling,
// w_z = 0 after spinning. A spinning or stationary ball has v and w_xy set to exactly 0.
// Throws std::invalid_argument for dt_s outside that range.
BallState advanceWithinState(const ClothParams& params, const BallState& ball, double dt_s);

// The state dt_s >= 0 later, through any number of state changes: the trajectory of a lone ball.
// Throws std::invalid_argument for a negative or non-finite dt_s.
BallState advance(const ClothParams& params, const BallState& ball, double dt_s);

// Time until a lone ball comes to rest, s, through its remaining state changes (0 for a ball at
// rest): the sum of their durations.
double timeToRest(const ClothParams& params, const BallState& ball);

// Kinetic energy per unit mass, J/kg: v^2 / 2 + (1/5) R^2 |w|^2 (a solid ball, I = (2/5) m R^2).
double specificKineticEnergy(const ClothParams& params, const BallState& ball);

}  // namespace baize::physics
