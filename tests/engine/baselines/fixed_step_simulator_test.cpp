#include "engine/baselines/fixed_step_simulator.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "engine/io/scene.h"
#include "engine/io/table.h"
#include "engine/models/model_registry.h"
#include "tests/engine/error_test_support.h"

namespace baize::engine {
namespace {

using physics::BallState;

// Energy may "grow" by rounding only: a few ulps of the total, relative.
constexpr double kEnergyRounding = 1e-12;
// A lone ball stepped in pieces ends where the closed form puts it up to the rounding of a few
// hundred thousand additions of positions of order 1 m, m.
constexpr double kPiecewiseRounding_m = 1e-9;
// First order means the error falls about tenfold per tenfold smaller step; the phase of each
// contact within its step scatters that, so a mean over several shots must fall at least this much.
constexpr double kFirstOrderMinRatio = 3.0;
// Positions of a ball at rest on the table, m: push-out leaves a ball exactly at the cushion, so
// only rounding may put its centre closer to the cushion than R.
constexpr double kOnTableRounding_m = 1e-9;

BallState ballAt(double x, double y, double vx = 0, double vy = 0) {
  BallState b;
  b.position = {x, y};
  b.velocity = {vx, vy, 0};
  return b;
}

double totalEnergy(const SimulationParams& p, const std::vector<BallRecord>& balls) {
  double sum = 0;
  for (const BallRecord& b : balls)
    if (!b.pocketed) sum += physics::specificKineticEnergy(p.cloth, b.state);
  return sum;
}

// Largest final-position distance between two results' balls (both must agree on pockets).
double finalPositionError(const SimulationResult& a, const SimulationResult& b) {
  double worst = 0;
  EXPECT_EQ(a.final_balls.size(), b.final_balls.size());
  for (std::size_t i = 0; i < a.final_balls.size(); ++i) {
    EXPECT_EQ(a.final_balls[i].pocketed, b.final_balls[i].pocketed) << "ball " << i;
    worst =
        std::max(worst, (a.final_balls[i].state.position - b.final_balls[i].state.position).norm());
  }
  return worst;
}

// Two-ball cut shots on a pocketless table: the cue ball slides into an object ball at several cut
// offsets, both then roll into cushions.
std::vector<std::vector<BallState>> twoBallShots() {
  std::vector<std::vector<BallState>> shots;
  for (double offset_m : {0.0, 0.011, 0.023, 0.034, 0.046}) {
    BallState cue = ballAt(-0.7, -0.05, 1.8, 0.1);
    cue.angular_velocity = {0, -10, 3};  // some draw and side
    shots.push_back({cue, ballAt(0, offset_m)});
  }
  return shots;
}

// One ball with spin around a pocketless table: several cushion impacts in the cushion model.
std::vector<std::vector<BallState>> cushionShots() {
  std::vector<std::vector<BallState>> shots;
  for (double angle_rad : {0.3, 0.55, 0.8, 1.05, 1.3}) {
    BallState b = ballAt(-0.4, -0.2, 2.5 * std::cos(angle_rad), 2.5 * std::sin(angle_rad));
    b.angular_velocity = {20, -40, 60};
    shots.push_back({b});
  }
  return shots;
}

// Mean over shots of the largest final-position error against the event loop at each step.
std::vector<double> meanErrors(const std::vector<std::vector<BallState>>& shots,
                               const std::vector<double>& steps_s) {
  const SimulationParams p = poolSimulationParams();
  const TableGeometry table = rectangularTable(2.54, 1.27);
  std::vector<double> errors(steps_s.size(), 0.0);
  for (const auto& shot : shots) {
    const SimulationResult reference = simulate(p, table, shot);
    for (std::size_t k = 0; k < steps_s.size(); ++k)
      errors[k] += finalPositionError(simulateFixedStep(p, table, shot, steps_s[k]), reference) /
                   static_cast<double>(shots.size());
  }
  return errors;
}

TEST(FixedStepSimulator, LoneBallEndsWhereTheClosedFormSays) {
  const SimulationParams p = poolSimulationParams();
  BallState b = ballAt(-3, 0, 1.2, 0.3);
  b.angular_velocity = {5, 30, 40};
  const TableGeometry table = rectangularTable(20, 10);  // never reached
  const SimulationResult reference = simulate(p, table, {b});
  const SimulationResult stepped = simulateFixedStep(p, table, {b}, 1e-4);
  EXPECT_LT(finalPositionError(stepped, reference), kPiecewiseRounding_m);
  EXPECT_NEAR(stepped.end_time_s, reference.end_time_s, 1e-4);  // within one step
}

TEST(FixedStepSimulator, TwoBallErrorFallsAboutFirstOrderWithTheStep) {
  const std::vector<double> errors = meanErrors(twoBallShots(), {1e-3, 1e-4, 1e-5});
  EXPECT_GT(errors[0], 0);
  EXPECT_GT(errors[0] / errors[1], kFirstOrderMinRatio) << errors[0] << " " << errors[1];
  EXPECT_GT(errors[1] / errors[2], kFirstOrderMinRatio) << errors[1] << " " << errors[2];
}

TEST(FixedStepSimulator, CushionErrorFallsAboutFirstOrderWithTheStep) {
  const std::vector<double> errors = meanErrors(cushionShots(), {1e-3, 1e-4, 1e-5});
  EXPECT_GT(errors[0], 0);
  EXPECT_GT(errors[0] / errors[1], kFirstOrderMinRatio) << errors[0] << " " << errors[1];
  EXPECT_GT(errors[1] / errors[2], kFirstOrderMinRatio) << errors[1] << " " << errors[2];
}

// The 9-ball break at a coarse and a fine step: energy never grows from one step to the next, no
// ball leaves the table, and every ball still on it ends at least R inside every cushion.
TEST(FixedStepSimulator, BreakKeepsEnergyFallingAndEveryBallOnTheTable) {
  const Scene scene = loadScene(assetsDirectory() + "/scenes/9-ball-break.json");
  const SimulationParams p = simulationParamsFor(scene);
  const TableGeometry table = geometryOf(scene.table);
  const double R = p.ball.radius_m;
  std::vector<BallState> balls;
  const SceneRun reference = runScene(scene);
  for (const PlacedBall& placed : scene.balls)
    balls.push_back(ballAt(placed.position_m.x(), placed.position_m.y()));
  balls[0].velocity = reference.strike.ball.v;
  balls[0].angular_velocity = reference.strike.ball.w;
  // Beyond the playing area by more than the pockets reach: off the table, m.
  const double off_x = scene.table.length_m / 2 + 0.15, off_y = scene.table.width_m / 2 + 0.15;
  for (double dt : {1e-2, 1e-3}) {
    double energy = totalEnergy(p, {});
    bool first = true;
    long steps = 0;
    const SimulationResult r =
        simulateFixedStep(p, table, balls, dt, [&](double, const std::vector<BallRecord>& now) {
          const double e = totalEnergy(p, now);
          if (!first) {
            EXPECT_LE(e, energy * (1 + kEnergyRounding)) << "dt " << dt << " step " << steps;
          }
          first = false;
          energy = e;
          ++steps;
          for (const BallRecord& b : now) {
            if (b.pocketed) continue;
            EXPECT_LT(std::abs(b.state.position.x()), off_x);
            EXPECT_LT(std::abs(b.state.position.y()), off_y);
          }
        });
    EXPECT_GT(steps, 100);
    for (const BallRecord& b : r.final_balls) {
      if (b.pocketed) continue;
      EXPECT_LE(std::abs(b.state.position.x()), scene.table.length_m / 2 - R + kOnTableRounding_m);
      EXPECT_LE(std::abs(b.state.position.y()), scene.table.width_m / 2 - R + kOnTableRounding_m);
      EXPECT_EQ(physics::motionState(p.cloth, b.state), physics::MotionState::Stationary);
    }
  }
}

TEST(FixedStepSimulator, SameInputGivesTheSameOutputBitForBit) {
  const auto shots = twoBallShots();
  const SimulationParams p = poolSimulationParams();
  const TableGeometry table = rectangularTable(2.54, 1.27);
  const SimulationResult a = simulateFixedStep(p, table, shots[2], 1e-3);
  const SimulationResult b = simulateFixedStep(p, table, shots[2], 1e-3);
  ASSERT_EQ(a.events.size(), b.events.size());
  for (std::size_t i = 0; i < a.final_balls.size(); ++i) {
    EXPECT_EQ(a.final_balls[i].state.position.x(), b.final_balls[i].state.position.x());
    EXPECT_EQ(a.final_balls[i].state.position.y(), b.final_balls[i].state.position.y());
  }
  EXPECT_EQ(a.end_time_s, b.end_time_s);
}

// Impacts go through the event loop's models: a head-on hit of equal balls with Newton's
// restitution e leaves the struck ball with (1 + e)/2 of the speed.
TEST(FixedStepSimulator, HeadOnHitUsesTheBallBallModel) {
  SimulationParams p = poolSimulationParams();
  const TableGeometry table = rectangularTable(20, 10);
  const SimulationResult r =
      simulateFixedStep(p, table, {ballAt(-0.2, 0, 1, 0), ballAt(0, 0)}, 1e-5);
  const Event* hit = nullptr;
  for (const Event& e : r.events)
    if (e.kind == EventKind::BallBall && hit == nullptr) hit = &e;
  ASSERT_NE(hit, nullptr);
  const double v_in = hit->before[0].velocity.x();
  EXPECT_NEAR(hit->after[1].velocity.x(),
              (1 + p.ball_ball->rigidContact(p, 0).restitution) / 2 * v_in, 1e-12);
}

TEST(FixedStepSimulator, RejectsBadStepsAndBadBalls) {
  const SimulationParams p = poolSimulationParams();
  const TableGeometry table = rectangularTable(2.54, 1.27);
  EXPECT_MENTIONS(invalidArgumentMessage([&] { simulateFixedStep(p, table, {ballAt(0, 0)}, 0); }),
                  "fixed time step");
  EXPECT_MENTIONS(invalidArgumentMessage([&] { simulateFixedStep(p, table, {ballAt(0, 0)}, NAN); }),
                  "fixed time step");
  EXPECT_MENTIONS(invalidArgumentMessage([&] {
                    simulateFixedStep(p, table, {ballAt(0, 0), ballAt(0.01, 0)}, 1e-3);
                  }),
                  "overlaps");
  EXPECT_MENTIONS(
      invalidArgumentMessage([&] { simulateFixedStep(p, table, {ballAt(1.27, 0)}, 1e-3); }),
      "beyond cushion");
}

}  // namespace
}  // namespace baize::engine
