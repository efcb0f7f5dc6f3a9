// Impact of two balls of equal radius that touch on the table, resolved as one instantaneous event.
//
// World frame, z up; both balls rest on the slate, so their centre velocities are horizontal
// (v.z = 0) and the line of centres n (unit, from ball 1 to ball 2) is horizontal. Units: SI
// (kg, m, s, rad, N s, J). Ball velocities reuse BallVelocity {v, w} from cushion_model.h.
//
// Two models sit behind one entry, resolveBallBallImpact(), chosen by BallBallParams::model:
//
// * FrictionalInelastic (default; Alciatore's model, "TP A-14" style). One algebraic step: the
//   normal relative velocity reverses with Newton's restitution e, and a friction impulse of at
//   most mu * (normal impulse) opposes the slip of the contact points (including spin), capped at
//   the value that makes that slip zero. mu is Alciatore's fit of measured throw,
//   mu(u) = a + b exp(-c u) with u the slip speed at the contact (m/s), or a constant.
//
// * Mathavan2014 (Mathavan, Jackson & Parkin 2014, Sports Engineering 17:227-237). The method of
//   the Mathavan 2010 cushion model applied to the ball-ball contact: integration in P, the normal
//   impulse at the ball-ball contact, with Coulomb friction (mu_b) at that contact and at each
//   ball's cloth contact (mu_s); compression ends when the normal relative velocity is zero;
//   restitution ends by Stronge's energetic criterion (the normal work returned is e^2 of the work
//   absorbed).
//
// The vertical friction impulse (both models). The contact slip has a vertical part, R (w1 + w2) x
// n along z, whenever the balls carry topspin or backspin; friction opposes it, so it pushes one
// ball down into the cloth and lifts the other by the same impulse. Both models keep that vertical
// friction (it changes the balls' spins about the horizontal tangent; that is how follow reduces
// throw) and keep both balls on the table: the vertical velocity it would give is removed (v.z = 0
// after the impact) and reported in discarded_vertical_velocity_mps. For the ball pressed down the
// table absorbs it; the ball pushed up would hop by (v_z)^2 / 2g, well under a millimetre for the
// friction coefficients here, which this event model ignores. Only the table's reaction on the ball
// pressed down is a real normal force, so only that ball feels cloth friction in Mathavan2014
// (see ball_ball_impact.cpp for the derivation).
//
// Policy for a contact that is not approaching ((v1 - v2) . n <= 0: separating or grazing): it is a
// caller error and throws std::invalid_argument. The event engine must only resolve contacts whose
// approachSpeed() is positive; a touching but separating pair needs no impulse.
#pragma once

#include <Eigen/Core>
#include <optional>

#include "physics/cushion_model.h"  // BallVelocity

namespace baize::physics {

enum class BallBallModel {
  FrictionalInelastic,  // Alciatore: one algebraic step (default)
  Mathavan2014,         // integrated in the normal impulse with cloth friction
};

enum class BallBallFrictionLaw {
  AlciatoreFit,  // mu(u) = a + b exp(-c u), u the contact slip speed in m/s (default)
  Constant,      // mu = constant_friction
};

// Constants of one impact. Defaults: the frictional inelastic model with pool balls (57.15 mm,
// 0.170 kg, e = 0.95). snookerMathavan2014Params() gives the Mathavan model with the paper's
// values.
struct BallBallParams {
  BallBallModel model = BallBallModel::FrictionalInelastic;
  double radius_m = 0.028575;  // both balls (WPA pool ball, 57.15 mm diameter)
  double mass1_kg = 0.170;     // ball 1
  double mass2_kg = 0.170;     // ball 2
  double restitution = 0.95;  // e in [0, 1]: Newton's (FrictionalInelastic) or energetic (Mathavan)

  // FrictionalInelastic only.
  BallBallFrictionLaw friction_law = BallBallFrictionLaw::AlciatoreFit;
  double friction_fit_a = 9.951e-3;       // mu at high slip speed
  double friction_fit_b = 0.108;          // extra mu at zero slip speed
  double friction_fit_c_s_per_m = 1.088;  // decay rate of mu with slip speed, s/m
  double constant_friction = 0.06;        // mu for BallBallFrictionLaw::Constant

