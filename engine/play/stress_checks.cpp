#include "engine/play/stress_checks.h"

#include <algorithm>
#include <cmath>
#include <sstream>
#include <stdexcept>

namespace baize::engine {
namespace {

using physics::BallState;

// Kinetic energy after an event may exceed that before by this fraction of it plus kEnergyFloor:
// rounding in the impact models (the exact cushion solver is accurate to 1e-9 of the speed, but
// conserves or loses energy by construction; the ball-ball model loses it exactly).
constexpr double kEnergyRelativeTolerance = 1e-12;
// Absolute floor for the energy check, J/kg: rounding of energies of balls near the stopping
// thresholds (speeds of 1e-9 m/s carry 5e-19 J/kg).
constexpr double kEnergyFloor_Jpkg = 1e-15;

bool finite(const BallState& b) {
  return b.position.allFinite() && b.velocity.allFinite() && b.angular_velocity.allFinite();
}

std::string at(double time_s) {
  std::ostringstream text;
  text.precision(17);
  text << " at t = " << time_s << " s";
  return text.str();
}

// Checks the balls on the table at one instant: all finite, no overlap, all on the table.
void checkPositions(const StressTable& table, const std::vector<BallState>& balls,
                    const std::vector<int>& ids, double time_s, ShotCheck* check) {
  const double R = table.params.ball.radius_m;
  for (std::size_t i = 0; i < balls.size(); ++i) {
    const std::string ball = "ball " + std::to_string(ids[i]);
    if (!finite(balls[i])) {
      check->fail("non-finite", ball + at(time_s));
      continue;
    }
    for (std::size_t j = 0; j < i; ++j) {
      const double gap = (balls[i].position - balls[j].position).norm() - 2 * R;
      if (gap < -kStressOverlapTolerance_m) {
        std::ostringstream m;
        m.precision(17);
        m << "balls " << ids[j] << " and " << ids[i] << " overlap by " << -gap << " m";
        check->fail("overlap", m.str() + at(time_s));
      }
    }
    const std::string off = offTableReason(table, balls[i].position, kStressOverlapTolerance_m);
    if (!off.empty()) check->fail("escape", ball + ": " + off + at(time_s));
  }
}

}  // namespace

void ShotCheck::fail(const std::string& kind, const std::string& message) {
  if (failures.empty()) first_message = kind + ": " + message;
  ++failures[kind];
}

StressShotOutcome checkShot(const StressTable& table, const engine::SimulationParams& params,
                            const std::vector<BallState>& input) {
  StressShotOutcome out;
  ShotCheck& check = out.check;
  engine::SimulationResult result;
  try {
    result = engine::simulate(params, table.geometry, input);
  } catch (const engine::BallLeftTableError& e) {  // the event loop's own escape guard
    check.fail("escape", e.what());
    return out;
  } catch (const std::runtime_error& e) {
    check.fail("hang", e.what());
    return out;
  } catch (const std::invalid_argument& e) {
    check.fail("rejected", e.what());
    return out;
  }
  out.events = static_cast<long>(result.events.size());
  const int n = static_cast<int>(input.size());
  std::vector<BallState> known = input;  // each ball's last known state and its time
  std::vector<double> known_time(n, 0);
  std::vector<bool> pocketed(n, false);
  std::vector<BallState> on_table;
  std::vector<int> ids;
  for (const engine::Event& e : result.events) {
    if (!std::isfinite(e.time_s)) check.fail("non-finite", "an event time");
    double before = 0, after = 0;
    for (const BallState& b : e.before) before += physics::specificKineticEnergy(params.cloth, b);
    for (const BallState& b : e.after) {
      if (!finite(b)) {
        check.fail("non-finite",
                   std::string("state after a ") + engine::eventKindName(e.kind) + at(e.time_s));
      }
      after += physics::specificKineticEnergy(params.cloth, b);
    }
    if (before > 0)
      out.worst_energy_growth = std::max(out.worst_energy_growth, (after - before) / before);
    if (!(after <= before * (1 + kEnergyRelativeTolerance) + kEnergyFloor_Jpkg)) {
      std::ostringstream m;
      m.precision(17);
      m << engine::eventKindName(e.kind) << ": " << before << " -> " << after << " J/kg";
      check.fail("energy", m.str() + at(e.time_s));
    }
    // Every ball moved on to the event's time (those not in it along their closed form).
    on_table.clear();
    ids.clear();
    for (int i = 0; i < n; ++i) {
      if (pocketed[i]) continue;
      if (i == e.ball) {
        known[i] = e.after[0];
      } else if (e.kind == engine::EventKind::BallBall && i == e.other) {
        known[i] = e.after[1];
      } else {
        known[i] =
            physics::advance(params.cloth, known[i], std::max(0.0, e.time_s - known_time[i]));
      }
      known_time[i] = e.time_s;
      if (e.kind == engine::EventKind::Pocket && i == e.ball) {
        pocketed[i] = true;
        ++out.pocketed;
        continue;
      }
      on_table.push_back(known[i]);
      ids.push_back(i);
    }
    checkPositions(table, on_table, ids, e.time_s, &check);
  }
  on_table.clear();
  ids.clear();
  for (int i = 0; i < n; ++i) {
    if (result.final_balls[i].pocketed) continue;
    on_table.push_back(result.final_balls[i].state);
    ids.push_back(i);
  }
  checkPositions(table, on_table, ids, result.end_time_s, &check);
  return out;
}

}  // namespace baize::engine
