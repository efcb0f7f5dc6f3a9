#include "physics/cue_strike.h"

#include <Eigen/Geometry>
#include <cmath>
#include <stdexcept>
#include <string>

#include "physics/value_text.h"

// Derivation of the impulse.
//
// The cue is a rigid body of mass m_c moving along its axis d at speed V; the ball (mass m,
// I = 2/5 m R^2) is at rest. The tip pushes with an impulse F d through Q (the tip grips: no slip
// at the tip, so the impulse lies along the cue). Momentum and angular momentum about the centre:
//   v = F d / m,   w = (Q x d) F / I,   cue speed after V' = V - F / m_c.
// Velocity of the ball's surface point Q along d:
//   (v + w x Q) . d = F / m + (F / I) ((Q x d) x Q) . d = F / m + (F / I) |Q x d|^2
// (scalar triple product), = (F / m) (1 + (5 / (2 R^2)) l^2) with l = |Q x d|, the distance from
// the centre to the cue line. Newton's restitution at the tip along d, (ball point - cue) = e_tip
// V:
//   (F / m)(1 + 5 l^2 / (2 R^2)) - V + F / m_c = e_tip V
//   => F = (1 + e_tip) m V / (1 + m / m_c + 5 l^2 / (2 R^2)).
// This is a one-dimensional collision of m_c with the effective mass m / (1 + 5 l^2 / (2 R^2)), so
// the ball's kinetic energy F^2 / (2 m_eff) never exceeds what the cue loses, with equality at
// e_tip = 1. The cross term. With Q = R (a r + b z - c h) and d = cos(th) h - sin(th) z:
//   Q . d = -R (c cos th + b sin th),
//   l^2 = R^2 - (Q . d)^2 = R^2 (a^2 + b^2 cos^2 th + c^2 sin^2 th - 2 b c sin th cos th)
//       = R^2 (a^2 + (b cos th - c sin th)^2).
// The cross term's sign follows from Q sitting behind the ball (-c h) while the cue points down
// (-sin th z): for a high hit (b > 0) raising the cue swings its line towards the centre, through
// it at tan th = b / c, so the same b gives less spin. Level cue: l^2 = R^2 (a^2 + b^2).

