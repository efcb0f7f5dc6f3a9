// Fuzz target: the cushion impact models (physics/cushion_exact_solver.h, the paper scheme and the
// simple rule) on arbitrary parameters and incoming velocities. Every call throws
// std::invalid_argument or returns a finite outgoing state, on the table, not moving into the
// cushion, whose kinetic energy has not grown beyond rounding (exact solver and simple rule; the
// paper's Euler scheme may gain energy at few steps, so only finiteness is asked of it).
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <stdexcept>
#include <string>

#include "physics/cushion_exact_solver.h"
#include "physics/cushion_paper_solver.h"
#include "physics/cushion_simple_model.h"
#include "tests/fuzz/fuzz_support.h"

namespace {

using baize::fuzz::check;
using baize::physics::BallVelocity;
using baize::physics::CushionParams;

// The exact solver's energy may exceed the incoming energy by its integration error: its tolerance
// is relative per share of the impulse; 1e-6 of the energy covers the loosest allowed tolerance
// (1e-2) over the few percent of the energy friction can move, as the solver's own tests find.
constexpr double kExactEnergySlackRelative = 1e-6;
// The paper scheme's cost is its step count: a few hundred is enough to exercise every branch.
constexpr int kMaxFuzzPaperSteps = 300;

bool finite(const BallVelocity& b) { return b.v.allFinite() && b.w.allFinite(); }

std::string describe(const CushionParams& p, const BallVelocity& b) {
  char text[512];
  std::snprintf(text, sizeof text, "m=%a R=%a h=%a e=%a mu_w=%a mu_s=%a v=(%a,%a,%a) w=(%a,%a,%a)",
                p.mass_kg, p.radius_m, p.contact_height_m, p.restitution, p.cushion_friction,
                p.cloth_friction, b.v.x(), b.v.y(), b.v.z(), b.w.x(), b.w.y(), b.w.z());
  return text;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  namespace phys = baize::physics;
  baize::fuzz::FuzzInput in(data, size);
  CushionParams p;
  p.mass_kg = in.value(0.2, false);
  p.radius_m = in.value(0.03, false);
  // Mostly inside (R, 2R), the allowed range, to reach the solver.
  p.contact_height_m = p.radius_m * (1 + in.value(1.0, false));
  p.restitution = in.value(1.0, false);
  p.cushion_friction = in.value(0.5, false);
  p.cloth_friction = in.value(0.5, false);
  BallVelocity ball;
  ball.v = {in.value(5.0), in.value(5.0, false), in.byte() % 16 == 0 ? in.value(1.0) : 0.0};
  const double spin_scale = 5.0 / 0.03;  // rad/s: 5 m/s over R, a strong spin
  ball.w = {in.value(spin_scale), in.value(spin_scale), in.value(spin_scale)};
  phys::ExactSolverOptions options;
  if (in.byte() % 4 == 0) options.tolerance = in.value(1e-6, false);
  const int paper_steps = in.integer(-2, kMaxFuzzPaperSteps);
  const double simple_restitution = in.value(1.0, false);
  const std::string where = describe(p, ball);

  double energy_before = 0;
  bool valid_input = true;
  try {
    phys::validateCushionParams(p);
    phys::validateIncomingBall(ball);
    energy_before = phys::kineticEnergy(p, ball);
  } catch (const std::invalid_argument&) {
    valid_input = false;
  }

  try {
    const phys::CushionImpactResult r = phys::solveCushionImpactExact(p, ball, options);
    check(valid_input, "the exact solver accepted what validation refuses: " + where);
    check(finite(r.after), "the exact solver returned a non-finite state: " + where);
    check(r.after.v.z() == 0, "the exact solver lifted the ball: " + where);
    // The end of compression is located to a fraction of the tolerance times v_y0; with e_e near 0
    // restitution adds almost nothing, so that much inward speed may remain.
    check(r.after.v.y() <= options.tolerance * ball.v.y(),
          "the exact solver left the ball moving into the cushion: " + where);
    if (std::isfinite(energy_before)) {
      const double after = phys::kineticEnergy(p, r.after);
      check(after <= energy_before * (1 + kExactEnergySlackRelative),
            "the exact solver gained energy: " + where);
    }
  } catch (const std::invalid_argument&) {
  }

  try {
    phys::PaperSolverOptions paper;
    paper.steps = paper_steps;
    const phys::CushionImpactResult r = phys::solveCushionImpactPaper(p, ball, paper);
    check(valid_input && paper_steps >= 1, "the paper scheme accepted invalid input: " + where);
    check(finite(r.after), "the paper scheme returned a non-finite state: " + where);
  } catch (const std::invalid_argument&) {
  }

  try {
    phys::SimpleCushionParams simple;
    simple.restitution = simple_restitution;
    const BallVelocity after = phys::simpleCushionRebound(simple, ball);
    check(finite(after), "the simple rule returned a non-finite state: " + where);
    check(after.v.y() < 0 || ball.v.y() * simple_restitution == 0,
          "the simple rule left the ball moving into the cushion: " + where);
  } catch (const std::invalid_argument&) {
  }
  return 0;
}
