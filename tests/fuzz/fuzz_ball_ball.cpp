// Fuzz target: physics::resolveBallBallImpact (both models, both friction laws, the adaptive and
// the Euler Mathavan solver) on arbitrary parameters, velocities and lines of centres. Every call
// throws std::invalid_argument or returns finite velocities on the table (v.z = 0) whose kinetic
// energy has not grown beyond the solver's accuracy (the Euler reference scheme: finite only).
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <stdexcept>
#include <string>

#include "physics/ball_ball_impact.h"
#include "tests/fuzz/fuzz_support.h"

namespace {

using baize::fuzz::check;
using baize::physics::BallBallParams;
using baize::physics::BallVelocity;

// Energy may exceed the incoming energy by rounding (the algebraic model) or by the adaptive
// integration's error (relative to the largest speed, at most tolerance 1e-3): 1e-6 relative covers
// both with margin; the solver's own tests hold it to 1e-12 at its default tolerance.
constexpr double kEnergySlackRelative = 1e-6;
// The Euler reference scheme's cost is its step count: a few hundred exercise every branch.
constexpr int kMaxFuzzFixedSteps = 300;

bool finite(const BallVelocity& b) { return b.v.allFinite() && b.w.allFinite(); }

double energy(const BallBallParams& p, const BallVelocity& b, double mass_kg) {
  const double inertia = 0.4 * mass_kg * p.radius_m * p.radius_m;  // solid sphere, kg m^2
  return 0.5 * mass_kg * b.v.squaredNorm() + 0.5 * inertia * b.w.squaredNorm();
}

BallVelocity ballFrom(baize::fuzz::FuzzInput& in) {
  const double spin_scale = 5.0 / 0.028575;  // rad/s: 5 m/s over a pool ball's radius
  BallVelocity b;
  b.v = {in.value(5.0), in.value(5.0), in.byte() % 16 == 0 ? in.value(1.0) : 0.0};
  b.w = {in.value(spin_scale), in.value(spin_scale), in.value(spin_scale)};
  return b;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  namespace phys = baize::physics;
  baize::fuzz::FuzzInput in(data, size);
  BallBallParams p;
  p.model = static_cast<phys::BallBallModel>(in.integer(0, 2));  // 2: not a model
  p.radius_m = in.value(0.03, false);
  p.mass1_kg = in.value(0.2, false);
  p.mass2_kg = in.byte() % 2 == 0 ? p.mass1_kg : in.value(0.2, false);
  p.restitution = in.value(1.0, false);
  p.friction_law = static_cast<phys::BallBallFrictionLaw>(in.integer(0, 2));  // 2: not a law
  p.friction_fit_a = in.value(0.05, false);
  p.friction_fit_b = in.value(0.5, false);
  p.friction_fit_c_s_per_m = in.value(2.0, false);
  p.constant_friction = in.value(0.5, false);
  p.ball_friction = in.value(0.2, false);
  p.cloth_friction = in.value(0.5, false);
  if (in.byte() % 4 == 0) p.tolerance = in.value(1e-6, false);
  p.fixed_steps = in.byte() % 4 == 0 ? in.integer(-2, kMaxFuzzFixedSteps) : 0;
  const BallVelocity b1 = ballFrom(in), b2 = ballFrom(in);
  Eigen::Vector3d n;
  if (in.byte() % 8 == 0) {
    n = {in.value(1.0), in.value(1.0), in.value(1e-9)};  // anything, mostly refused
  } else {
    const double angle_rad = in.value(3.2);
    n = {std::cos(angle_rad), std::sin(angle_rad), 0};
  }

  try {
    const phys::BallBallImpactResult r = phys::resolveBallBallImpact(p, b1, b2, n);
    check(finite(r.ball1) && finite(r.ball2), "the impact returned non-finite velocities");
    check(r.ball1.v.z() == 0 && r.ball2.v.z() == 0, "the impact lifted a ball");
    check(std::isfinite(r.normal_impulse_Ns) && r.normal_impulse_Ns >= 0,
          "the normal impulse is negative or not finite");
    const double before = energy(p, b1, p.mass1_kg) + energy(p, b2, p.mass2_kg);
    const double after = energy(p, r.ball1, p.mass1_kg) + energy(p, r.ball2, p.mass2_kg);
    const bool euler = p.model == phys::BallBallModel::Mathavan2014 && p.fixed_steps > 0;
    if (std::isfinite(before) && !euler) {
      check(after <= before * (1 + kEnergySlackRelative), "the impact gained energy");
    }
  } catch (const std::invalid_argument&) {
  }
  return 0;
}
