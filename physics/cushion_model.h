// The ball-cushion impact model of Mathavan, Jackson & Parkin (2010): a rigid cushion nose touching
// the ball at I above its equator and the cloth touching it at C below, both with Coulomb friction,
// resolved in impulse space (the independent variable P is the normal impulse at I).
//
// Frame (the "local cushion frame"): x along the cushion, y horizontal and into the cushion (an
// incoming ball has v.y > 0), z up. Units: SI (kg, m, s, rad, N s, J).
//
// This file holds what both solvers share: parameters, their validation, the incoming state, the
// slip velocities at the two contacts and the result record. The solvers are in
// cushion_paper_solver.h (the paper's Euler scheme) and cushion_exact_solver.h (event-located).
#pragma once

#include <Eigen/Core>
#include <optional>
#include <string>
#include <vector>

#include "physics/cushion_restitution_speed.h"

namespace baize::physics {

// Constants of one impact; they never change while it runs. Defaults: the Mathavan 2010 paper's
// snooker values.
struct CushionParams {
  double mass_kg = 0.1406;
  double radius_m = 0.02625;
  double contact_height_m =
      0.02625 * 7.0 / 5.0;         // nose height above the slate; h = 7R/5 in the paper
  double restitution = 0.98;       // e_e, energetic coefficient (Stronge), in [1e-6, 1]
  double cushion_friction = 0.14;  // mu_w, ball on cushion nose
  double cloth_friction = 0.212;   // mu_s, ball on cloth
  // Given: e_e above is e_0, and falls with the normal incident speed above a knee
  // (cushion_restitution_speed.h). None, the default: constant, as in the paper.
  std::optional<RestitutionSpeedDependence> restitution_speed_dependence;
};

// The ball radii the impact models accept, m. Cue-sport balls are 47.6 to 68 mm; the models are
// scale-free, but their adaptive solvers measure errors and events against R |w| and v together,
// and radii hundreds of orders of magnitude off (found by fuzzing: 1e-200 m, 1e300 m) exhaust
// their step budgets. Three decades either side of real balls leave every physical use open.
inline constexpr double kMinBallRadius_m = 1e-3;
inline constexpr double kMaxBallRadius_m = 1.0;
// The steepest cushion nose accepted: sin theta = h/R - 1 at most sin 80 deg. Near 90 deg the nose
// sits on top of the ball, the normal impulse is almost vertical and barely compresses the contact,
// and the solvers' step counts grow like 1/cos theta without bound (found by fuzzing: the paper
// scheme at h = 1.99999 R). Real cushions sit near 15-25 deg.
inline constexpr double kMaxNoseSinTheta = 0.98480775301220806;  // sin(80 deg)
// The least share of the frictionless push-back rate (cos theta) the cushion must keep whatever
// the slip directions: cos th - mu_w sin th - mu_s (sin th + mu_w cos th) >= this x cos th. Near 0
// friction nearly holds the ball against the cushion, restitution needs an impulse that grows
// without bound, and the exact solver exhausted its step budget (found by fuzzing: mu_w = mu_s =
// 1/3 at sin theta = 0.8, within 1e-6 of the bound; at 1e-3 it took 8800 evaluations, at 1e-2
// 2000). Real tables keep about 0.8.
inline constexpr double kMinNormalRateShare = 1e-2;
// The least energetic restitution accepted. Restitution ends where the normal work has fallen
// from W_c to (1 - e_e^2) W_c, and the exact solver locates that to 1e-4 of its tolerance times
// W_c: at the default tolerance an e_e below about 5e-8 (e_e^2 W_c under that residual) ended
// restitution at once and lost the rebound, -e_e v_y0, which is then more than the 1e-9 V0 the
// solver promises. Real cushions lie near 0.7 to 0.98. At 1e-6 the rebound is kept at tolerances
// up to about 1e-8; above them the 1e-6 V0 it could lose lies within those tolerances' errors.
inline constexpr double kMinRestitution = 1e-6;
// The ball masses they accept, kg: cue-sport balls weigh 0.1 to 0.3 kg; subnormal masses (found by
// fuzzing: 1e-309 kg) stalled the ball-ball integration the same way.
inline constexpr double kMinBallMass_kg = 1e-3;
inline constexpr double kMaxBallMass_kg = 1e3;

// sin(theta) = (h - R) / R: theta is the angle of the contact normal at I above the horizontal.
double contactSinTheta(const CushionParams& params);

// Throws std::invalid_argument naming the value and the allowed range when the parameters are not
// physical or leave the model (for example mu_w >= tan(theta), where the table reaction turns
// negative).
void validateCushionParams(const CushionParams& params);

// Ball velocity and angular velocity in the local cushion frame.
struct BallVelocity {
  Eigen::Vector3d v = Eigen::Vector3d::Zero();  // centre velocity, m/s
  Eigen::Vector3d w = Eigen::Vector3d::Zero();  // angular velocity, rad/s
};

// Whether the impact's outcome scales with the incoming ball: scaling its velocity and spin by
// lambda scales every outgoing one by lambda (the paper's model, e_e constant). A solver or table
// that relies on it (the table of rolling impacts, cushion_rolling_surface.h) may answer only
// when this holds; otherwise the impact goes to the exact solver. False when the restitution
// falls with speed.
// Inline: the default cushion path asks it at every impact.
inline bool impactScalesWithSpeed(const CushionParams& params) {
  return !params.restitution_speed_dependence ||
         params.restitution_speed_dependence->falloff_exponent == 0;
}

// The parameters one impact is solved with: with a speed dependence, e_e at the ball's normal
// incident speed v_y (never below kMinRestitution) and no dependence left; else `params`.
CushionParams paramsAtIncidentSpeed(const CushionParams& params, const BallVelocity& incoming);

// The incoming ball of the paper's Fig. 2, with the spins assigned the physically right way round
// (the Mathavan 2010 text prints them swapped): v = V0 (cos a, sin a, 0), w = (-wT sin a, wT cos a,
// wS). alpha is measured from the cushion line (pi/2 is head-on); topspin wT = V0/R is natural
// roll; positive sidespin is counter-clockwise seen from above.
BallVelocity incomingBall(double speed_mps, double alpha_rad, double topspin_radps,
                          double sidespin_radps);

// Bounds on the incoming velocity components, m/s and rad/s. Cue balls leave the tip below 20 m/s
// with spins below about 500 rad/s; the bounds are far above that and far below where the solvers'
// squared speeds and scales overflow (found by fuzzing: v_y = 1.8e308 m/s exhausted the exact
// solver's step budget).
inline constexpr double kMaxBallSpeed_mps = 1e3;
inline constexpr double kMaxBallSpin_radps = 1e6;
static_assert(kMaxKneeSpeed_mps == kMaxBallSpeed_mps, "a knee above every ball is never reached");
// The smallest normal approach speed an impact model resolves, m/s. Approach speeds near the
// subnormal range (found by fuzzing: 5e-324 m/s at a cushion, 1e-311 m/s between balls) make the
// impulse scales and first steps underflow to zero, and the solvers stall. The event loop never
// comes near it: its speeds are 0 or at least kSpeedEpsilon_mps (1e-9), so approach speeds are 0
// or above about 1e-25 m/s (rounding of a 1e-9 m/s speed).
inline constexpr double kMinApproachSpeed_mps = 1e-100;

// Throws std::invalid_argument unless every component is finite and within the bounds above, v.z
// is 0 (the ball is on the table) and v.y >= kMinApproachSpeed_mps (the ball moves into the
// cushion).
void validateIncomingBall(const BallVelocity& ball);

// Slip velocity of the ball's surface at the cushion contact I, in the tangent basis (x, Y') with
// Y' = (0, -sin th, cos th): (v_x + R(w_y sin th - w_z cos th), -v_y sin th + R w_x).
Eigen::Vector2d cushionSlip(const CushionParams& params, const BallVelocity& ball);

// Slip velocity at the cloth contact C, in (x, y): (v_x - R w_y, v_y + R w_x).
Eigen::Vector2d clothSlip(const CushionParams& params, const BallVelocity& ball);

// Change of the ball's velocities when the normal impulse at I grows by `normal_impulse_Ns` while
// friction impulses -cushion_friction_impulse (in the basis x, Y' at I) and -cloth_friction_impulse
// (in x, y at C) act, the table's normal impulse being whatever keeps v_z at 0 (eq. 3d). Linear in
// all three; with the friction impulses written as mu_w (cos Phi, sin Phi) dP and
// mu_s (sin th + mu_w sin Phi cos th) (cos Phi', sin Phi') dP it gives eq. 14a and its five
// partners.
BallVelocity impulseResponse(const CushionParams& params, double normal_impulse_Ns,
                             const Eigen::Vector2d& cushion_friction_impulse_Ns,
                             const Eigen::Vector2d& cloth_friction_impulse_Ns);

// Kinetic energy of the ball (translation plus rotation of a solid sphere), J.
double kineticEnergy(const CushionParams& params, const BallVelocity& ball);

enum class Contact { Cushion, Cloth };  // I and C
enum class ContactMode { Slip, Stick };

// From impulse_Ns on, `contact` is in `mode`. The first two entries give the modes at P = 0.
struct ContactChange {
  double impulse_Ns = 0;
  Contact contact = Contact::Cushion;
  ContactMode mode = ContactMode::Slip;
};

// The ball's state part way through the impact (for slip-against-impulse plots).
struct ImpactSample {
  double impulse_Ns = 0;  // P
  BallVelocity ball;
  double normal_work_J = 0;  // W(P): work of the normal impulse at I, positive while compressing
  Eigen::Vector2d cushion_slip = Eigen::Vector2d::Zero();  // (s_x, s_y') at I
  Eigen::Vector2d cloth_slip = Eigen::Vector2d::Zero();    // (s'_x, s'_y) at C
};

struct CushionImpactResult {
  BallVelocity after;                 // outgoing state, local cushion frame
  double compression_impulse_Ns = 0;  // P_c: normal impulse at I when compression ends
  double final_impulse_Ns = 0;        // P_f: normal impulse at I when the impact ends
  double compression_work_J = 0;      // W_c: work of the normal force at I during compression
  std::vector<ContactChange> contact_changes;  // initial modes, then every stick/slip change
  long rhs_evaluations = 0;                    // cost: evaluations of the rates dy/dP
  std::vector<ImpactSample> trace;             // only when the solver options ask for it
};

}  // namespace baize::physics
