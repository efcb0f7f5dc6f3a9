// Shared pieces of the tests of the exact cushion solver's parts (cushion_impact_equations,
// cushion_held_laws, cushion_impact_rates, cushion_step_control, cushion_event_location): impacts
// to build them on, and access to a layer's contact modes (protected: the solver's driver sets
// them).
#pragma once

#include <cmath>

#include "physics/cushion_impact_equations.h"
#include "physics/cushion_model.h"

namespace baize::physics::test {

// The parts are built at the solver's default tolerance (ExactSolverOptions).
inline constexpr double kPartsTolerance = 3e-11;
inline ExactSolverOptions partsOptions() {
  ExactSolverOptions options;
  options.tolerance = kPartsTolerance;
  return options;
}

// The paper's snooker cushion, and a pool one with the nose at 63.5 % of the ball's diameter.
inline CushionParams snookerCushion() { return CushionParams{}; }
inline CushionParams poolCushion() {
  CushionParams p;
  p.mass_kg = 0.17;
  p.radius_m = 0.028575;
  p.contact_height_m = 0.635 * 2 * p.radius_m;
  return p;
}

// A ball at 2 m/s, 40 degrees off the cushion, with topspin and sidespin: both contacts slide.
inline BallVelocity spinningBall(const CushionParams& p) {
  const double angle = 40 * 3.14159265358979323846 / 180;
  return incomingBall(2.0, angle, 30 / (p.radius_m * 40), 20 / (p.radius_m * 40));
}

// A layer of the solver with its contacts' modes set from outside.
template <typename Layer>
struct Exposed : Layer {
  using Layer::Layer;
  void setContactMode(int k, ContactMode mode) { this->contacts_[k].mode = mode; }
  void setCreepGuess(int k, const Eigen::Vector2d& guess) { this->contacts_[k].creep = guess; }
  // Held since its slip grew from zero along `origin`, as the impulse (order 1) or its square (2).
  void setCreepFromRest(int k, const Eigen::Vector2d& origin, double growth_order) {
    this->contacts_[k].creep_from_rest = true;
    this->contacts_[k].creep_origin = origin;
    this->contacts_[k].creep_growth_order = growth_order;
  }
  double vanishedSlip() const { return this->vanished_slip_; }
  double regularizingSlip() const { return this->regularizing_slip_; }
};

}  // namespace baize::physics::test
