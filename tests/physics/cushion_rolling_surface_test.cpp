// Tests of the rolling balls' cushion table: its answers lie within its promise (1e-8 V0) of the
// exact solver at its tightest tolerance, it answers rolling balls only and only inside its plane,
// mirror images get mirror answers to the bit, answers scale with V0, each parameter set has its
// own table, and threads answering at once get the answers of one thread.
#include "physics/cushion_rolling_surface.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <random>
#include <thread>
#include <vector>

#include "physics/cushion_exact_solver.h"
#include "tests/physics/cushion_test_support.h"

namespace baize::physics {
namespace {

using test::degrees;
using test::mirrored;
using test::velocityDifference;

CushionParams poolCushion() { return test::poolTableCushion(); }

BallVelocity rolling(const CushionParams& p, double speed, double alpha, double sidespin_k) {
  return incomingBall(speed, alpha, speed / p.radius_m, sidespin_k * speed / p.radius_m);
}

BallVelocity exactAnswer(const CushionParams& p, const BallVelocity& in) {
  ExactSolverOptions reference;
  reference.tolerance = 1e-14;
  return solveCushionImpactExact(p, in, reference).after;
}

TEST(CushionRollingSurface, AnswersRollingBallsWithinItsPromise) {
  const CushionParams p = poolCushion();
  CushionRollingSurface& table = rollingSurfaceFor(p);
  std::mt19937_64 generator(7);
  std::uniform_real_distribution<double> speed(0.2, 3), alpha(degrees(2), degrees(178)),
      side(-1.5, 1.5);
  for (int i = 0; i < 24; ++i) {
    const BallVelocity in = rolling(p, speed(generator), alpha(generator), side(generator));
    const std::optional<BallVelocity> answer = table.answer(in);
    ASSERT_TRUE(answer.has_value()) << "impact " << i;
    const double v0 = std::hypot(in.v.x(), in.v.y());
    EXPECT_LE(velocityDifference(*answer, exactAnswer(p, in), p.radius_m),
              kRollingTablePromise * v0)
        << "impact " << i;
    EXPECT_EQ(answer->v.z(), 0.0);
  }
  const RollingSurfaceStats stats = table.stats();
  EXPECT_GT(stats.cells_kept, 0);
  EXPECT_GE(stats.cells_built, stats.cells_kept + stats.cells_to_exact);
  EXPECT_GE(stats.exact_solves,
            stats.cells_built * CushionRollingSurface::kNodes * CushionRollingSurface::kNodes);
}

TEST(CushionRollingSurface, LeavesOtherBallsToTheExactSolver) {
  const CushionParams p = poolCushion();
  CushionRollingSurface& table = rollingSurfaceFor(p);
  const double speed = 1.2;
  // Sliding (stun: no spin; half topspin), grazing, and sidespin beyond the plane.
  EXPECT_FALSE(table.answer(incomingBall(speed, degrees(60), 0, 0)).has_value());
  EXPECT_FALSE(table.answer(incomingBall(speed, degrees(60), 0.5 * speed / p.radius_m, 0)));
  EXPECT_FALSE(table.answer(rolling(p, speed, degrees(0.5), 0)).has_value());
  EXPECT_FALSE(table.answer(rolling(p, speed, degrees(179.5), 0)).has_value());
  EXPECT_FALSE(table.answer(rolling(p, speed, degrees(60), 7)).has_value());
  EXPECT_FALSE(table.answer(rolling(p, speed, degrees(60), -7)).has_value());
  // An invalid ball is refused as the exact solver refuses it.
  EXPECT_THROW(table.answer(incomingBall(speed, degrees(-30), speed / p.radius_m, 0)),
               std::invalid_argument);
}

TEST(CushionRollingSurface, MirrorImagesGetMirrorAnswersToTheBit) {
  const CushionParams p = poolCushion();
  CushionRollingSurface& table = rollingSurfaceFor(p);
  for (const double side : {0.0, 0.4, -0.9}) {
    const BallVelocity in = rolling(p, 1.3, degrees(70), side);
    const std::optional<BallVelocity> a = table.answer(in), b = table.answer(mirrored(in));
    ASSERT_TRUE(a && b);
    const BallVelocity image = mirrored(*a);
    EXPECT_EQ(image.v, b->v) << side;
    EXPECT_EQ(image.w, b->w) << side;
  }
}

TEST(CushionRollingSurface, AnswersScaleWithTheIncomingSpeed) {
  const CushionParams p = poolCushion();
  CushionRollingSurface& table = rollingSurfaceFor(p);
  const std::optional<BallVelocity> slow = table.answer(rolling(p, 0.5, degrees(40), 0.3));
  const std::optional<BallVelocity> fast = table.answer(rolling(p, 2.0, degrees(40), 0.3));
  ASSERT_TRUE(slow && fast);
  BallVelocity scaled;
  scaled.v = 4 * slow->v;
  scaled.w = 4 * slow->w;
  EXPECT_LE(velocityDifference(*fast, scaled, p.radius_m), 1e-14);
}

TEST(CushionRollingSurface, EachParameterSetHasItsOwnTable) {
  CushionParams p = poolCushion();
  CushionParams lively = p;
  lively.restitution = 0.9;
  lively.cushion_friction = 0.2;
  EXPECT_EQ(&rollingSurfaceFor(p), &rollingSurfaceFor(poolCushion()));
  EXPECT_NE(&rollingSurfaceFor(p), &rollingSurfaceFor(lively));
  const BallVelocity in = rolling(lively, 1.5, degrees(80), 0.2);
  const std::optional<BallVelocity> answer = rollingSurfaceFor(lively).answer(in);
  ASSERT_TRUE(answer.has_value());
  EXPECT_LE(velocityDifference(*answer, exactAnswer(lively, in), lively.radius_m),
            kRollingTablePromise * 1.5);
  CushionParams bad = p;
  bad.restitution = 2;
  EXPECT_THROW(rollingSurfaceFor(bad), std::invalid_argument);
}

// Threads that race to build the same cells while others read them get, to the bit, what one
// thread gets from a surface of its own.
TEST(CushionRollingSurface, ThreadsAnsweringAtOnceGetTheAnswersOfOneThread) {
  const CushionParams p = poolCushion();
  std::mt19937_64 generator(11);
  // A few root cells' worth of the plane, so the threads meet in the same cells.
  std::uniform_real_distribution<double> speed(0.5, 2), alpha(degrees(80), degrees(100)),
      side(-0.4, 0.4);
  std::vector<BallVelocity> impacts;
  for (int i = 0; i < 64; ++i)
    impacts.push_back(rolling(p, speed(generator), alpha(generator), side(generator)));
  CushionRollingSurface alone(p);
  std::vector<std::optional<BallVelocity>> expected;
  for (const BallVelocity& in : impacts) expected.push_back(alone.answer(in));

  constexpr int kThreads = 4;
  CushionRollingSurface shared(p);
  std::vector<std::vector<std::optional<BallVelocity>>> answers(
      kThreads, std::vector<std::optional<BallVelocity>>(impacts.size()));
  std::vector<std::thread> threads;
  for (int t = 0; t < kThreads; ++t) {
    threads.emplace_back([&, t] {
      for (std::size_t k = 0; k < impacts.size(); ++k) {
        const std::size_t i = (k * (2 * t + 1) + 7 * t) % impacts.size();  // each its own order
        answers[t][i] = shared.answer(impacts[i]);
      }
    });
  }
  for (std::thread& thread : threads) thread.join();
  int answered = 0;
  for (int t = 0; t < kThreads; ++t) {
    for (std::size_t i = 0; i < impacts.size(); ++i) {
      ASSERT_EQ(answers[t][i].has_value(), expected[i].has_value())
          << "thread " << t << " impact " << i;
      if (!expected[i]) continue;
      ++answered;
      EXPECT_EQ(answers[t][i]->v, expected[i]->v) << "thread " << t << " impact " << i;
      EXPECT_EQ(answers[t][i]->w, expected[i]->w) << "thread " << t << " impact " << i;
    }
  }
  // Most of these rolling impacts lie in kept cells (a few in cells left to the exact solver).
  constexpr double kLeastShareAnswered = 0.75;
  EXPECT_GT(answered, kLeastShareAnswered * kThreads * impacts.size());
  EXPECT_EQ(shared.stats().cells_built, alone.stats().cells_built);  // each cell built once
}

}  // namespace
}  // namespace baize::physics