namespace baize::physics {
namespace {

constexpr double kPi = 3.14159265358979323846;

}  // namespace

void validateCueStrikeParams(const CueStrikeParams& p) {
  requireFinite("cue mass (kg)", p.cue_mass_kg);
  requireFinite("cue tip restitution e_tip", p.tip_restitution);
  requireFinite("ball mass (kg)", p.ball_mass_kg);
  requireFinite("ball radius (m)", p.ball_radius_m);
  if (!(p.cue_mass_kg > 0)) rejectValue("cue mass (kg)", p.cue_mass_kg, "it must be > 0");
  if (!(p.tip_restitution >= 0 && p.tip_restitution <= 1)) {
    rejectValue("cue tip restitution e_tip", p.tip_restitution, "it must lie in [0, 1]");
  }
  if (!(p.ball_mass_kg > 0)) rejectValue("ball mass (kg)", p.ball_mass_kg, "it must be > 0");
  if (!(p.ball_radius_m > 0)) rejectValue("ball radius (m)", p.ball_radius_m, "it must be > 0");
  if (p.end_mass_kg) {
    requireFinite("cue end mass (kg)", *p.end_mass_kg);
    if (!(*p.end_mass_kg > 0)) {
      rejectValue("cue end mass (kg)", *p.end_mass_kg,
                  "it must be > 0 (leave it empty for no squirt)");
    }
  }
}

void validateCueShot(const CueShot& s) {
  requireFinite("cue speed V (m/s)", s.speed_mps);
  requireFinite("cue heading phi (rad)", s.heading_rad);
  requireFinite("cue elevation theta (rad)", s.elevation_rad);
  requireFinite("tip side offset a (units of R)", s.side_offset);
  requireFinite("tip height offset b (units of R)", s.height_offset);
  if (!(s.speed_mps >= 0)) rejectValue("cue speed V (m/s)", s.speed_mps, "it must be >= 0");
  if (!(s.elevation_rad >= 0 && s.elevation_rad < kPi / 2)) {
    rejectValue(
        "cue elevation theta (rad)", s.elevation_rad,
        "it must lie in [0, pi/2): the cue cannot come from below the table or straight down");
  }
  const double offset = std::hypot(s.side_offset, s.height_offset);
  if (!(offset <= kMiscueOffsetLimit)) {
    rejectValue("tip offset sqrt(a^2 + b^2) (units of R)", offset,
                "it must be at most " + valueText(kMiscueOffsetLimit) +
                    " or the tip miscues (a = " + valueText(s.side_offset) +
                    ", b = " + valueText(s.height_offset) + ")");
  }
}

namespace {

// -Q . d / R = c cos(theta) + b sin(theta): positive when the tip meets Q first along the cue line.
double tipFacing(const CueShot& shot) {
  const double a = shot.side_offset, b = shot.height_offset;
  const double c = std::sqrt(1 - a * a - b * b);
  return c * std::cos(shot.elevation_rad) + b * std::sin(shot.elevation_rad);
}

}  // namespace

bool cueMeetsTipPointFirst(const CueShot& shot) { return tipFacing(shot) > 0; }

double steepestCueElevationRad(double side_offset, double height_offset) {
  const double a = side_offset, b = height_offset;
  if (b >= 0) return kPi / 2;
  return std::atan2(std::sqrt(1 - a * a - b * b), -b);
}

CueStrikeResult strikeCueBall(const CueStrikeParams& params, const CueShot& shot) {
  validateCueStrikeParams(params);
  validateCueShot(shot);
  const double R = params.ball_radius_m, m = params.ball_mass_kg, m_c = params.cue_mass_kg;
  const double a = shot.side_offset, b = shot.height_offset;
  const double c = std::sqrt(1 - a * a - b * b);
  const double cos_th = std::cos(shot.elevation_rad), sin_th = std::sin(shot.elevation_rad);
  const Eigen::Vector3d z = Eigen::Vector3d::UnitZ();
  const Eigen::Vector3d aim(std::cos(shot.heading_rad), std::sin(shot.heading_rad), 0.0);
  const Eigen::Vector3d right = aim.cross(z);
  const Eigen::Vector3d d = cos_th * aim - sin_th * z;
  const Eigen::Vector3d Q = R * (a * right + b * z - c * aim);

  // The tip must meet Q first along the cue line: Q . d = -R (c cos th + b sin th) < 0.
  const double facing = tipFacing(shot);
  if (!(facing > 0)) {
    rejectValue("cue elevation theta (rad)", shot.elevation_rad,
                "with b = " + valueText(b) + " the cue line meets the ball behind the tip point " +
                    "(c cos(theta) + b sin(theta) = " + valueText(facing) + " must be > 0)");
  }
  const double cross = b * cos_th - c * sin_th;
  const double offset_sq = a * a + cross * cross;  // (l / R)^2
  const double F =
      (1 + params.tip_restitution) * m * shot.speed_mps / (1 + m / m_c + 2.5 * offset_sq);
  const double inertia = 0.4 * m * R * R;

  CueStrikeResult result;
  result.impulse_Ns = F;
  result.cue_axis = d;
  result.contact_point_m = Q;
  result.cue_line_offset_m = R * std::sqrt(offset_sq);
  result.cue_speed_after_mps = shot.speed_mps - F / m_c;
  Eigen::Vector3d v = (F / m) * d;
  result.discarded_vertical_velocity_mps = v.z();
  v.z() = 0;  // the cloth takes the downward part: no jump in this model
  if (params.end_mass_kg) {
    const double s = 1 - a * a;
    const double alpha =
        std::atan(2.5 * a * std::sqrt(s) / (1 + m / *params.end_mass_kg + 2.5 * s));
    // Away from the offset side: right english (a > 0) turns the ball left, i.e. counter-clockwise
    // seen from above, which is a positive rotation about z.
    const double ca = std::cos(alpha), sa = std::sin(alpha);
    v = Eigen::Vector3d(ca * v.x() - sa * v.y(), sa * v.x() + ca * v.y(), 0.0);
    result.squirt_angle_rad = alpha;
  }
  result.ball.v = v;
  result.ball.w = (F / inertia) * Q.cross(d);
  return result;
}

}  // namespace baize::physics
