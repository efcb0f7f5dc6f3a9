// Fuzz target: engine::simulate with one to four balls on a rectangular table of fuzzed size, at
// fuzzed positions (anywhere, or frozen against the previous ball or a cushion), velocities and
// spins, and with a fuzzed choice of cushion and ball-ball models and cloth. The run throws
// std::invalid_argument (input it refuses), std::runtime_error (the event budget ran out) or
// returns; when it returns, at every event no two balls overlap, no ball is beyond a cushion, and
// the event has not added energy.
#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <stdexcept>
#include <string>
#include <vector>

#include "engine/models/model_registry.h"
#include "engine/sim/shot_simulator.h"
#include "tests/fuzz/fuzz_support.h"

namespace {

using baize::fuzz::check;
using baize::physics::BallState;

// A budget far above what a few balls need, that still catches runaway loops and keeps each input
// fast; a shot that exhausts it throws std::runtime_error, which is allowed.
constexpr long kMaxFuzzEvents = 3000;
// The paper cushion scheme costs its step count per impact.
constexpr int kMaxFuzzPaperSteps = 300;
// Overlap and escape allowed at an event: contact positions are polynomial roots, located to
// rounding (the same tolerance as baize stress).
constexpr double kOverlapTolerance_m = 1e-9;
// Energy may not grow at an event beyond rounding (relative, and a floor in J/kg for balls nearly
// at rest), as the engine's own tests require.
constexpr double kEnergyRelativeTolerance = 1e-12;
constexpr double kEnergyFloor_Jpkg = 1e-15;

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  namespace engine = baize::engine;
  namespace phys = baize::physics;
  baize::fuzz::FuzzInput in(data, size);
  engine::SimulationParams p = engine::poolSimulationParams();
  p.max_events = kMaxFuzzEvents;
  p.record_trajectories = true;
  // The models by their place in the seeds' numbering (make_binary_seeds.py).
  const char* const cushion_models[] = {"exact", "paper", "simple"};
  nlohmann::json cushion = {{"model", cushion_models[in.integer(0, 2)]}};
  const int paper_steps = in.integer(1, kMaxFuzzPaperSteps);
  if (cushion["model"] == "paper") cushion["paper_steps"] = paper_steps;
  p.cushion =
      engine::cushionModels().read(engine::JsonReader(cushion, "fuzz"), engine::ModelDefaults{});
  p.ball_ball = engine::ballBallModels().make(in.integer(0, 1) ? "mathavan2014" : "frictional",
                                              engine::ModelDefaults{});
  if (in.byte() % 4 == 0) {  // another cloth, within the allowed ranges
    p.cloth.sliding_friction = in.inRange(0.01, 0.99);
    p.cloth.rolling_friction = p.cloth.sliding_friction * in.inRange(0.001, 0.99);
    p.cloth.spinning_friction = in.inRange(0.001, 0.99);
  }
  const double R = p.ball.radius_m;
  const double length_m = in.inRange(4.5 * R, 4.0);
  const double width_m = in.inRange(2.5 * R, length_m);
  const engine::TableGeometry table = engine::rectangularTable(length_m, width_m);
  const double x_max = length_m / 2 - R, y_max = width_m / 2 - R;

  const int count = in.integer(1, 4);
  std::vector<BallState> balls(count);
  for (int i = 0; i < count; ++i) {
    BallState& b = balls[i];
    const int placement = in.byte() % 4;
    if (placement == 0 && i > 0) {  // frozen against (or a hair from) the previous ball
      const double angle_rad = in.inRange(-M_PI, M_PI);
      const double gap_m = in.byte() % 2 == 0 ? 0.0 : in.value(1e-7, false);
      b.position = balls[i - 1].position +
                   (2 * R + gap_m) * Eigen::Vector2d(std::cos(angle_rad), std::sin(angle_rad));
    } else if (placement == 1) {  // touching a cushion
      b.position = {in.byte() % 2 == 0 ? x_max : -x_max, in.inRange(-y_max, y_max)};
    } else if (placement == 2) {  // anywhere, any value
      b.position = {in.value(x_max), in.value(y_max)};
    } else {
      b.position = {in.inRange(-x_max, x_max), in.inRange(-y_max, y_max)};
    }
    const double speed_scale_mps = in.byte() % 4 == 0 ? 1e-3 : 8.0;  // tiny speeds now and then
    b.velocity = {in.value(speed_scale_mps), in.value(speed_scale_mps),
                  in.byte() % 32 == 0 ? in.value(1.0) : 0.0};
    const double spin_scale_radps = 3 * speed_scale_mps / R;
    b.angular_velocity = {in.value(spin_scale_radps), in.value(spin_scale_radps),
                          in.value(spin_scale_radps)};
  }

  engine::SimulationResult result;
  try {
    result = engine::simulate(p, table, balls);
  } catch (const std::invalid_argument&) {
    return 0;
  } catch (const std::runtime_error&) {
    return 0;
  }

  for (const engine::Event& e : result.events) {
    double before = 0, after = 0;
    for (const BallState& b : e.before) before += phys::specificKineticEnergy(p.cloth, b);
    for (const BallState& b : e.after) after += phys::specificKineticEnergy(p.cloth, b);
    // The paper's Euler scheme at a few hundred steps may add energy at a cushion (first order:
    // docs/cushion-solvers.md); the other models may not.
    const bool euler_cushion =
        std::string(p.cushion->name()) == "paper" &&
        (e.kind == engine::EventKind::Cushion || e.kind == engine::EventKind::Jaw);
    check(euler_cushion || after <= before * (1 + kEnergyRelativeTolerance) + kEnergyFloor_Jpkg,
          std::string("energy grew at a ") + engine::eventKindName(e.kind) +
              " event at t = " + std::to_string(e.time_s));
    std::vector<BallState> at(count);
    for (int i = 0; i < count; ++i) {
      at[i] = engine::sampleTrajectory(p.cloth, result.trajectories[i], e.time_s);
      const Eigen::Vector2d& q = at[i].position;
      check(q.allFinite() && at[i].velocity.allFinite() && at[i].angular_velocity.allFinite(),
            "a ball's state is not finite at an event");
      check(
          std::abs(q.x()) <= x_max + kOverlapTolerance_m &&
              std::abs(q.y()) <= y_max + kOverlapTolerance_m,
          "ball " + std::to_string(i) + " is beyond a cushion at t = " + std::to_string(e.time_s));
      for (int j = 0; j < i; ++j) {
        check((q - at[j].position).norm() >= 2 * R - kOverlapTolerance_m,
              "balls " + std::to_string(j) + " and " + std::to_string(i) +
                  " overlap at t = " + std::to_string(e.time_s));
      }
    }
  }
  return 0;
}
