#include "engine/sim/cushion_solve_ahead.h"

#include <gtest/gtest.h>

#include <cfenv>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <functional>
#include <random>
#include <stdexcept>
#include <string>
#include <thread>
#include <vector>

#include "engine/io/scene.h"
#include "engine/models/model_registry.h"
#include "engine/sim/shot_simulator.h"

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

std::uint64_t oneCoreBits(const Scene& scene) { return resultBits(runScene(scene).result); }

// Whether a worker can run beside the tests at all.
bool twoCores() { return CushionImpactWorker::secondCoreAvailable(); }

// Runs `scene` (each result must be `expected`) until the worker answered one of its impacts, or
// for at most kPatience: where the worker can run at all it gets a core sooner or later, even
// while other test programs keep both cores busy. Whether it answered one.
constexpr auto kPatience = std::chrono::seconds(10);
bool runUntilAnImpactIsTakenAhead(CushionImpactWorker& worker, const Scene& scene,
                                  std::uint64_t expected) {
  const long taken_before = worker.impactsTakenAhead();
  const auto start = std::chrono::steady_clock::now();
  while (worker.impactsTakenAhead() == taken_before &&
         std::chrono::steady_clock::now() - start < kPatience) {
    worker.wake();
    EXPECT_EQ(resultBits(runScene(scene, false, &worker).result), expected) << scene.source;
  }
  return worker.impactsTakenAhead() > taken_before;
}

// Runs `attempt` (waking the worker first, when `wake`) once, and again while none of its shots
// held the worker, where it can run, for at most kPatience. Whether a shot held it.
bool repeatUntilServed(CushionImpactWorker& worker, const std::function<void()>& attempt,
                       bool wake = true) {
  const auto start = std::chrono::steady_clock::now();
  for (;;) {
    if (wake) worker.wake();
    const long served_before = worker.shotsServed();
    attempt();
    if (worker.shotsServed() > served_before) return true;
    if (!twoCores() || std::chrono::steady_clock::now() - start >= kPatience) return false;
  }
}

// Runs `scene` `runs` times with the worker on, each result `expected`; where the worker can run,
// some impact is answered ahead (in those runs, or in more within kPatience).
void expectTheSameBitsWithImpactsTakenAhead(const Scene& scene, std::uint64_t expected, int runs) {
  CushionImpactWorker worker;
  worker.wake();
  const long taken_before = worker.impactsTakenAhead();
  for (int run = 0; run < runs; ++run)
    EXPECT_EQ(resultBits(runScene(scene, false, &worker).result), expected);
  if (twoCores()) {
    EXPECT_TRUE(worker.impactsTakenAhead() > taken_before ||
                runUntilAnImpactIsTakenAhead(worker, scene, expected));
  }
}

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
  // More with BAIZE_SOLVE_AHEAD_SHOTS=N (a longer check by hand).
  long variations = 60;
  if (const char* more = std::getenv("BAIZE_SOLVE_AHEAD_SHOTS")) {
    char* end = nullptr;
    variations = std::strtol(more, &end, 10);
    if (*more == '\0' || *end != '\0' || variations < 0 || variations > 10000000) {
      throw std::invalid_argument("BAIZE_SOLVE_AHEAD_SHOTS = \"" + std::string(more) +
                                  "\" is not allowed: it must be a whole number of shots in "
                                  "[0, 10000000]");
    }
  }
  for (long k = 0; k < variations; ++k) {
    Scene s = shippedScene(k % 3 == 0   ? "9-ball-break"
                           : k % 3 == 1 ? "8-ball-break"
                                        : "snooker-break-off");
    s.shot.speed_mps = uniform(3, 12);
    s.shot.heading_rad += uniform(-0.05, 0.05);
    const double offset = uniform(0, 0.45), angle = uniform(-M_PI, M_PI);
    s.shot.side_offset = offset * std::cos(angle);
    s.shot.height_offset = offset * std::sin(angle);
    scenes.push_back(s);
  }
  return scenes;
}

TEST(CushionSolveAhead, ResultsAreTheSameBitForBitWithAndWithoutTheWorker) {
  const std::vector<Scene> scenes = manyBallScenes();
  std::vector<std::uint64_t> alone;
  for (const Scene& scene : scenes) alone.push_back(oneCoreBits(scene));
  CushionImpactWorker worker;
  worker.wake();
  const long taken_before = worker.impactsTakenAhead();
  for (int run = 0; run < 2; ++run) {  // the worker's share differs from run to run
    for (std::size_t k = 0; k < scenes.size(); ++k) {
      EXPECT_EQ(resultBits(runScene(scenes[k], false, &worker).result), alone[k])
          << scenes[k].source << " (speed " << scenes[k].shot.speed_mps << " m/s), run " << run;
    }
  }
  // Not vacuous: where the worker can run, it answers impacts of these shots (how many depends on
  // what else runs on the machine); where it cannot, none.
  if (twoCores()) {
    EXPECT_TRUE(worker.impactsTakenAhead() > taken_before ||
                runUntilAnImpactIsTakenAhead(worker, scenes[0], alone[0]));
  } else {
    EXPECT_EQ(worker.impactsTakenAhead(), taken_before);
  }
}

