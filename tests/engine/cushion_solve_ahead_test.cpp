#include "engine/cushion_solve_ahead.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <cstring>
#include <random>
#include <string>
#include <thread>
#include <vector>

#include "engine/scene.h"

namespace baize::engine {
namespace {

// Every bit of a result: each event's time, kind, balls, contact and states before and after, the
// final states, and the prediction counts (FNV-1a over the bytes).
std::uint64_t resultBits(const SimulationResult& result) {
  std::uint64_t hash = 1469598103934665603ULL;
  auto mixBytes = [&](const void* data, std::size_t size) {
    const auto* bytes = static_cast<const unsigned char*>(data);
    for (std::size_t k = 0; k < size; ++k) {
      hash ^= bytes[k];
      hash *= 1099511628211ULL;
    }
  };
  auto mixState = [&](const physics::BallState& s) {
    mixBytes(s.position.data(), sizeof(double) * 2);
    mixBytes(s.velocity.data(), sizeof(double) * 3);
    mixBytes(s.angular_velocity.data(), sizeof(double) * 3);
  };
  for (const Event& e : result.events) {
    mixBytes(&e.time_s, sizeof e.time_s);
    const int ids[4] = {static_cast<int>(e.kind), e.ball, e.other, e.index};
    mixBytes(ids, sizeof ids);
    for (const physics::BallState& s : e.before) mixState(s);
    for (const physics::BallState& s : e.after) mixState(s);
  }
  for (const BallRecord& b : result.final_balls) {
    mixState(b.state);
    const int where[2] = {b.pocketed ? 1 : 0, b.pocket};
    mixBytes(where, sizeof where);
  }
  const long counts[2] = {result.predictions, result.skipped_predictions};
  mixBytes(counts, sizeof counts);
  return hash;
}

// Restores the helper's setting when a test ends, whatever it set.
class HelperSetting {
 public:
  HelperSetting() : saved_(CushionSolveAhead::enabled()) {}
  ~HelperSetting() { CushionSolveAhead::setEnabled(saved_); }

