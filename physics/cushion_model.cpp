#include "physics/cushion_model.h"

#include <cmath>
#include <stdexcept>

#include "physics/value_text.h"

namespace baize::physics {
double contactSinTheta(const CushionParams& params) {
  return (params.contact_height_m - params.radius_m) / params.radius_m;
}

void validateCushionParams(const CushionParams& p) {
  requireFinite("ball mass (kg)", p.mass_kg);
  requireFinite("ball radius (m)", p.radius_m);
  requireFinite("cushion contact height h (m)", p.contact_height_m);
  requireFinite("cushion restitution e_e", p.restitution);
  requireFinite("cushion friction mu_w", p.cushion_friction);
  requireFinite("cloth friction mu_s", p.cloth_friction);
  if (!(p.mass_kg >= kMinBallMass_kg && p.mass_kg <= kMaxBallMass_kg)) {
    rejectValue(
        "ball mass (kg)", p.mass_kg,
        "it must lie in [" + valueText(kMinBallMass_kg) + ", " + valueText(kMaxBallMass_kg) + "]");
  }
  if (!(p.radius_m >= kMinBallRadius_m && p.radius_m <= kMaxBallRadius_m)) {
    rejectValue("ball radius (m)", p.radius_m,
                "it must lie in [" + valueText(kMinBallRadius_m) + ", " +
                    valueText(kMaxBallRadius_m) + "]");
  }
  const double highest_m = p.radius_m * (1 + kMaxNoseSinTheta);
  if (!(p.contact_height_m > p.radius_m && p.contact_height_m <= highest_m)) {
    rejectValue("cushion contact height h (m)", p.contact_height_m,
                "it must lie above R = " + valueText(p.radius_m) +
                    " and at most R (1 + sin 80 deg) = " + valueText(highest_m) +
                    " (the nose touches the upper half of the ball, below its top)");
  }
  if (!(p.restitution >= kMinRestitution && p.restitution <= 1)) {
    rejectValue("cushion restitution e_e", p.restitution,
                "it must lie in [" + valueText(kMinRestitution) +
                    ", 1] (below it the exact solver could lose the rebound)");
  }
  if (p.restitution_speed_dependence)
    validateRestitutionSpeedDependence(*p.restitution_speed_dependence);
  const double s = contactSinTheta(p);
  const double c = std::sqrt(1 - s * s);
  const double tan_theta = s / c;
  if (!(p.cushion_friction >= 0 && p.cushion_friction < tan_theta)) {
    rejectValue(
        "cushion friction mu_w", p.cushion_friction,
        "it must lie in [0, tan(theta)) = [0, " + valueText(tan_theta) +
            ") for this contact height, or the table's reaction on the ball turns negative");
  }
  // Below 1 the stick equations stay well posed; real cloth is 0.15 to 0.4.
  if (!(p.cloth_friction >= 0 && p.cloth_friction < 1)) {
    rejectValue("cloth friction mu_s", p.cloth_friction, "it must lie in [0, 1)");
  }
  // The normal velocity must fall at every instant whatever the slip directions, or the cushion
  // could not stop the ball: cos th - mu_w sin th - mu_s (sin th + mu_w cos th) > 0, with a margin
  // (kMinNormalRateShare) so that it cannot nearly hold it either.
  const double worst_normal_rate =
      c - p.cushion_friction * s - p.cloth_friction * (s + p.cushion_friction * c);
  if (!(worst_normal_rate >= kMinNormalRateShare * c)) {
    rejectValue("cloth friction mu_s", p.cloth_friction,
                "with mu_w = " + valueText(p.cushion_friction) +
                    " and sin(theta) = " + valueText(s) + " it must be at most " +
                    valueText((c * (1 - kMinNormalRateShare) - p.cushion_friction * s) /
                              (s + p.cushion_friction * c)) +
                    ", or friction could (nearly) hold the ball against the cushion");
  }
}

CushionParams paramsAtIncidentSpeed(const CushionParams& params, const BallVelocity& incoming) {
  if (!params.restitution_speed_dependence) return params;
  CushionParams at_speed = params;
  at_speed.restitution = restitutionAtSpeed(params.restitution, *params.restitution_speed_dependence,
                                            incoming.v.y(), kMinRestitution);
  at_speed.restitution_speed_dependence.reset();
  return at_speed;
}

BallVelocity incomingBall(double speed_mps, double alpha_rad, double topspin_radps,
                          double sidespin_radps) {
  BallVelocity ball;
  ball.v = {speed_mps * std::cos(alpha_rad), speed_mps * std::sin(alpha_rad), 0.0};
  ball.w = {-topspin_radps * std::sin(alpha_rad), topspin_radps * std::cos(alpha_rad),
            sidespin_radps};
  return ball;
}

void validateIncomingBall(const BallVelocity& ball) {
  const char* names[] = {"v_x", "v_y", "v_z", "w_x", "w_y", "w_z"};
  for (int i = 0; i < 3; ++i) {
    if (!(std::abs(ball.v[i]) <= kMaxBallSpeed_mps)) {
      rejectValue(
          std::string("incoming ") + names[i] + " (m/s)", ball.v[i],
          "it must be a finite number of magnitude at most " + valueText(kMaxBallSpeed_mps));
    }
    if (!(std::abs(ball.w[i]) <= kMaxBallSpin_radps)) {
      rejectValue(
          std::string("incoming ") + names[i + 3] + " (rad/s)", ball.w[i],
          "it must be a finite number of magnitude at most " + valueText(kMaxBallSpin_radps));
    }
  }
  if (ball.v.z() != 0)
    rejectValue("incoming v_z (m/s)", ball.v.z(), "the ball must be on the table (0)");
  if (!(ball.v.y() > 0)) {
    rejectValue(
        "incoming v_y (m/s)", ball.v.y(),
        "the ball must move into the cushion (v_y > 0; the angle must lie in (0, 180) degrees)");
  }
  if (!(ball.v.y() >= kMinApproachSpeed_mps)) {
    rejectValue("incoming v_y (m/s)", ball.v.y(),
                "it must be at least " + valueText(kMinApproachSpeed_mps) +
                    " (a slower approach is no impact the solvers can resolve)");
  }
}

Eigen::Vector2d cushionSlip(const CushionParams& params, const BallVelocity& ball) {
  const double s = contactSinTheta(params);
  const double c = std::sqrt(1 - s * s);
  const double R = params.radius_m;
  return {ball.v.x() + R * (ball.w.y() * s - ball.w.z() * c),
          -ball.v.y() * s + ball.v.z() * c + R * ball.w.x()};
}

Eigen::Vector2d clothSlip(const CushionParams& params, const BallVelocity& ball) {
  const double R = params.radius_m;
  return {ball.v.x() - R * ball.w.y(), ball.v.y() + R * ball.w.x()};
}

BallVelocity impulseResponse(const CushionParams& params, double normal_impulse_Ns,
                             const Eigen::Vector2d& a, const Eigen::Vector2d& b) {
  const double s = contactSinTheta(params);
  const double c = std::sqrt(1 - s * s);
  const double M = params.mass_kg;
  const double k = 5.0 / (2.0 * M * params.radius_m);  // R / I for a solid sphere
  const double P = normal_impulse_Ns;
  BallVelocity change;
  change.v = {-(a.x() + b.x()) / M, -(c * P - s * a.y() + b.y()) / M, 0.0};
  change.w = {-k * (a.y() + b.y()), -k * (s * a.x() - b.x()), k * c * a.x()};
  return change;
}

double kineticEnergy(const CushionParams& params, const BallVelocity& ball) {
  const double inertia = 0.4 * params.mass_kg * params.radius_m * params.radius_m;
  return 0.5 * params.mass_kg * ball.v.squaredNorm() + 0.5 * inertia * ball.w.squaredNorm();
}

}  // namespace baize::physics
