#include "engine/sim/ball_properties.h"

namespace baize::engine {

double kineticEnergy(const BallProperties& ball, const physics::BallVelocity& velocity) {
  const double inertia =
      BallProperties::kInertiaFactor * ball.mass_kg * ball.radius_m * ball.radius_m;
  return 0.5 * ball.mass_kg * velocity.v.squaredNorm() + 0.5 * inertia * velocity.w.squaredNorm();
}

}  // namespace baize::engine