// The worker solves in the loop's floating-point environment (here: rounding upwards).
TEST(CushionSolveAhead, TheWorkerSolvesInTheCallersRoundingMode) {
  const Scene scene = shippedScene("9-ball-break");
  const int saved = std::fegetround();
  ASSERT_EQ(std::fesetround(FE_UPWARD), 0);
  const std::uint64_t alone = oneCoreBits(scene);
  expectTheSameBitsWithImpactsTakenAhead(scene, alone, 20);
  std::fesetround(saved);
  EXPECT_NE(alone, oneCoreBits(scene));  // the rounding mode mattered
}

TEST(CushionSolveAhead, TheMathavan2010PaperSchemeIsSolvedAheadToTheSameBits) {
  Scene scene = shippedScene("9-ball-break");
  scene.overrides.cushion = nlohmann::json{{"model", "paper"}, {"paper_steps", 500}};
  expectTheSameBitsWithImpactsTakenAhead(scene, oneCoreBits(scene), 10);
}

// Nothing is handed over to a worker the shot was not given: it serves no shot and answers no
// impact, however many shots run beside it.
TEST(CushionSolveAhead, AWorkerNotHandedOverIsNeverUsed) {
  const Scene scene = shippedScene("9-ball-break");
  CushionImpactWorker worker;
  worker.wake();
  for (int run = 0; run < 10; ++run) runScene(scene);
  EXPECT_EQ(worker.shotsServed(), 0);
  EXPECT_EQ(worker.impactsTakenAhead(), 0);
}

// Shots on several threads at once: one holds the worker at a time, the others solve their own
// impacts, and every result is the one-core result.
TEST(CushionSolveAhead, ShotsOnSeveralThreadsAtOnceGiveTheOneCoreResults) {
  const std::vector<Scene> scenes = manyBallScenes();
  std::vector<std::uint64_t> expected;
  for (const Scene& scene : scenes) expected.push_back(oneCoreBits(scene));
  CushionImpactWorker worker;
  constexpr int kThreads = 3;
  std::vector<int> mismatches(kThreads, 0);
  // Again while the worker served none of them (the machine may be busy).
  const bool served = repeatUntilServed(worker, [&] {
    std::vector<std::thread> threads;
    for (int t = 0; t < kThreads; ++t) {
      threads.emplace_back([&, t] {
        for (std::size_t k = 0; k < scenes.size(); ++k) {
          const std::size_t s = (k + static_cast<std::size_t>(t) * 7) % scenes.size();
          if (resultBits(runScene(scenes[s], false, &worker).result) != expected[s])
            ++mismatches[t];
        }
      });
    }
    for (std::thread& thread : threads) thread.join();
  });
  for (int t = 0; t < kThreads; ++t) EXPECT_EQ(mismatches[t], 0) << "thread " << t;
  EXPECT_EQ(served, twoCores());
}

// A shot that fails (here: too few events allowed) releases the worker, and later shots get it.
TEST(CushionSolveAhead, AFailedShotReleasesTheWorker) {
  Scene failing = shippedScene("9-ball-break");
  failing.overrides.max_events = 40;
  const Scene scene = shippedScene("9-ball-break");
  const std::uint64_t alone = oneCoreBits(scene);
  CushionImpactWorker worker;
  // Until the failing shot held the worker (it may find the worker busy, asleep or on its own
  // core while other programs use the machine).
  const bool failing_shot_held_it = repeatUntilServed(
      worker, [&] { EXPECT_THROW(runScene(failing, false, &worker), std::runtime_error); });
  for (int run = 0; run < 10; ++run)
    EXPECT_EQ(resultBits(runScene(scene, false, &worker).result), alone);
  if (twoCores()) {
    EXPECT_TRUE(failing_shot_held_it);
    EXPECT_TRUE(runUntilAnImpactIsTakenAhead(worker, scene, alone));
  }
}

// The hand-over itself, without the event loop.
class HandOver : public ::testing::Test {
 protected:
  // A rolling ball meeting the cushion at an angle: the incoming state of impact k.
  static physics::BallVelocity incoming(int k) {
    const double angle = 0.2 + 0.01 * k, speed = 1.0 + 0.05 * k;
    physics::BallVelocity b;
    b.v = Eigen::Vector3d(speed * std::cos(angle), speed * std::sin(angle), 0);
    b.w = Eigen::Vector3d(-b.v.y() / 0.028575, b.v.x() / 0.028575, 3.0);
    return b;
  }
  static bool sameBits(const physics::BallVelocity& a, const physics::BallVelocity& b) {
    return std::memcmp(a.v.data(), b.v.data(), sizeof(double) * 3) == 0 &&
           std::memcmp(a.w.data(), b.w.data(), sizeof(double) * 3) == 0;
  }
  // Predicts `predicted` for ball 0, gives the worker time, then resolves `actual`; repeats
  // (within kPatience) until the worker held the shot. Returns the answer and whether it held it.
  std::pair<physics::BallVelocity, bool> handOver(const physics::BallVelocity& predicted,
                                                  const physics::BallVelocity& actual) {
    physics::BallVelocity answer;
    const bool held = repeatUntilServed(worker_, [&] {
      std::this_thread::sleep_for(std::chrono::microseconds(200));
      CushionSolveAhead ahead(params_, 1, &worker_);
      ahead.predict(0, 1.0, predicted);
      std::this_thread::sleep_for(std::chrono::milliseconds(1));
      answer = ahead.resolve(0, actual);
    });
    return {answer, held};
  }
  CushionImpactWorker worker_;
  SimulationParams params_ = poolSimulationParams();
};

