// Fuzz target: engine::sceneFromJson on arbitrary bytes, then the scene's shot. Bytes that are not
// JSON are refused by the JSON parser (its exceptions are fine); a document is either refused with
// std::invalid_argument or gives a scene whose shot runs: to rest, refused by the event loop with
// std::invalid_argument, or stopped by the event budget with std::runtime_error. Every event keeps
// energy from growing and every value finite. Any other exception, a crash or a hang is a finding.
#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <nlohmann/json.hpp>
#include <stdexcept>
#include <string>

#include "engine/io/scene.h"
#include "tests/fuzz/fuzz_json.h"
#include "tests/fuzz/fuzz_support.h"

namespace {

// Event budget of one fuzzed shot: a 9-ball break takes under 100 events, a snooker break-off about
// 300; a budget far above that still catches runaway loops, and keeps each input fast.
constexpr long kMaxFuzzEvents = 3000;
// The paper cushion scheme costs its step count per impact (about 26 ns a step): scenes may ask
// for 1e7 steps, which is correct but slow enough to look like a hang to the fuzzer.
constexpr int kMaxFuzzPaperSteps = 20000;
// Kinetic energy may not grow at an event beyond rounding (relative, and an absolute floor in J/kg
// for balls nearly at rest), as the engine's own tests require.
constexpr double kEnergyRelativeTolerance = 1e-12;
constexpr double kEnergyFloor_Jpkg = 1e-15;

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace baize;
  nlohmann::json document;
  if (!baize::fuzz::parseJson(data, size, &document)) return 0;
  engine::Scene scene;
  engine::SimulationParams params;
  physics::CueStrikeParams cue;
  try {
    // A folder that does not exist: a table or ball-set file named by the document is not found.
    scene = engine::sceneFromJson(document, "fuzz-no-such-folder/scene.json");
    params = engine::simulationParamsFor(scene);
    cue = engine::cueStrikeParamsFor(scene);
  } catch (const std::invalid_argument&) {
    return 0;
  }
  params.max_events = std::min(params.max_events, kMaxFuzzEvents);
  const bool paper = std::string(params.cushion->name()) == "paper";
  if (paper) {
    const int steps = params.cushion->parametersJson()["paper_steps"].get<int>();
    params.cushion = engine::cushionModels().changed(
        *params.cushion, {{"paper_steps", std::min(steps, kMaxFuzzPaperSteps)}}, "fuzz");
  }

  std::vector<physics::BallState> balls;
  physics::CueStrikeResult strike;
  try {
    strike = physics::strikeCueBall(cue, scene.shot);
  } catch (const std::invalid_argument&) {
    return 0;  // a shot the cue cannot play (a miscue): refused by the strike, as baize simulate
               // does
  }
  for (const engine::PlacedBall& b : scene.balls) {
    physics::BallState state;
    state.position = b.position_m;
    if (b.id == scene.cue_ball) {
      state.velocity = strike.ball.v;
      state.angular_velocity = strike.ball.w;
    }
    balls.push_back(state);
  }
  engine::SimulationResult result;
  try {
    result = engine::simulate(params, engine::geometryOf(scene.table), balls);
  } catch (const std::invalid_argument&) {
    return 0;  // refused by the event loop's own checks (a ball-set file's radius out of range)
  } catch (const std::runtime_error&) {
    return 0;  // the event budget ran out
  }
  for (const engine::Event& e : result.events) {
    double before = 0, after = 0;
    for (const physics::BallState& b : e.before)
      before += physics::specificKineticEnergy(params.cloth, b);
    for (const physics::BallState& b : e.after)
      after += physics::specificKineticEnergy(params.cloth, b);
    fuzz::check(std::isfinite(after), "non-finite energy after an event");
    // The paper's Euler scheme at few steps may add energy at a cushion (first order:
    // docs/cushion-solvers.md); the other models may not.
    const bool euler_cushion =
        paper && (e.kind == engine::EventKind::Cushion || e.kind == engine::EventKind::Jaw);
    fuzz::check(
        euler_cushion || after <= before * (1 + kEnergyRelativeTolerance) + kEnergyFloor_Jpkg,
        std::string("energy grew at a ") + engine::eventKindName(e.kind) + " event");
  }
  for (const engine::BallRecord& b : result.final_balls) {
    fuzz::check(std::isfinite(b.state.position.x()) && std::isfinite(b.state.position.y()),
                "a ball ended at a non-finite position");
  }
  return 0;
}
