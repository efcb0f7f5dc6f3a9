// An optional speed dependence of the cushion's energetic restitution e_e. The Mathavan 2010 model
// holds e_e constant, so its rebound scales with the incoming speed; the measured snooker rebounds
// it was fitted to level off above about 2 m/s, where the rigid cushion stops applying (the nose
// deforms and gives back less). This law follows them:
//
//   e_e(v) = e_0                          for v <= v_knee
//   e_e(v) = e_0 (v_knee / v)^p           above, p in [0, 1]
//
// with v the ball's normal incident speed (its velocity into the cushion, v_y of the local cushion
// frame). Continuous at the knee; above it the normal rebound speed grows as v^(1 - p), so it never
// falls as the ball comes in faster, and p = 1 holds it at the knee's. Two parameters, as the
// snooker data can fix (docs/calibrate.md); a falloff exponent of 0 is the constant e_e.
#pragma once

namespace baize::physics {

struct RestitutionSpeedDependence {
  double knee_speed_mps = 0;    // v_knee, m/s: e_e is e_0 at or below this normal speed
  double falloff_exponent = 0;  // p: above the knee e_e falls as (v_knee / v)^p
};

// The knee speeds accepted, m/s: above 0 and at most the fastest incoming ball the impact models
// take (kMaxBallSpeed_mps), beyond which a knee could never be reached.
inline constexpr double kMaxKneeSpeed_mps = 1e3;
// The steepest falloff accepted: at p = 1 the normal rebound speed stays at the knee's; beyond it
// a faster ball would come back slower, which no cushion does.
inline constexpr double kMaxFalloffExponent = 1;

// Throws std::invalid_argument naming the key (restitution_speed_dependence.knee_speed_mps or
// .falloff_exponent), the value and the allowed range.
void validateRestitutionSpeedDependence(const RestitutionSpeedDependence& law);

// e_e at the normal incident speed `normal_speed_mps` for the restitution `restitution_at_knee`
// (e_0), never below `floor` (the least restitution the solvers resolve).
double restitutionAtSpeed(double restitution_at_knee, const RestitutionSpeedDependence& law,
                          double normal_speed_mps, double floor);

}  // namespace baize::physics
