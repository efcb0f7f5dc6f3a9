// The cue's strike on the cue ball as one instantaneous impulse along the cue axis.
//
// World frame, z up. Units: SI (kg, m, s, rad, N s, J); tip offsets in units of the ball radius R.
//
// Geometry. The cue points along the heading phi (in the table plane, from +x towards +y) with
// elevation theta (0 = level, butt raised for theta > 0). With h = (cos phi, sin phi, 0) the
// horizontal aim, r = h x z the horizontal "right" seen looking along the cue, the cue axis is
// d = cos(theta) h - sin(theta) z and the tip touches the ball at
//   Q = R (a r + b z - c h),   c = sqrt(1 - a^2 - b^2),
// measured from the ball's centre: a is the side offset (positive to the right looking along the
// cue), b the height above the centre, both in units of R and in the ball's upright frame (not in
// the plane normal to an elevated cue).
//
// Impulse (derived in cue_strike.cpp). The tip gives the ball F along d through Q:
//   F = (1 + e_tip) m V / (1 + m / m_c + (5 / (2 R^2)) l^2),   l^2 = |Q x d|^2 = R^2 (a^2 + (b cos
//   theta - c sin theta)^2)
// with l the distance from the ball's centre to the cue line; v = F d / m, w = Q x F d / I.
//
// Cloth. The downward part of F (elevated cue) goes into the cloth: the output has v.z = 0 and the
// removed vertical velocity is reported. No jumps and no cloth friction during the strike are
// modelled; the angular velocity keeps the whole of Q x F d / I (elevation with side offset gives
// spin about the horizontal aim axis, which curves the ball later: masse).
//
// Sign conventions. Right english (a > 0) gives w_z > 0, counter-clockwise seen from above. Top
// (b > 0) gives forward roll spin, w = -|w| r; b = 0.4 makes a level strike leave the ball rolling.
//
// Squirt (optional): with an end mass m_end the ball leaves rotated in the table plane away from
// the offset side by the angle with tan(alpha) = (5/2) a sqrt(1 - a^2) / (1 + m / m_end + (5/2)(1 -
// a^2)) (physics-notes section 4), speed and spin unchanged.
#pragma once

#include <Eigen/Core>
#include <optional>

#include "physics/cushion_model.h"  // BallVelocity

namespace baize::physics {

// Largest tip offset sqrt(a^2 + b^2), in units of R, that does not miscue (physics-notes section 4,
// "about 0.5 R"; a chalked tip slips off beyond it).
constexpr double kMiscueOffsetLimit = 0.5;

// Fastest cue speed V accepted from input (scenes), m/s. The fastest break shots measured send the
// cue ball off at about 12-14 m/s; a level centre hit sends it off at up to about 1.33 V (pool
// ball, the default 0.54 kg cue with e_tip 0.75), so 12.3 m/s reaches about 16 m/s: above any
// measured break, and the fastest ball speed the stress program (engine/play/stress_shots.cpp)
// checks the engine at, which also strikes its cue shots at up to this speed. The strike itself
// holds at any speed (validateCueShot does not check this bound): noise added to a shot may exceed
// it slightly.
constexpr double kMaxCueSpeed_mps = 12.3;

struct CueStrikeParams {
  double cue_mass_kg = 0.54;  // m_c, whole cue (19 oz)
  // e_tip. Alciatore measured 0.71-0.75 for playing cues with medium-hardness leather tips
  // (billiards.colostate.edu, "cue tip efficiency" FAQ and TP A.30); the top of that range.
  double tip_restitution = 0.75;
  double ball_mass_kg = 0.170;      // m (WPA pool ball)
  double ball_radius_m = 0.028575;  // R
  // Effective end mass of the shaft for squirt, kg (typically 0.005-0.015); empty: no squirt.
  std::optional<double> end_mass_kg;
};

struct CueShot {
  double speed_mps = 0;      // V, cue speed just before contact, >= 0
  double heading_rad = 0;    // phi, aim direction in the table plane
  double elevation_rad = 0;  // theta in [0, pi/2)
  double side_offset = 0;    // a, units of R, + right looking along the cue
  double height_offset = 0;  // b, units of R, + above the centre
};

struct CueStrikeResult {
  BallVelocity ball;                                          // world frame, v.z = 0
  double impulse_Ns = 0;                                      // F
  Eigen::Vector3d cue_axis = Eigen::Vector3d::Zero();         // d, unit
  Eigen::Vector3d contact_point_m = Eigen::Vector3d::Zero();  // Q relative to the ball's centre
  double cue_line_offset_m = 0;                // l, distance from the ball's centre to the cue line
  double cue_speed_after_mps = 0;              // V - F / m_c
  double discarded_vertical_velocity_mps = 0;  // -F sin(theta) / m, absorbed by the cloth (<= 0)
  double squirt_angle_rad = 0;                 // signed: > 0 turns the ball to the left of the aim
};

// Throw std::invalid_argument naming the value and the allowed range.
void validateCueStrikeParams(const CueStrikeParams& params);
void validateCueShot(const CueShot& shot);

// Whether the cue meets the ball first at the tip point Q (Q . d < 0, i.e. c cos(theta) + b
// sin(theta) > 0), with the arithmetic strikeCueBall uses to refuse a shot; needs an offset within
// the miscue limit. Always true at or above the centre (b >= 0) for theta in [0, pi/2).
bool cueMeetsTipPointFirst(const CueShot& shot);
// The elevation (rad) from which the cue no longer meets Q first: pi/2 for b >= 0, atan(c / -b)
// below the centre (c = sqrt(1 - a^2 - b^2)), where the cue line grazes the ball at Q. For
// messages; cueMeetsTipPointFirst decides.
double steepestCueElevationRad(double side_offset, double height_offset);

// Throws std::invalid_argument on invalid parameters, a miscue (offset above kMiscueOffsetLimit) or
// a cue that cannot reach Q (Q must face the cue: Q . d < 0).
CueStrikeResult strikeCueBall(const CueStrikeParams& params, const CueShot& shot);

}  // namespace baize::physics
