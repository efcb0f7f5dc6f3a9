#include "engine/sim/pressed_contact.h"

#include <algorithm>
#include <cmath>

namespace baize::engine {

void releasePressedContact(const BallProperties& ball, double energy_before_J,
                           const Eigen::Vector3d& normal, physics::BallVelocity* first,
                           physics::BallVelocity* second) {
  const double separation = second ? (second->v - first->v).dot(normal) : first->v.dot(normal);
  if (separation >= kSustainedContactSpeed_mps) return;
  auto spinEnergy = [&](const physics::BallVelocity& b) {
    return kineticEnergy(ball, {Eigen::Vector3d::Zero(), b.w});
  };
  const double energy = kineticEnergy(ball, *first) + (second ? kineticEnergy(ball, *second) : 0);
  const double spin = spinEnergy(*first) + (second ? spinEnergy(*second) : 0);
  // Spin paid out is spin * (1 - scale^2); keep a rounding margin so energy cannot grow.
  const double budget = (spin + energy_before_J - energy) * (1 - kEnergyBudgetMargin);
  if (!(budget > 0)) return;
  // The kinetic energy the boost b adds: m/4 (2 b s + b^2) for two balls of mass m (each takes
  // half), m/2 (2 b s + b^2) for one ball off a cushion; the largest b within budget solves the
  // quadratic.
  const double effective_mass = second ? ball.mass_kg / 2 : ball.mass_kg;
  const double affordable =
      -separation + std::sqrt(separation * separation + 2 * budget / effective_mass);
  const double boost = std::min(kSustainedContactSpeed_mps - separation, affordable);
  if (!(boost > 0)) return;
  if (second) {
    first->v -= 0.5 * boost * normal;
    second->v += 0.5 * boost * normal;
  } else {
    first->v += boost * normal;
  }
  const double excess =
      kineticEnergy(ball, *first) + (second ? kineticEnergy(ball, *second) : 0) - energy_before_J;
  if (excess <= 0) return;
  const double scale = std::sqrt(std::max(0.0, 1 - excess / spin));
  first->w *= scale;
  if (second) second->w *= scale;
}

}  // namespace baize::engine
