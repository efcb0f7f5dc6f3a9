// The checks `baize stress` makes on one shot: the event loop runs it to rest and every event is
// checked for non-finite values, overlapping balls, a ball off the table (stress_tables.h defines
// "on the table" with pockets), kinetic energy growing across the event, and the shot needing
// more than max_events events (a hang) or being refused.
#pragma once

#include <map>
#include <string>
#include <vector>

#include "engine/play/stress_tables.h"
#include "engine/sim/shot_simulator.h"
#include "physics/cloth_motion.h"

namespace baize::engine {

// Overlap between balls, or a centre closer than R to a cushion or jaw, beyond this is a failure,
// m: contact positions come from polynomial roots, correct to rounding (~1e-14 m).
constexpr double kStressOverlapTolerance_m = 1e-9;

struct ShotCheck {
  std::map<std::string, long> failures;  // kind ("overlap", "escape", ...) -> events failing so
  std::string first_message;             // "<kind>: <what, where, when>" of the first failure
  void fail(const std::string& kind, const std::string& message);
  bool failed() const { return !failures.empty(); }
};

struct StressShotOutcome {
  ShotCheck check;
  long events = 0;
  double worst_energy_growth = 0;  // largest relative growth of kinetic energy across an event
  int pocketed = 0;                // balls that fell into a pocket
};

// Simulates `balls` on `table` with `params` and checks every event.
StressShotOutcome checkShot(const StressTable& table, const engine::SimulationParams& params,
                            const std::vector<physics::BallState>& balls);

}  // namespace baize::engine