  // Mathavan2014 only.
  double ball_friction = 0.05;    // mu_b, ball on ball
  double cloth_friction = 0.212;  // mu_s, ball on cloth
  // Allowed local error of one integration step (adaptive Dormand-Prince 8(5,3), dop853.h, its
  // error norm taken over the components), relative to the largest speed in the problem for
  // velocities and impulses, and to the approach speed for the normal approach and the normal work
  // (which decide where the impact ends). At the default the outgoing velocities agree with a
  // converged (1e-14) solution within 5e-11 of the approach speed (worst of 4000 random impacts:
  // 3.4e-11), at about 140 rate evaluations per impact (at most about 950, when a loaded cloth
  // slip swings round close to zero).
  double tolerance = 1e-11;
  // > 0: use the paper's scheme instead, explicit Euler in P with this many increments of
  // (1 + e) mu* v_n0 / fixed_steps (mu* = m1 m2 / (m1 + m2)); first order, kept as a reference.
  int fixed_steps = 0;
};

// The Mathavan, Jackson & Parkin (2014) model with their snooker values: R = 26.25 mm,
// M = 0.1406 kg, e = 0.89, mu_b = 0.05, mu_s = 0.212.
BallBallParams snookerMathavan2014Params();

// Throws std::invalid_argument naming the value and the allowed range.
void validateBallBallParams(const BallBallParams& params);

// (v1 - v2) . n, m/s: positive while the balls approach along the line of centres n (1 -> 2).
double approachSpeed(const BallVelocity& ball1, const BallVelocity& ball2,
                     const Eigen::Vector3d& line_of_centres);

// Throws std::invalid_argument unless every component is finite (speeds and spins within
// kMaxBallSpeed_mps and kMaxBallSpin_radps of cushion_model.h), both v.z are 0, n is a horizontal
// unit vector (within kLineOfCentresTolerance) and the balls approach (approachSpeed > 0). The
// models then use n projected on the table plane and renormalised.
void validateBallBallContact(const BallVelocity& ball1, const BallVelocity& ball2,
                             const Eigen::Vector3d& line_of_centres);

// How far |n| may be from 1, and n.z from 0 (dimensionless): n comes from a normalised difference
// of centres, whose error is a few ulp; anything larger means the caller passed the wrong vector.
constexpr double kLineOfCentresTolerance = 1e-9;

// Alciatore's friction law (or the constant), for a contact slip speed in m/s.
double ballBallFriction(const BallBallParams& params, double slip_speed_mps);

// Slip velocity of ball 1's surface relative to ball 2's at the contact point (m/s, world frame):
// (v1 + w1 x R n) - (v2 + w2 x (-R n)), minus its normal part. Horizontal part along t = z x n,
// vertical part -R (w1 + w2) . t.
Eigen::Vector3d contactSlip(const BallBallParams& params, const BallVelocity& ball1,
                            const BallVelocity& ball2, const Eigen::Vector3d& line_of_centres);

struct BallBallImpactResult {
  BallVelocity ball1;  // after the impact, world frame, v.z = 0
  BallVelocity ball2;
  double normal_impulse_Ns = 0;  // total normal impulse at the ball-ball contact (on ball 2, +n)
  double compression_impulse_Ns = 0;  // normal impulse when compression ended
  double compression_work_J = 0;      // work the normal force absorbed during compression
  // Friction impulse at the ball-ball contact acting on ball 1 (ball 2 gets the opposite), world
  // frame, tangent to the contact: horizontal part along t, vertical part along z.
  Eigen::Vector3d contact_friction_impulse_Ns = Eigen::Vector3d::Zero();
  // Normal impulse the table gives each ball to hold it down against the vertical friction (>= 0).
  // Only Mathavan2014 applies cloth friction with it.
  double table_normal_impulse_Ns[2] = {0, 0};
  // Vertical velocity (m/s, + up) the vertical friction impulse would give each ball as a free
  // body. The output has v.z = 0: the table absorbs a downward one, an upward one is dropped.
  double discarded_vertical_velocity_mps[2] = {0, 0};
  // Normal impulse at which the ball-ball slip vanished, after which the contact rolls (no friction
  // impulse is needed to keep it rolling). Empty when the balls slip throughout.
  std::optional<double> contact_rolling_from_impulse_Ns;
  long rhs_evaluations = 0;  // Mathavan2014 cost: evaluations of the rates d(state)/dP
};

// Resolves one impact. Throws std::invalid_argument on invalid parameters or contact state.
BallBallImpactResult resolveBallBallImpact(const BallBallParams& params, const BallVelocity& ball1,
                                           const BallVelocity& ball2,
                                           const Eigen::Vector3d& line_of_centres);

}  // namespace baize::physics
