// Shared pieces of the cushion impact tests: a seeded generator of random impacts, a metric for the
// difference of two ball states, the mirror map, rebound speed and angle (and, through
// fp_trap_support.h, the guard that turns floating-point exceptions into crashes while physics
// runs).
#pragma once

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <random>
#include <stdexcept>
#include <vector>

#include "physics/cushion_model.h"
#include "physics/cushion_paper_solver.h"
#include "tests/physics/fp_trap_support.h"  // FloatingPointTraps, used with the impacts

namespace baize::physics::test {

constexpr double kPi = 3.14159265358979323846;
constexpr double degrees(double angle_deg) { return angle_deg * kPi / 180.0; }

// The 9 ft pool table's cushion and balls (0.17 kg, 57.15 mm, nose at 36.29 mm, mu_s 0.2).
inline CushionParams poolTableCushion() {
  CushionParams p;
  p.mass_kg = 0.17;
  p.radius_m = 0.028575;
  p.contact_height_m = 0.03629;
  p.cloth_friction = 0.2;
  return p;
}

// Largest difference between two ball states, as a speed (m/s): centre velocity components, and
// angular velocity components times the radius (the surface speed they cause).
inline double velocityDifference(const BallVelocity& a, const BallVelocity& b, double radius_m) {
  double largest = 0;
  for (int i = 0; i < 3; ++i) {
    largest = std::max(largest, std::abs(a.v[i] - b.v[i]));
    largest = std::max(largest, radius_m * std::abs(a.w[i] - b.w[i]));
  }
  return largest;
}

// The reflection x -> -x: velocity (a vector) flips its x component; angular velocity (a
// pseudovector) keeps its x component and flips y and z.
inline BallVelocity mirrored(const BallVelocity& ball) {
  BallVelocity image;
  image.v = {-ball.v.x(), ball.v.y(), ball.v.z()};
  image.w = {ball.w.x(), -ball.w.y(), -ball.w.z()};
  return image;
}

// Rebound speed (m/s) and angle from the cushion line (rad): pi/2 is straight back, above pi/2 the
// ball returns toward the side it came from.
inline double reboundSpeed(const BallVelocity& after) { return after.v.norm(); }
inline double reboundAngle(const BallVelocity& after) { return std::atan2(-after.v.y(), after.v.x()); }

// One random impact, described both by its inputs and by the incoming state they give.
struct RandomImpact {
  CushionParams params;
  double speed_mps = 0;
  double alpha_rad = 0;
  double topspin_radps = 0;
  double sidespin_radps = 0;
  BallVelocity incoming;
};

// Deterministic random impacts over the ranges of the issue: speed 0.1-2.5 m/s, alpha 1-179 deg,
// topspin -2..3 V0/R, sidespin -3..3 V0/R, and (when asked) random e_e, h, mu_w < tan(theta), mu_s,
// mass and radius. The uniform mapping is written here so the sequence does not depend on the
// standard library's distributions, which differ between implementations.
class RandomImpacts {
 public:
  explicit RandomImpacts(std::uint64_t seed) : engine_(seed) {}

  // Uniform in [low, high): the top 53 bits of the engine's output scaled to [0, 1).
  double uniform(double low, double high) {
    const double unit = static_cast<double>(engine_() >> 11) * 0x1.0p-53;
    return low + (high - low) * unit;
  }

  CushionParams randomParams() {
    CushionParams p;
    p.mass_kg = uniform(0.10, 0.20);
    p.radius_m = uniform(0.025, 0.030);
    // Pool noses sit near h = 1.27 R, snooker near 1.4 R.
    p.contact_height_m = p.radius_m * uniform(1.2, 1.5);
    p.restitution = uniform(0.5, 1.0);
    const double s = contactSinTheta(p);
    const double tan_theta = s / std::sqrt(1 - s * s);
    p.cushion_friction = uniform(0.0, 0.95) * tan_theta;
    p.cloth_friction = uniform(0.0, 0.4);
    return p;
  }

  RandomImpact next(bool random_params) {
    RandomImpact impact;
    if (random_params) impact.params = randomParams();
    const double R = impact.params.radius_m;
    impact.speed_mps = uniform(0.1, 2.5);
    impact.alpha_rad = degrees(uniform(1.0, 179.0));
    impact.topspin_radps = uniform(-2.0, 3.0) * impact.speed_mps / R;
    impact.sidespin_radps = uniform(-3.0, 3.0) * impact.speed_mps / R;
    impact.incoming = incomingBall(impact.speed_mps, impact.alpha_rad, impact.topspin_radps,
                                   impact.sidespin_radps);
    return impact;
  }

 private:
  std::mt19937_64 engine_;
};

// The paper scheme's Euler trajectory with its two stop rules replaced by linear interpolation in
// its trace: compression ends where the recorded v_y crosses zero (W_c interpolated there), and the
// impact ends where the recorded work crosses (1 - e^2) W_c, the state interpolated there. The
// scheme's own rules stop at the first increment past each target, an error of up to one increment
// that depends on where the target falls inside it; interpolation makes that error O(dP^2), so what
// is left is the Euler error of the trajectory, smooth in 1/N while the slip directions are smooth.
// If the scheme stopped just short of the interpolated target (its own target can be a little
// higher), the last increment is extended linearly, a fraction of one increment.
inline BallVelocity paperSchemeWithLocatedStops(const CushionParams& params, const BallVelocity& incoming,
                                                int steps) {
  PaperSolverOptions options;
  options.steps = steps;
  options.record_trace = true;
  const std::vector<ImpactSample> trace = solveCushionImpactPaper(params, incoming, options).trace;
  std::size_t n = 1;
  while (n < trace.size() && trace[n].ball.v.y() > 0) ++n;
  if (n == trace.size()) throw std::logic_error("the paper scheme's trace never ends compression");
  const ImpactSample& a = trace[n - 1];
  const ImpactSample& b = trace[n];
  const double at_zero = a.ball.v.y() / (a.ball.v.y() - b.ball.v.y());
  const double compression_work = a.normal_work_J + at_zero * (b.normal_work_J - a.normal_work_J);
  const double target = (1 - params.restitution * params.restitution) * compression_work;
  std::size_t m = n;
  while (m + 1 < trace.size() && trace[m].normal_work_J > target) ++m;
  const ImpactSample& c = trace[m - 1];
  const ImpactSample& d = trace[m];
  const double at_target = (c.normal_work_J - target) / (c.normal_work_J - d.normal_work_J);
  BallVelocity end;
  end.v = c.ball.v + at_target * (d.ball.v - c.ball.v);
  end.w = c.ball.w + at_target * (d.ball.w - c.ball.w);
  return end;
}

}  // namespace baize::physics::test
