// Step control of the exact cushion solver (the Mathavan 2010 model; method at the top of
// cushion_exact_solver.cpp): the step-size factor from a step's error, the predictive controller
// that follows the accepted steps' trend, the extrapolation of a phase end across the next step,
// and the caps on a step from the contacts' slips (their directions' time constants and turning
// scales, a held law's room, an approaching slip's zero, the first step after a contact changes).
#pragma once

#include <limits>

#include "physics/cushion_impact_rates.h"

namespace baize::physics::cushion_exact {

// First step as a fraction of M v_y0, the scale of the whole normal impulse.
constexpr double kFirstStepFraction = 0.2;
// The zero an approaching slip runs to is located where it is this multiple of the vanishing
// threshold, to within the looseness (so that it has vanished when located).
constexpr double kApproachLanding = 0.5;
constexpr double kApproachLooseness = 0.25;

// x^(-1/8) within 0.21 % (see the definition).
double inverseEighthRoot(double x);
// The factor by which to change the step after one with this error (scaled; <= 1 accepts), under
// this step control.
double stepFactor(double error, const ExactStepControl& control);
// The root in (0, limit] of the cubic through value g0 > 0 and slope d0 < 0 at 0 and value gp and
// slope dp at -H < 0 (an event function extrapolated from the last step across the next): Newton
// from the linear guess, kept where the cubic falls. Returns false when it finds none there.
bool extrapolatedRoot(double gp, double dp, double g0, double d0, double H, double limit,
                      double* root);

class StepControl : public ImpactRates {
 public:
  StepControl(const CushionParams& params, const BallVelocity& incoming,
              const ExactSolverOptions& options);

  // Caps on the next step (tau), each described where it is defined.
  double restartStep(const State& k1) const;
  double turningScaleStep(const std::array<Eigen::Vector2d, 2>& u, const State& k1) const;
  double slipDirectionStep(const std::array<Eigen::Vector2d, 2>& u) const;
  double heldLawStep(int k, const State& z, const State& k1) const;
  double approachStep(int k, const State& z, const State& k1) const;
  // h capped after a release (once), at the slip directions' time constants and at the slips'
  // turning scales, at slips u and rate k1.
  double cappedStep(const std::array<Eigen::Vector2d, 2>& u, const State& k1, double h);
  // The factor of the step after an accepted step of length h (tau) and this error, which it
  // records for the next (predictive control).
  double acceptedStepFactor(double h, double error);
  // The factor of the retry after a main-loop step rejected with this error, which it records
  // (the step after the next accepted one does not grow).
  double rejectedStepFactor(double error);
  // The factor of a step after one with this error, under the options' step control.
  double stepFactor(double error) const { return cushion_exact::stepFactor(error, step_control_); }

 protected:
  // N s: the longest impulse the next step may cover after a release (infinite: no cap)
  double release_step_cap_ = std::numeric_limits<double>::infinity();
  // The last accepted ordinary step (tau) and its error, for predictive step control (error 0:
  // none since the last event or change).
  double previous_step_ = 0, previous_error_ = 0;
  // The phase-end function and its slope where the last accepted step started, and that step
  // (tau; 0: none comparable), to extrapolate the phase end from (valid while previous_error_ > 0
  // and last_step_ > 0); and the aimed
  // steps since the last event or change that did not land (kMaxMissedLandings).
  double last_phase_value_ = 0, last_phase_slope_ = 0, last_step_ = 0;
  int missed_landings_ = 0;
  const ExactStepControl step_control_;  // ExactSolverOptions::step_control
  // A main-loop step was rejected since the last one accepted (acceptedStepFactor).
  bool after_rejection_ = false;
  // ExactStepControl::slip_direction_time_constants over 7/2 mu / M per contact (N s per unit of
  // slip: the impulse over which its own friction turns a slip of unit size by that many
  // radians); infinite where that rate is zero or too small for the quotient (slipDirectionStep).
  std::array<double, 2> direction_time_scale_{};
};

}  // namespace baize::physics::cushion_exact
