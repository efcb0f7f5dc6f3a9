#include "engine/sim/shot_simulation.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <stdexcept>
#include <string>
#include <vector>

#include "engine/io/scene.h"
#include "engine/io/table.h"
#include "engine/sim/shot_simulator.h"

namespace baize::engine {
namespace {

using physics::BallState;

// Positions sampled from two closed forms of the same motion (from the ball's last state, or from
// its last recorded trajectory piece across a state change) agree to rounding of a few operations.
constexpr double kSampleTolerance_m = 1e-12;

bool sameBits(const BallState& a, const BallState& b) {
  return std::memcmp(a.position.data(), b.position.data(), sizeof(double) * 2) == 0 &&
         std::memcmp(a.velocity.data(), b.velocity.data(), sizeof(double) * 3) == 0 &&
         std::memcmp(a.angular_velocity.data(), b.angular_velocity.data(), sizeof(double) * 3) == 0;
}

bool sameEvent(const Event& a, const Event& b) {
  if (std::memcmp(&a.time_s, &b.time_s, sizeof a.time_s) != 0 || a.kind != b.kind ||
      a.ball != b.ball || a.other != b.other || a.index != b.index ||
      a.before.size() != b.before.size() || a.after.size() != b.after.size())
    return false;
  for (std::size_t k = 0; k < a.before.size(); ++k)
    if (!sameBits(a.before[k], b.before[k]) || !sameBits(a.after[k], b.after[k])) return false;
  return true;
}

// A shipped scene's shot, struck: what the event loop starts from.
struct Start {
  SimulationParams params;
  TableGeometry table;
  std::vector<BallState> balls;
  std::vector<std::string> ids;
};

Start startOf(const std::string& name, bool record_trajectories = false) {
  const Scene scene = loadScene(assetsDirectory() + "/scenes/" + name + ".json");
  const SceneStart start = sceneStart(scene, record_trajectories);
  return {start.params, geometryOf(scene.table), start.balls, start.ball_ids};
}

const char* const kScenes[] = {"9-ball-break", "snooker-break-off", "three-cushion-bank",
                               "heavy-sidespin", "one-ball-among-100"};

// One event at a time gives exactly what a run to rest gives: every event and final state, to the
// bit, and nextEvent() announces each event step() then resolves.
TEST(ShotSimulation, SteppingGivesTheRunToRestBitForBit) {
  for (const char* name : kScenes) {
    const Start s = startOf(name);
    const SimulationResult whole = simulate(s.params, s.table, s.balls, s.ids);
    ShotSimulation stepped(s.params, s.table, s.balls, s.ids);
    std::size_t k = 0;
    for (;;) {
      const std::optional<PredictedEvent> next = stepped.nextEvent();
      const Event* event = stepped.step();
      ASSERT_EQ(next.has_value(), event != nullptr) << name;
      if (!event) break;
      ASSERT_LT(k, whole.events.size()) << name;
      EXPECT_TRUE(sameEvent(*event, whole.events[k])) << name << ", event " << k;
      EXPECT_EQ(next->dt_s, event->time_s);
      EXPECT_EQ(next->kind, event->kind);
      EXPECT_EQ(next->ball, event->ball);
      EXPECT_EQ(stepped.time(), event->time_s);
      ++k;
    }
    EXPECT_EQ(k, whole.events.size()) << name;
    EXPECT_EQ(stepped.step(), nullptr);  // at rest it stays at rest
    const SimulationResult rest = stepped.runToRest();
    ASSERT_EQ(rest.final_balls.size(), whole.final_balls.size());
    for (std::size_t i = 0; i < rest.final_balls.size(); ++i) {
      EXPECT_TRUE(sameBits(rest.final_balls[i].state, whole.final_balls[i].state))
          << name << " " << i;
      EXPECT_EQ(rest.final_balls[i].pocketed, whole.final_balls[i].pocketed);
    }
    EXPECT_EQ(rest.predictions, whole.predictions);
    EXPECT_EQ(rest.skipped_predictions, whole.skipped_predictions);
  }
}

// advanceTo() resolves every event up to the time and no later one; the balls sampled there are
// where the recorded trajectories put them.
TEST(ShotSimulation, AdvancingToATimeSamplesTheBallsOnTheirPaths) {
  const Start s = startOf("9-ball-break", /*record_trajectories=*/true);
  const SimulationResult whole = simulate(s.params, s.table, s.balls, s.ids);
  ShotSimulation sim(s.params, s.table, s.balls, s.ids);
  for (double t = 0; t < whole.end_time_s + 0.5; t += 0.137) {
    sim.advanceTo(t);
    EXPECT_EQ(sim.time(), t);
    std::size_t resolved = 0;
    while (resolved < whole.events.size() && whole.events[resolved].time_s <= t) ++resolved;
    EXPECT_EQ(sim.events().size(), resolved) << "at t = " << t;
    for (int i = 0; i < sim.ballCount(); ++i) {
      const BallState expected = sampleTrajectory(s.params.cloth, whole.trajectories[i], t);
      EXPECT_NEAR((sim.ballAt(i).position - expected.position).norm(), 0, kSampleTolerance_m)
          << "ball " << s.ids[i] << " at t = " << t;
      EXPECT_EQ(sim.pocketed(i), whole.trajectories[i].back().pocketed &&
                                     whole.trajectories[i].back().start_time_s <= t);
    }
  }
  EXPECT_EQ(sim.events().size(), whole.events.size());
}

TEST(ShotSimulation, AdvancingBackInTimeIsRefused) {
  const Start s = startOf("three-cushion-bank");
  ShotSimulation sim(s.params, s.table, s.balls, s.ids);
  sim.advanceTo(0.5);
  try {
    sim.advanceTo(0.25);
    FAIL() << "advancing back was accepted";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("0.25"), std::string::npos) << e.what();
  }
  EXPECT_THROW(sim.advanceTo(std::nan("")), std::invalid_argument);
  EXPECT_EQ(sim.time(), 0.5);
}

// Bad input is refused when the simulation is made, as simulate() refuses it.
TEST(ShotSimulation, BadInputIsRefusedAtTheStart) {
  Start s = startOf("three-cushion-bank");
  s.balls[1].position = s.balls[0].position;  // two balls in one place
  EXPECT_THROW(ShotSimulation(s.params, s.table, s.balls, s.ids), std::invalid_argument);
}

// The event budget counts as simulate()'s does: stepping fails where the run fails, with the same
// message, having resolved at most max_events events.
TEST(ShotSimulation, TheEventBudgetStopsSteppingWhereItStopsARun) {
  Start s = startOf("9-ball-break");
  s.params.max_events = 30;
  std::string run_message, step_message;
  try {
    simulate(s.params, s.table, s.balls, s.ids);
  } catch (const std::runtime_error& e) {
    run_message = e.what();
  }
  ShotSimulation sim(s.params, s.table, s.balls, s.ids);
  long resolved = 0;
  try {
    while (sim.step()) ++resolved;
  } catch (const std::runtime_error& e) {
    step_message = e.what();
  }
  EXPECT_NE(run_message.find("max_events = 30"), std::string::npos) << run_message;
  EXPECT_EQ(step_message, run_message);
  EXPECT_GT(resolved, 0);
  EXPECT_LE(resolved, s.params.max_events);
}

}  // namespace
}  // namespace baize::engine
