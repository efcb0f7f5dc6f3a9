#include "physics/cushion_paper_solver.h"

#include <cmath>
#include <stdexcept>
#include <string>

namespace baize::physics {
namespace {

// Unit vector along a slip velocity; zero when there is no slip, which switches that contact's
// friction off for the increment, as the paper does (section 3.2).
Eigen::Vector2d slipDirection(const Eigen::Vector2d& slip) {
  const double speed = slip.norm();
  return speed > 0 ? Eigen::Vector2d(slip / speed) : Eigen::Vector2d::Zero();
}

ImpactSample sampleOf(const CushionParams& params, double P, const BallVelocity& ball, double work) {
  return {P, ball, work, cushionSlip(params, ball), clothSlip(params, ball)};
}

}  // namespace

CushionImpactResult solveCushionImpactPaper(const CushionParams& params, const BallVelocity& incoming,
                                            const PaperSolverOptions& options) {
  validateCushionParams(params);
  validateIncomingBall(incoming);
  if (options.steps < 1) {
    throw std::invalid_argument("paper solver steps = " + std::to_string(options.steps) +
                                " is not allowed: it must be >= 1");
  }
  const double s = contactSinTheta(params);
  const double c = std::sqrt(1 - s * s);
  const double mu_w = params.cushion_friction;
  const double mu_s = params.cloth_friction;
  const double e = params.restitution;
  // The paper's increment: the impulse of a spinless ball on a flat wall, cut into N pieces.
  const double dP = (1 + e) * params.mass_kg * incoming.v.y() / options.steps;
  // validateCushionParams guarantees dv_y/dP <= -worst_rate / M < 0, so compression ends within
  // M v_y0 / worst_rate and restitution soon after; this bound only guards against a logic error.
  const long max_increments = 1000L * options.steps;

  CushionImpactResult result;
  BallVelocity ball = incoming;
  double P = 0, work = 0, work_target = 0;
  bool compressing = true;
  if (options.record_trace) result.trace.push_back(sampleOf(params, P, ball, work));
  for (long n = 0;; ++n) {
    if (n == max_increments) throw std::logic_error("paper cushion solver did not terminate");
    const Eigen::Vector2d a = mu_w * slipDirection(cushionSlip(params, ball));
    const double table_rate = s + c * a.y();  // dP_C/dP, eq. 8
    const Eigen::Vector2d b = mu_s * table_rate * slipDirection(clothSlip(params, ball));
    const BallVelocity change = impulseResponse(params, dP, a * dP, b * dP);
    const double vy_before = ball.v.y();
    ball.v += change.v;
    ball.w += change.w;
    P += dP;
    work += dP * c * (vy_before + ball.v.y()) / 2;  // eq. 17a
    ++result.rhs_evaluations;
    if (options.record_trace) result.trace.push_back(sampleOf(params, P, ball, work));
    if (compressing && ball.v.y() <= 0) {  // eq. 17c, met at the first increment that crosses
      compressing = false;
      result.compression_impulse_Ns = P;
      result.compression_work_J = work;
      work_target = (1 - e * e) * work;  // eq. 17b
    }
    if (!compressing && work <= work_target) break;
  }
  result.after = ball;
  result.final_impulse_Ns = P;
  return result;
}

}  // namespace baize::physics
