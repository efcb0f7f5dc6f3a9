// The balls' own constants, one group every model reads them from: the cloth, cushion and
// ball-ball models take mass and radius from here instead of each keeping a copy.
#pragma once

#include "physics/cushion_model.h"  // BallVelocity

namespace baize::engine {

// One ball set: every ball the same. Pool defaults (WPA: 57.15 mm, 0.17 kg).
struct BallProperties {
  double mass_kg = 0.17;
  double radius_m = 0.028575;
  // I = k m R^2; a solid sphere's k. The physics models assume it (they write 2/5 themselves), so
  // it is a constant here, not a setting.
  static constexpr double kInertiaFactor = 0.4;
};

// Translational plus spin energy of one ball, J. The same arithmetic as physics::kineticEnergy
// (so results are bit for bit the same whichever the caller uses).
double kineticEnergy(const BallProperties& ball, const physics::BallVelocity& velocity);

}  // namespace baize::engine