 private:
  bool saved_;
};

Scene shippedScene(const std::string& name) {
  return loadScene(assetsDirectory() + "/scenes/" + name + ".json");
}

// The shipped breaks and other many-ball scenes, and seeded variations of the breaks' strikes
// (speed, heading, tip offsets), which send balls into jaws and pockets in many ways.
std::vector<Scene> manyBallScenes() {
  std::vector<Scene> scenes;
  for (const char* name : {"9-ball-break", "8-ball-break", "snooker-break-off",
                           "three-cushion-bank", "heavy-sidespin", "one-ball-among-100"})
    scenes.push_back(shippedScene(name));
  std::mt19937_64 random(20261121);
  auto uniform = [&](double lo, double hi) {
    return lo + (hi - lo) * ((random() >> 11) * 0x1.0p-53);
  };
  for (int k = 0; k < 24; ++k) {
    Scene s = shippedScene(k % 2 == 0 ? "9-ball-break" : "8-ball-break");
    s.shot.speed_mps = uniform(3, 12);
    s.shot.heading_rad += uniform(-0.05, 0.05);
    const double offset = uniform(0, 0.45), angle = uniform(-M_PI, M_PI);
    s.shot.side_offset = offset * std::cos(angle);
    s.shot.height_offset = offset * std::sin(angle);
    scenes.push_back(s);
  }
  return scenes;
}

TEST(CushionSolveAhead, ResultsAreTheSameBitForBitWithAndWithoutTheHelper) {
  HelperSetting restore;
  const long taken_before = CushionSolveAhead::impactsTakenAhead();
  for (const Scene& scene : manyBallScenes()) {
    CushionSolveAhead::setEnabled(false);
    const std::uint64_t alone = resultBits(runScene(scene).result);
    CushionSolveAhead::setEnabled(true);
    for (int run = 0; run < 3; ++run) {  // the helper's share differs from run to run
      EXPECT_EQ(resultBits(runScene(scene).result), alone)
          << scene.source << " (speed " << scene.shot.speed_mps << " m/s), run " << run;
    }
  }
  // Not vacuous: the helper answered some of those impacts (none on a one-core machine).
  if (std::thread::hardware_concurrency() >= 2) {
    EXPECT_GT(CushionSolveAhead::impactsTakenAhead(), taken_before);
  } else {
    EXPECT_EQ(CushionSolveAhead::impactsTakenAhead(), taken_before);
  }
}

TEST(CushionSolveAhead, TheSeedPaperSchemeIsSolvedAheadToTheSameBits) {
  HelperSetting restore;
  Scene scene = shippedScene("9-ball-break");
  scene.overrides.cushion_model = CushionModelChoice::SeedPaper;
  scene.overrides.paper_steps = 500;
  CushionSolveAhead::setEnabled(false);
  const std::uint64_t alone = resultBits(runScene(scene).result);
  CushionSolveAhead::setEnabled(true);
  EXPECT_EQ(resultBits(runScene(scene).result), alone);
}

TEST(CushionSolveAhead, TurnedOffItIsNeverUsed) {
  HelperSetting restore;
  CushionSolveAhead::setEnabled(false);
  const Scene scene = shippedScene("9-ball-break");
  const long before = CushionSolveAhead::impactsTakenAhead();
  for (int run = 0; run < 10; ++run) runScene(scene);
  EXPECT_EQ(CushionSolveAhead::impactsTakenAhead(), before);
}

// Shots on several threads at once: one holds the helper at a time, the others solve their own
// impacts, and every result is the one-core result.
TEST(CushionSolveAhead, ShotsOnSeveralThreadsAtOnceGiveTheOneCoreResults) {
  HelperSetting restore;
  const std::vector<Scene> scenes = manyBallScenes();
  CushionSolveAhead::setEnabled(false);
  std::vector<std::uint64_t> expected;
  for (const Scene& scene : scenes) expected.push_back(resultBits(runScene(scene).result));
  CushionSolveAhead::setEnabled(true);
  constexpr int kThreads = 3;
  std::vector<int> mismatches(kThreads, 0);
  std::vector<std::thread> threads;
  for (int t = 0; t < kThreads; ++t) {
    threads.emplace_back([&, t] {
      for (std::size_t k = 0; k < scenes.size(); ++k) {
        const std::size_t s = (k + static_cast<std::size_t>(t) * 7) % scenes.size();
        if (resultBits(runScene(scenes[s]).result) != expected[s]) ++mismatches[t];
      }
    });
  }
  for (std::thread& thread : threads) thread.join();
  for (int t = 0; t < kThreads; ++t) EXPECT_EQ(mismatches[t], 0) << "thread " << t;
}

// A shot that fails (here: too few events allowed) releases the helper, and the next shot gets it.
TEST(CushionSolveAhead, AFailedShotReleasesTheHelper) {
  HelperSetting restore;
  CushionSolveAhead::setEnabled(true);
  Scene failing = shippedScene("9-ball-break");
  failing.overrides.max_events = 40;
  EXPECT_THROW(runScene(failing), std::runtime_error);
  const Scene scene = shippedScene("9-ball-break");
  CushionSolveAhead::setEnabled(false);
  const std::uint64_t alone = resultBits(runScene(scene).result);
  CushionSolveAhead::setEnabled(true);
  const long before = CushionSolveAhead::impactsTakenAhead();
  EXPECT_EQ(resultBits(runScene(scene).result), alone);
  if (std::thread::hardware_concurrency() >= 2) {
    // Timing decides how many impacts the helper answers; over enough breaks some are.
    for (int run = 0; run < 200 && CushionSolveAhead::impactsTakenAhead() == before; ++run)
      runScene(scene);
    EXPECT_GT(CushionSolveAhead::impactsTakenAhead(), before);
  }
}

}  // namespace
}  // namespace baize::engine
