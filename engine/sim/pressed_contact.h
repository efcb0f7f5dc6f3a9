// Sustained contact: a ball pressed into another ball or a cushion, kept as a steady train of small
// bounces (see kSustainedContactSpeed_mps).
#pragma once

#include <Eigen/Core>

#include "engine/sim/ball_properties.h"
#include "physics/cushion_model.h"

namespace baize::engine {

// Sustained contact: a ball pressed into another ball or a cushion by cloth friction (spin driving
// it on, or the ball ahead slowing faster) makes a Zeno sequence of ever smaller bounces that the
// cloth damps out, ending in a contact that lasts. The event loop keeps such a contact as a steady
// train of small bounces instead: a pressed contact leaves at this separation speed at least, m/s,
// the energy for it taken from the balls' spin (the source that presses them). The impulses then
// average to the pressing force of the lasting contact, the relative speed ripples by at most this
// much and the gap by this^2 / (2 a) (0.25 um at a = 2 m/s^2), and a push of a second costs about
// a thousand events. Invisible at table scale, well above rounding.
constexpr double kSustainedContactSpeed_mps = 1e-3;
// Fraction of the energy budget left unspent by that release, so that rounding in the energy sums
// cannot make the balls' energy grow.
constexpr double kEnergyBudgetMargin = 1e-9;

// Raises the separation speed of a pressed contact towards kSustainedContactSpeed_mps (see there)
// by a normal impulse, paying the energy it adds out of the balls' spin and out of what the impact
// itself dissipated (`energy_before_J` is the balls' kinetic energy before it): as far as that
// budget reaches, so energy never grows. `normal` points from `first` to `second`; `second` is null
// for a cushion (infinite mass; the normal then points away from it, into the table).
void releasePressedContact(const BallProperties& ball, double energy_before_J,
                           const Eigen::Vector3d& normal, physics::BallVelocity* first,
                           physics::BallVelocity* second);

}  // namespace baize::engine
