#include "physics/cushion_impact_equations.h"

#include <cmath>

namespace baize::physics::cushion_exact {

// s0 of the change of variable, as a fraction of the velocity scale: below it a slipping contact's
// own slip sets the pace (its direction turns over impulses of about M |u| / mu). A held contact
// whose slip grows to it slips on as an ordinary slipping contact.
constexpr double kRegularizingSlipFraction = 1e-3;
// A slip below this fraction of (tolerance x velocity scale) has vanished. It must lie above what
// the integration resolves of a slip (impulse errors of tolerance x M V reach the slips through the
// contact matrix, whose entries are up to 7/2, as about 3.5 tolerance x V), and taking it as zero
// moves the result by about that much: the remaining impulse to its true zero is about M |u| / (7/2
// mu), over which friction of any direction changes the velocities by less than |u|. So it sets
// much of the error at any tolerance: at 5 rather than 10 the largest error over the bench's 12000
// snooker impacts at the default tolerance falls from 4.3e-10 to 2.4e-10 V0, and at 1e-8 from 2e-7
// to 7e-8 V0 (8000 wide ones), for the same evaluations. 5 keeps it 40 % above the 3.5.
constexpr double kVanishedSlipFraction = 5;
// A held contact sliding along phi* slips as its own slip says once its slip's misalignment with
// phi*
// (|u| sin angle, which measures what the held law has missed) reaches this fraction of
// (tolerance x velocity scale).
constexpr double kCreepErrorFraction = 10;

ImpactEquations::ImpactEquations(const CushionParams& params, const BallVelocity& incoming,
                                 const ExactSolverOptions& options)
    : params_(params),
      incoming_(incoming),
      tolerance_(options.tolerance),
      min_error_share_(options.min_error_share) {
  const double tolerance = options.tolerance;
  s_ = contactSinTheta(params);
  c_ = std::sqrt(1 - s_ * s_);
  M_ = params.mass_kg;
  inverse_mass_ = 1 / M_;
  mu_ = {params.cushion_friction, params.cloth_friction};
  slip0_ = {cushionSlip(params, incoming), clothSlip(params, incoming)};
  vy0_ = incoming.v.y();
  velocity_scale_ = incoming.v.norm() + params.radius_m * incoming.w.norm();
  const double impulse_scale = M_ * velocity_scale_;
  impulse_scale_ = impulse_scale;
  for (int i = 0; i < kWork; ++i) error_scale_[i] = tolerance * impulse_scale;
  error_scale_[kWork] = tolerance * impulse_scale * velocity_scale_;
  inverse_error_scale_ = error_scale_.cwiseInverse();
  vanished_slip_ = kVanishedSlipFraction * tolerance * velocity_scale_;
  regularizing_slip_ = kRegularizingSlipFraction * velocity_scale_;
  creep_error_limit_ = kCreepErrorFraction * tolerance * velocity_scale_;
  for (int k = 0; k < 2; ++k) contacts_[k].frictionless = mu_[k] == 0;
  coupling_x_ = 1 - 2.5 * s_;
  coupling_y_ = 2.5 - s_;
  diagonal_y_ = s_ * s_ + 2.5;
  scaled_ = {3.5 * inverse_mass_,         diagonal_y_ * inverse_mass_, coupling_x_ * inverse_mass_,
             coupling_y_ * inverse_mass_, s_ * c_ * inverse_mass_,     c_ * inverse_mass_};
}

// Friction per unit P under the given laws (a contact with a zero direction has no friction).
Friction ImpactEquations::frictionFor(const Laws& laws) const {
  const double s = s_, c = c_;
  const bool stick_I = !contacts_[0].frictionless && laws.stick[0];
  const bool stick_C = !contacts_[1].frictionless && laws.stick[1];
  const Eigen::Vector2d slide_I =
      contacts_[0].frictionless ? Eigen::Vector2d::Zero() : laws.direction[0];
  const Eigen::Vector2d slide_C =
      contacts_[1].frictionless ? Eigen::Vector2d::Zero() : laws.direction[1];
  Friction f;
  if (stick_I && stick_C) {  // the x pair gives 0, the y pair a 2x2 solve
    const double det = 3.5 * (s * s + 2.5) - (2.5 - s) * (2.5 - s);
    f.a.y() = c * (2.5 + 2.5 * s) / det;
    f.b.y() = -f.a.y();
  } else if (stick_I) {  // the cloth slides; its force couples through q = s + c a_y
    const Eigen::Vector2d g = mu_[1] * slide_C;
    f.a.y() = (s * c - (2.5 - s) * s * g.y()) / ((s * s + 2.5) + (2.5 - s) * c * g.y());
    const double table_rate = s + c * f.a.y();
    f.a.x() = -(1 - 2.5 * s) * table_rate * g.x() * (1 / 3.5);
    f.b = table_rate * g;
  } else {
    f.a = mu_[0] * slide_I;
    if (stick_C) {
      f.b = Eigen::Vector2d(-(1 - 2.5 * s) * f.a.x() * (1 / 3.5),
                            -(c + (2.5 - s) * f.a.y()) * (1 / 3.5));
    } else {
      f.b = mu_[1] * (s + c * f.a.y()) * slide_C;
    }
  }
  return f;
}

// d(slip_k)/dP under friction f.
Eigen::Vector2d ImpactEquations::slipRate(int k, const Friction& f) const {
  const Eigen::Vector4d response = contactResponse(f.a.x(), f.a.y(), f.b.x(), f.b.y());
  if (k == 0) return -Eigen::Vector2d(response[0], response[1] - s_ * c_) * inverse_mass_;
  return -Eigen::Vector2d(response[2], response[3] + c_) * inverse_mass_;
}

// How far inside its friction cone contact k's friction is, as a fraction of the cone.
double ImpactEquations::coneMargin(int k, const Friction& f) const {
  if (k == 0) return 1 - f.a.norm() / mu_[0];
  return 1 - f.b.norm() / (mu_[1] * (s_ + c_ * f.a.y()));
}

// du/dtau of both contacts under the rate dz/dtau.
std::array<Eigen::Vector2d, 2> ImpactEquations::slipChanges(const State& r) const {
  const Eigen::Vector4d response = contactResponse(r[kAx], r[kAy], r[kBx], r[kBy]);
  return {Eigen::Vector2d(-response[0], -(response[1] - s_ * c_ * r[kP])) * inverse_mass_,
          Eigen::Vector2d(-response[2], -(response[3] + c_ * r[kP])) * inverse_mass_};
}

BallVelocity ImpactEquations::ballAt(const State& z) const {
  const BallVelocity change = impulseResponse(params_, z[kP], Eigen::Vector2d(z[kAx], z[kAy]),
                                              Eigen::Vector2d(z[kBx], z[kBy]));
  BallVelocity ball = incoming_;
  ball.v += change.v;
  ball.w += change.w;
  ball.v.z() = 0;  // held on the table by construction; removes rounding
  return ball;
}

}  // namespace baize::physics::cushion_exact
