#include "physics/cushion_restitution_speed.h"

#include <algorithm>
#include <cmath>

#include "physics/value_text.h"

namespace baize::physics {

void validateRestitutionSpeedDependence(const RestitutionSpeedDependence& law) {
  if (!(law.knee_speed_mps > 0 && law.knee_speed_mps <= kMaxKneeSpeed_mps)) {
    rejectValue("restitution_speed_dependence.knee_speed_mps", law.knee_speed_mps,
                "it must be a speed in (0, " + valueText(kMaxKneeSpeed_mps) + "] m/s");
  }
  if (!(law.falloff_exponent >= 0 && law.falloff_exponent <= kMaxFalloffExponent)) {
    rejectValue("restitution_speed_dependence.falloff_exponent", law.falloff_exponent,
                "it must lie in [0, " + valueText(kMaxFalloffExponent) +
                    "] (at 1 the rebound stops growing with the incoming speed; above it a faster "
                    "ball would come back slower)");
  }
}

double restitutionAtSpeed(double restitution_at_knee, const RestitutionSpeedDependence& law,
                          double normal_speed_mps, double floor) {
  if (!(normal_speed_mps > law.knee_speed_mps)) return restitution_at_knee;
  const double fallen =
      restitution_at_knee * std::pow(law.knee_speed_mps / normal_speed_mps, law.falloff_exponent);
  return std::max(fallen, floor);
}

}  // namespace baize::physics