TEST_F(HandOver, TheWorkersAnswerIsTakenForTheSameInput) {
  // Until the worker's answer was taken (on a busy machine it may not have solved it in time).
  bool taken_ahead = false;
  const auto start = std::chrono::steady_clock::now();
  while (!taken_ahead && twoCores() && std::chrono::steady_clock::now() - start < kPatience) {
    const long taken = worker_.impactsTakenAhead();
    const auto [answer, held] = handOver(incoming(1), incoming(1));
    EXPECT_TRUE(sameBits(answer, params_.cushion->resolve(params_, incoming(1))));
    if (twoCores()) {
      ASSERT_TRUE(held);
    }
    taken_ahead = worker_.impactsTakenAhead() == taken + 1;
  }
  EXPECT_EQ(taken_ahead, twoCores());
}

TEST_F(HandOver, AnotherInputIsSolvedByTheLoop) {
  const long taken = worker_.impactsTakenAhead();
  physics::BallVelocity actual = incoming(1);
  actual.v.x() = std::nextafter(actual.v.x(), 2.0);  // one bit off the prediction
  const auto [answer, held] = handOver(incoming(1), actual);
  EXPECT_TRUE(sameBits(answer, params_.cushion->resolve(params_, actual)));
  EXPECT_FALSE(sameBits(answer, params_.cushion->resolve(params_, incoming(1))));
  if (twoCores()) {
    ASSERT_TRUE(held);
  }
  EXPECT_EQ(worker_.impactsTakenAhead(), taken);
}

TEST_F(HandOver, AnImpactTheModelRefusesFailsInTheLoopWithTheModelsError) {
  physics::BallVelocity away = incoming(1);
  away.v.y() = -away.v.y();  // moving away from the cushion: the model refuses it
  std::string loop_message;
  try {
    params_.cushion->resolve(params_, away);
  } catch (const std::invalid_argument& e) {
    loop_message = e.what();
  }
  ASSERT_FALSE(loop_message.empty());
  // Handed over (the worker's solve fails), then resolved: the model's own error, every time.
  const bool held = repeatUntilServed(worker_, [&] {
    CushionSolveAhead ahead(params_, 1, &worker_);
    ahead.predict(0, 1.0, away);
    std::this_thread::sleep_for(std::chrono::milliseconds(1));
    std::string message;
    try {
      ahead.resolve(0, away);
    } catch (const std::invalid_argument& e) {
      message = e.what();
    }
    EXPECT_EQ(message, loop_message);
  });
  EXPECT_EQ(held, twoCores());
}

TEST_F(HandOver, MorePredictionsThanJobsAreSolvedByTheLoop) {
  constexpr int kBalls = 150;  // more than the worker's jobs
  const bool held = repeatUntilServed(worker_, [&] {
    CushionSolveAhead ahead(params_, kBalls, &worker_);
    for (int k = 0; k < kBalls; ++k) ahead.predict(k, 1.0 + k, incoming(k));
    for (int k = 0; k < kBalls; ++k) {
      EXPECT_TRUE(
          sameBits(ahead.resolve(k, incoming(k)), params_.cushion->resolve(params_, incoming(k))))
          << "ball " << k;
    }
  });
  EXPECT_EQ(held, twoCores());
}

// When shots use the worker: run back to back (after the first, it is awake for the next), not
// on their own (it is asleep by then, and a shot never waits for it to wake).
TEST(CushionSolveAheadPolicy, ShotsOnTheirOwnDoNotUseTheWorkerAndShotsBackToBackDo) {
  const Scene scene = shippedScene("9-ball-break");
  CushionImpactWorker worker;
  for (int shot = 0; shot < 5; ++shot) {
    // Fifty times its awake time: on a busy machine the worker may wait long for a core to notice
    // that its time is up and fall asleep.
    std::this_thread::sleep_for(std::chrono::milliseconds(100));
    runScene(scene, false, &worker);
  }
  EXPECT_EQ(worker.shotsServed(), 0);
  const bool served = repeatUntilServed(
      worker,
      [&] {
        for (int shot = 0; shot < 20; ++shot) runScene(scene, false, &worker);
      },
      /*wake=*/false);
  EXPECT_EQ(served, twoCores());
}

}  // namespace
}  // namespace baize::engine
