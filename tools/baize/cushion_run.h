// One cushion impact as the baize commands describe it: a shot in the paper's terms (speed, angle
// from the cushion line in degrees, spins in units of V0/R) solved with a chosen solver setting.
// `baize cushion`, its sweep and `baize bench cushion` all go through solveCushionShot, so they run
// the solvers in exactly the same way.
#pragma once

#include <string>

#include "physics/cushion_exact_solver.h"
#include "physics/cushion_model.h"
#include "physics/cushion_paper_solver.h"

namespace baize::tools {

// Tabulated: the default path (physics/cushion_tabulated_solver.h), its exact solver at
// exact_tolerance.
enum class SolverKind { Paper, Exact, Tabulated };

struct SolverSetting {
  SolverKind kind = SolverKind::Exact;
  int paper_steps = physics::PaperSolverOptions{}.steps;             // N, paper solver only
  // The exact solver's tolerance (for Tabulated, that of the impacts the table leaves: make a
  // default Tabulated setting with tabulatedDefault()).
  double exact_tolerance = physics::ExactSolverOptions{}.tolerance;
};

// The exact solver's default tolerance on that path: its own for Exact, the table's fallback
// tolerance (physics/cushion_tabulated_solver.h) for Tabulated.
double defaultTolerance(SolverKind kind);
// The default path as it runs in a shot: the table, and the exact solver at its default there.
SolverSetting tabulatedDefault();

// "paper", "exact" or "tabulated".
std::string solverName(SolverKind kind);
// "N=5000" for the paper solver; "default" for the exact solver (or the table) at its default
// tolerance,
// otherwise "tol=1e-08".
std::string settingLabel(const SolverSetting& setting);

struct CushionShot {
  double speed_mps = 1.0;   // V0
  double angle_deg = 90.0;  // alpha, from the cushion line; 90 is head-on
  double topspin_k = 1.0;   // w_T R / V0; 1 is natural roll
  double sidespin_k = 0.0;  // w_S R / V0; positive is counter-clockwise seen from above
};

// physics::incomingBall for the shot, spins converted with the given ball radius.
physics::BallVelocity incomingBallOf(const CushionShot& shot, double radius_m);

// Solves the impact; with record_trace the result carries result.trace (the paper solver keeps
// every increment, the exact solver about kTraceSamples samples plus its steps and events).
physics::CushionImpactResult solveCushionShot(const physics::CushionParams& params,
                                              const physics::BallVelocity& incoming,
                                              const SolverSetting& setting,
                                              bool record_trace = false);

// Samples asked of the exact solver's trace over the impulse (1 + e_e) M v_y0 of a spinless ball
// on a smooth wall, which is about the length of the impact; enough for smooth slip curves.
constexpr int kTraceSamples = 1000;

// The ball's motion on the table after the impact, from its outgoing velocity.
struct Rebound {
  double speed_mps = 0;  // horizontal speed |(v_x, v_y)|
  double angle_deg = 0;  // atan2(-v_y, v_x) in degrees: from the cushion line, 90 straight back
};
Rebound reboundOf(const physics::BallVelocity& after);

}  // namespace baize::tools
