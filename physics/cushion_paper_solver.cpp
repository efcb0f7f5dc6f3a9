#include "physics/cushion_paper_solver.h"

#include <cmath>
#include <stdexcept>
#include <string>

#include "physics/value_text.h"

namespace baize::physics {
namespace {

ImpactSample sampleOf(const CushionParams& params, double P, const BallVelocity& ball,
                      double work) {
  return {P, ball, work, cushionSlip(params, ball), clothSlip(params, ball)};
}

}  // namespace

CushionImpactResult solveCushionImpactPaper(const CushionParams& given,
                                            const BallVelocity& incoming,
                                            const PaperSolverOptions& options) {
  validateCushionParams(given);
  validateIncomingBall(incoming);
  const CushionParams params = paramsAtIncidentSpeed(given, incoming);
  if (options.steps < 1 || options.steps > kMaxPaperSteps) {
    rejectValue("paper solver steps", options.steps,
                "it must lie in [1, " + std::to_string(kMaxPaperSteps) + "]");
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
  // The increment's constant factors, hoisted out of the loop (eq. 14a and its partners with the
  // friction directions frozen over the increment; see impulseResponse).
  const double R = params.radius_m;
  const double linear = dP / params.mass_kg;                    // dv per unit friction coefficient
  const double angular = 5 * dP / (2 * params.mass_kg * R);     // dw per unit friction coefficient
  auto unit = [](double x, double y, double* ux, double* uy) {  // zero when there is no slip
    const double size = std::sqrt(x * x + y * y);
    *ux = size > 0 ? x / size : 0;
    *uy = size > 0 ? y / size : 0;
  };
  for (long n = 0;; ++n) {
    if (n == max_increments) throw std::logic_error("paper cushion solver did not terminate");
    Eigen::Vector3d& v = ball.v;
    Eigen::Vector3d& w = ball.w;
    double ix, iy, cx, cy;
    unit(v.x() + R * (w.y() * s - w.z() * c), -v.y() * s + R * w.x(), &ix, &iy);  // eq. 12a, 12b
    unit(v.x() - R * w.y(), v.y() + R * w.x(), &cx, &cy);                         // eq. 13a, 13b
    const double ax = mu_w * ix, ay = mu_w * iy;
    const double table_rate = s + c * ay;  // dP_C/dP, eq. 8
    const double bx = mu_s * table_rate * cx, by = mu_s * table_rate * cy;
    const double vy_before = v.y();
    v.x() -= linear * (ax + bx);
    v.y() -= linear * (c - s * ay + by);
    w.x() -= angular * (ay + by);
    w.y() -= angular * (s * ax - bx);
    w.z() += angular * c * ax;
    P += dP;
    work += dP * c * (vy_before + v.y()) / 2;  // eq. 17a
    ++result.rhs_evaluations;
    if (options.record_trace) result.trace.push_back(sampleOf(params, P, ball, work));
    if (compressing && v.y() <= 0) {  // eq. 17c, met at the first increment that crosses
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
