#include "engine/sim/shot_simulator.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <random>
#include <string>

#include "engine/io/ball_set.h"
#include "engine/io/rack.h"
#include "engine/io/table.h"
#include "engine/models/model_registry.h"
#include "engine/sim/contact_geometry.h"

namespace baize::engine {
namespace {

using physics::BallState;
using ::testing::HasSubstr;

// Closed-form distances and velocities through the whole loop: rounding of a few operations.
constexpr double kClosedFormRelative = 1e-12;
// The exact cushion solver's accuracy at its default tolerance, relative to the speed.
constexpr double kCushionAccuracy = 1e-9;
// Positions of touching balls and of balls at a cushion are located by polynomial roots: to
// rounding.
constexpr double kContactTolerance_m = 1e-9;

BallState ballAt(double x, double y, double vx = 0, double vy = 0) {
  BallState b;
  b.position = {x, y};
  b.velocity = {vx, vy, 0};
  return b;
}

double energy(const physics::ClothParams& cloth, const BallState& b) {
  return physics::specificKineticEnergy(cloth, b);
}

// The invariants every event keeps: nothing gains energy, and colliding balls touch at 2R. Returns
// how many ball-ball events there were.
int expectEventInvariants(const SimulationParams& p, const SimulationResult& r) {
  const double R = p.ball.radius_m;
  int collisions = 0;
  for (const Event& e : r.events) {
    double before = 0, after = 0;
    for (const BallState& b : e.before) before += energy(p.cloth, b);
    for (const BallState& b : e.after) after += energy(p.cloth, b);
    EXPECT_LE(after, before * (1 + 1e-12) + 1e-15) << eventKindName(e.kind) << " at " << e.time_s;
    if (e.kind == EventKind::BallBall) {
      ++collisions;
      EXPECT_NEAR((e.before[0].position - e.before[1].position).norm(), 2 * R, kContactTolerance_m);
    }
  }
  return collisions;
}

// A ball struck without spin slides, rolls on at 5/7 of its speed after 12 v^2 / (49 mu_s g), and
// stops after another (5/7 v)^2 / (2 mu_r g).
TEST(ShotSimulator, StunShotSlidesRollsAndStopsWhereTheClosedFormSays) {
  const SimulationParams p = poolSimulationParams();
  const double v0 = 1.5, g = p.cloth.gravity_mps2;
  const SimulationResult r = simulate(p, rectangularTable(20, 10), {ballAt(-5, 0, v0, 0)});
  ASSERT_EQ(r.events.size(), 2u);
  EXPECT_EQ(r.events[0].kind, EventKind::StateChange);
  EXPECT_NEAR(r.events[0].after[0].velocity.x(), 5.0 / 7 * v0, kClosedFormRelative * v0);
  const double sliding = 12 * v0 * v0 / (49 * p.cloth.sliding_friction * g);
  EXPECT_NEAR(r.events[0].after[0].position.x(), -5 + sliding, kClosedFormRelative * 10);
  const double v1 = 5.0 / 7 * v0, rolling = v1 * v1 / (2 * p.cloth.rolling_friction * g);
  EXPECT_NEAR(r.final_balls[0].state.position.x(), -5 + sliding + rolling,
              kClosedFormRelative * 10);
  EXPECT_NEAR(r.final_balls[0].state.position.y(), 0, kClosedFormRelative);
  EXPECT_EQ(r.final_balls[0].state.velocity.norm(), 0);
}

// A rolling ball meeting a cushion head-on gets exactly what the Mathavan 2010 model gives, in that
// cushion's frame: for the right-hand cushion (inward normal -x) local y is +x and local x is -y,
// so v_table = (v_y', -v_x') and w_table = (w_y', -w_x', w_z').
TEST(ShotSimulator, HeadOnCushionHitEqualsTheCushionModelCalledDirectly) {
  const SimulationParams p = poolSimulationParams();
  const double R = p.ball.radius_m;
  BallState ball = ballAt(0.5, 0, 1.2, 0);
  ball.angular_velocity = {0, 1.2 / R, 0};  // rolling along +x: v + R z x w = 0
  const SimulationResult r = simulate(p, rectangularTable(2.0, 1.0), {ball});
  const auto hit = std::find_if(r.events.begin(), r.events.end(),
                                [](const Event& e) { return e.kind == EventKind::Cushion; });
  ASSERT_NE(hit, r.events.end());
  EXPECT_EQ(hit->index, 1);
  const BallState& before = hit->before[0];
  EXPECT_NEAR(before.position.x(), 1.0 - R, kContactTolerance_m);
  const double V = before.velocity.x();
  const physics::BallVelocity model =
      p.cushion->resolve(p, physics::incomingBall(V, M_PI / 2, V / R, 0));
  const BallState& after = hit->after[0];
  EXPECT_NEAR(after.velocity.x(), model.v.y(), kCushionAccuracy * V);
  EXPECT_NEAR(after.velocity.y(), -model.v.x(), kCushionAccuracy * V);
  EXPECT_NEAR(after.angular_velocity.x(), model.w.y(), kCushionAccuracy * V / R);
  EXPECT_NEAR(after.angular_velocity.y(), -model.w.x(), kCushionAccuracy * V / R);
  EXPECT_LT(after.velocity.x(), 0) << "it comes back";
}

// Two balls: the collision is found at a centre distance of exactly 2R, and a frictionless head-on
// hit with e = 1 hands the whole velocity over (equal masses).
TEST(ShotSimulator, HeadOnBallHitHappensAtTouchingDistanceAndExchangesVelocities) {
  SimulationParams p = poolSimulationParams();
  p.ball_ball = ballBallModels().read(
      JsonReader({{"restitution", 1}, {"friction_law", "constant"}, {"constant_friction", 0}},
                 "test"),
      ModelDefaults{});
  const double R = p.ball.radius_m;
  const SimulationResult r =
      simulate(p, rectangularTable(20, 10), {ballAt(-2, 0, 2, 0), ballAt(0, 0)});
  const auto hit = std::find_if(r.events.begin(), r.events.end(),
                                [](const Event& e) { return e.kind == EventKind::BallBall; });
  ASSERT_NE(hit, r.events.end());
  EXPECT_NEAR((hit->before[0].position - hit->before[1].position).norm(), 2 * R,
              kContactTolerance_m);
  EXPECT_NEAR(hit->after[0].velocity.x(), 0, 1e-12);
  EXPECT_NEAR(hit->after[1].velocity.x(), hit->before[0].velocity.x(), 1e-12);
}

// The 30-degree rule through the whole loop: a rolling cue ball cutting a frictionless, elastic
// object ball at a half-ball hit (cut angle phi = 30 deg) leaves along the tangent line and then,
// once its topspin has pulled it round (sliding on the cloth along a fixed slip direction), rolls
// at theta from its first line with tan theta = sin phi cos phi / (sin^2 phi + 2/5): 33.67 deg.
TEST(ShotSimulator, ThirtyDegreeRuleHoldsThroughTheWholeLoop) {
  SimulationParams p = poolSimulationParams();
  p.ball_ball = ballBallModels().read(
      JsonReader({{"restitution", 1}, {"friction_law", "constant"}, {"constant_friction", 0}},
                 "test"),
      ModelDefaults{});
  const double R = p.ball.radius_m, v0 = 1.5;
  BallState cue = ballAt(-1, R, v0, 0);   // offset by R from the object ball's line: half-ball
  cue.angular_velocity = {0, v0 / R, 0};  // natural roll along +x
  const SimulationResult r = simulate(p, rectangularTable(20, 10), {cue, ballAt(0, 0)});
  const auto hit = std::find_if(r.events.begin(), r.events.end(),
                                [](const Event& e) { return e.kind == EventKind::BallBall; });
  ASSERT_NE(hit, r.events.end());
  const Eigen::Vector2d normal = (hit->before[1].position - hit->before[0].position).normalized();
  EXPECT_NEAR(std::acos(normal.x()), M_PI / 6, 1e-9);  // the cut angle is 30 deg
  // The cue ball's next event is its return to rolling.
  const auto rolls = std::find_if(hit + 1, r.events.end(), [](const Event& e) {
    return e.ball == 0 && e.kind == EventKind::StateChange;
  });
  ASSERT_NE(rolls, r.events.end());
  const Eigen::Vector3d v = rolls->after[0].velocity;
  const double phi = M_PI / 6;
  const double expected =
      std::atan(std::sin(phi) * std::cos(phi) / (std::pow(std::sin(phi), 2) + 0.4));
  EXPECT_NEAR(std::atan2(v.y(), v.x()), expected, 1e-9);
  EXPECT_NEAR(expected * 180 / M_PI, 33.67, 0.01);
}

// Random scenes of 2-4 balls on a cushioned table: at every event nothing gains energy, touching
// balls are 2R apart, and every ball ends on the table without overlapping another.
TEST(ShotSimulator, RandomScenesKeepEnergyFallingAndBallsApartAndOnTheTable) {
  SimulationParams p = poolSimulationParams();
  const double R = p.ball.radius_m, L = 2.54, W = 1.27;
  const TableGeometry table = rectangularTable(L, W);
  std::mt19937_64 engine(20261121);
  auto uniform = [&](double lo, double hi) {
    return lo + (hi - lo) * ((engine() >> 11) * 0x1.0p-53);
  };
  int collisions = 0, cushion_hits = 0;
  for (int scene = 0; scene < 60; ++scene) {
    const int n = 2 + scene % 3;
    std::vector<BallState> balls;
    while (static_cast<int>(balls.size()) < n) {
      BallState b = ballAt(uniform(-L / 2 + R, L / 2 - R), uniform(-W / 2 + R, W / 2 - R));
      bool clear = true;
      for (const BallState& o : balls) clear = clear && (o.position - b.position).norm() > 2 * R;
      if (clear) balls.push_back(b);
    }
    const double angle = uniform(0, 2 * M_PI), speed = uniform(0.5, 4);
    balls[0].velocity = {speed * std::cos(angle), speed * std::sin(angle), 0};
    balls[0].angular_velocity = {uniform(-50, 50), uniform(-50, 50), uniform(-50, 50)};
    const SimulationResult r = simulate(p, table, balls);
    collisions += expectEventInvariants(p, r);
    for (const Event& e : r.events) cushion_hits += e.kind == EventKind::Cushion;
    for (int i = 0; i < n; ++i) {
      const Eigen::Vector2d q = r.final_balls[i].state.position;
      EXPECT_LE(std::abs(q.x()), L / 2 - R + kContactTolerance_m);
      EXPECT_LE(std::abs(q.y()), W / 2 - R + kContactTolerance_m);
      for (int j = 0; j < i; ++j) {
        EXPECT_GE((q - r.final_balls[j].state.position).norm(), 2 * R - kContactTolerance_m);
      }
    }
  }
  EXPECT_GT(collisions, 10) << "the set must exercise ball-ball events";
  EXPECT_GT(cushion_hits, 50) << "the set must exercise cushion events";
}

// The scene mirrored in the x axis: y -> -y, w -> (-w_x, w_y, -w_z).
std::vector<BallState> mirrored(std::vector<BallState> balls) {
  for (BallState& b : balls) {
    b.position.y() *= -1;
    b.velocity.y() *= -1;
    b.angular_velocity.x() *= -1;
    b.angular_velocity.z() *= -1;
  }
  return balls;
}

// Mirroring the scene in the x axis mirrors the outcome.
TEST(ShotSimulator, MirrorImageScenesGiveMirrorImageResults) {
  const SimulationParams p = poolSimulationParams();
  const TableGeometry table = rectangularTable(2.54, 1.27);
  BallState cue = ballAt(-0.8, 0.1, 2.5, 0.7);
  cue.angular_velocity = {3, -20, 15};
  const std::vector<BallState> scene = {cue, ballAt(0.2, 0.25), ballAt(0.5, -0.3)};
  const SimulationResult a = simulate(p, table, scene), b = simulate(p, table, mirrored(scene));
  ASSERT_EQ(a.events.size(), b.events.size());
  for (std::size_t i = 0; i < scene.size(); ++i) {
    EXPECT_NEAR(a.final_balls[i].state.position.x(), b.final_balls[i].state.position.x(), 1e-9);
    EXPECT_NEAR(a.final_balls[i].state.position.y(), -b.final_balls[i].state.position.y(), 1e-9);
  }
}

// The same on the shipped 9 ft table, which is its own mirror image in the x axis: seeded shots
// with spin among three balls, aimed anywhere, so that jaws and pockets take part too.
TEST(ShotSimulator, MirrorImageScenesOnAPocketedTableGiveMirrorImageResults) {
  const SimulationParams p = poolSimulationParams();
  const TableGeometry table = geometryOf(builtinTable("pool-9ft"));
  std::mt19937_64 random(20261121);
  std::uniform_real_distribution<double> unit(-1, 1);
  int jaw_hits = 0, pocketed = 0;
  for (int shot = 0; shot < 40; ++shot) {
    const double heading = M_PI * unit(random), speed = 2.5 + 1.5 * unit(random);
    BallState cue = ballAt(0.9 * unit(random), 0.4 * unit(random), speed * std::cos(heading),
                           speed * std::sin(heading));
    cue.angular_velocity = {20 * unit(random), 20 * unit(random), 40 * unit(random)};
    const std::vector<BallState> scene = {cue, ballAt(0.3, 0.25), ballAt(-0.5, -0.3)};
    const SimulationResult a = simulate(p, table, scene), b = simulate(p, table, mirrored(scene));
    ASSERT_EQ(a.events.size(), b.events.size()) << "shot " << shot;
    for (std::size_t k = 0; k < a.events.size(); ++k) {
      ASSERT_EQ(a.events[k].kind, b.events[k].kind) << "shot " << shot << " event " << k;
      EXPECT_NEAR(a.events[k].time_s, b.events[k].time_s, 1e-9) << "shot " << shot;
      jaw_hits += a.events[k].kind == EventKind::Jaw;
    }
    for (std::size_t i = 0; i < scene.size(); ++i) {
      const BallRecord &x = a.final_balls[i], &y = b.final_balls[i];
      EXPECT_EQ(x.pocketed, y.pocketed) << "shot " << shot << " ball " << i;
      // Pockets are numbered counterclockwise from the bottom-left: the mirror of k is 5 - k.
      if (x.pocketed && y.pocketed) {
        EXPECT_EQ(x.pocket, 5 - y.pocket) << "shot " << shot;
      }
      EXPECT_NEAR(x.state.position.x(), y.state.position.x(), 1e-9) << "shot " << shot;
      EXPECT_NEAR(x.state.position.y(), -y.state.position.y(), 1e-9) << "shot " << shot;
      pocketed += x.pocketed;
    }
  }
  EXPECT_GT(jaw_hits, 0) << "the shots must reach the jaws";
  EXPECT_GT(pocketed, 0) << "the shots must pocket balls";
}

TEST(ShotSimulator, SameInputGivesBitIdenticalOutput) {
  const SimulationParams p = poolSimulationParams();
  const TableGeometry table = rectangularTable(2.54, 1.27);
  BallState cue = ballAt(-0.9, -0.2, 3, 1);
  cue.angular_velocity = {10, -40, 30};
  const std::vector<BallState> scene = {cue, ballAt(0.3, 0), ballAt(0.3 + 0.0572, 0.0)};
  const SimulationResult a = simulate(p, table, scene), b = simulate(p, table, scene);
  ASSERT_EQ(a.events.size(), b.events.size());
  for (std::size_t i = 0; i < a.events.size(); ++i)
    EXPECT_EQ(a.events[i].time_s, b.events[i].time_s);
  for (std::size_t i = 0; i < scene.size(); ++i) {
    EXPECT_EQ(a.final_balls[i].state.position, b.final_balls[i].state.position);
  }
}

// A ball rolling into a pocket's capture circle falls in and stops taking part.
TEST(ShotSimulator, ABallEnteringACaptureCircleIsPocketed) {
  const SimulationParams p = poolSimulationParams();
  TableGeometry table;
  table.pockets.push_back({{1.0, 0.0}, 0.03});
  const SimulationResult r = simulate(p, table, {ballAt(0, 0, 2, 0)});
  ASSERT_FALSE(r.events.empty());
  EXPECT_EQ(r.events.back().kind, EventKind::Pocket);
  EXPECT_TRUE(r.final_balls[0].pocketed);
  EXPECT_NEAR(r.events.back().before[0].position.x(), 1.0 - 0.03, kContactTolerance_m);
}

// Resting balls cost no predictions: the pairs among them are skipped.
TEST(ShotSimulator, PairsOfRestingBallsAreSkipped) {
  const SimulationParams p = poolSimulationParams();
  std::vector<BallState> balls = {ballAt(-1, 0, 0.5, 0)};
  for (int k = 0; k < 10; ++k) balls.push_back(ballAt(0.2 + 0.07 * k, 0.4));
  const SimulationResult r = simulate(p, rectangularTable(2.54, 1.27), balls);
  EXPECT_GE(r.skipped_predictions, 45) << "the 45 resting pairs, at every event";
}

// The recorded pieces reproduce every event's state: sampled at an event's time, the trajectory of
// an involved ball gives its state just after the event (the closed form from the piece's start).
TEST(ShotSimulator, TrajectoriesSampledAtEventsGiveTheEventStates) {
  SimulationParams p = poolSimulationParams();
  p.record_trajectories = true;
  BallState cue = ballAt(-0.9, -0.2, 3, 1);
  cue.angular_velocity = {10, -40, 30};
  const SimulationResult r =
      simulate(p, rectangularTable(2.54, 1.27), {cue, ballAt(0.3, 0), ballAt(0.5, 0.3)});
  ASSERT_EQ(r.trajectories.size(), 3u);
  int checked = 0;
  for (const Event& e : r.events) {
    const BallState sampled = sampleTrajectory(p.cloth, r.trajectories[e.ball], e.time_s);
    EXPECT_NEAR((sampled.position - e.after[0].position).norm(), 0, 1e-9) << eventKindName(e.kind);
    EXPECT_NEAR((sampled.velocity - e.after[0].velocity).norm(), 0, 1e-9) << eventKindName(e.kind);
    ++checked;
  }
  EXPECT_GT(checked, 5);
  for (int i = 0; i < 3; ++i) {
    const BallState end = sampleTrajectory(p.cloth, r.trajectories[i], r.end_time_s + 1);
    EXPECT_NEAR((end.position - r.final_balls[i].state.position).norm(), 0, 1e-9);
  }
  EXPECT_TRUE(
      simulate(poolSimulationParams(), rectangularTable(2.54, 1.27), {cue}).trajectories.empty())
      << "nothing recorded unless asked";
}

// A jaw is a cushion whose normal points from its centre to the ball: a ball rolling straight at a
// jaw's centre meets it head-on and gets exactly the Mathavan 2010 model's head-on result; a ball
// aimed at the part of the circle outside the jaw's angular range passes through.
TEST(ShotSimulator, AJawActsAsACushionAlongItsContactNormalWithinItsRange) {
  const SimulationParams p = poolSimulationParams();
  const double R = p.ball.radius_m, rho = 0.01;
  TableGeometry table;
  table.jaws.push_back({{1.0, 0.0}, rho, M_PI / 2, 3 * M_PI / 2});  // faces -x
  BallState ball = ballAt(0, 0, 1.5, 0);
  ball.angular_velocity = {0, 1.5 / R, 0};  // rolling
  const SimulationResult r = simulate(p, table, {ball});
  const auto hit = std::find_if(r.events.begin(), r.events.end(),
                                [](const Event& e) { return e.kind == EventKind::Jaw; });
  ASSERT_NE(hit, r.events.end());
  EXPECT_NEAR(hit->before[0].position.x(), 1.0 - rho - R, kContactTolerance_m);
  const double V = hit->before[0].velocity.x();
  const physics::BallVelocity model =
      p.cushion->resolve(p, physics::incomingBall(V, M_PI / 2, V / R, 0));
  EXPECT_NEAR(hit->after[0].velocity.x(), model.v.y(), kCushionAccuracy * V);
  TableGeometry back;
  back.jaws.push_back({{1.0, 0.0}, rho, -M_PI / 2, M_PI / 2});  // faces +x: the ball meets its back
  for (const Event& e : simulate(p, back, {ball}).events) EXPECT_NE(e.kind, EventKind::Jaw);
}

// A 9-ball break on the shipped 9 ft table with its jaws and pockets: energy never grows at an
// event, colliding balls touch at 2R, every ball ends pocketed or on the table, and the same break
// gives the same events twice.
TEST(ShotSimulator, NineBallBreakOnTheShippedTableKeepsItsInvariants) {
  const Table table = builtinTable("pool-9ft");
  const std::vector<PlacedBall> rack = placeRack("9-ball", table, builtinBallSet("pool"));
  SimulationParams p = poolSimulationParams();
  std::vector<BallState> balls;
  for (const PlacedBall& placed : rack)
    balls.push_back(ballAt(placed.position_m.x(), placed.position_m.y()));
  const Eigen::Vector2d aim = (balls[1].position - balls[0].position).normalized();
  balls[0].velocity = {8 * aim.x(), 8 * aim.y() + 0.05, 0};
  const TableGeometry geometry = geometryOf(table);
  const SimulationResult r = simulate(p, geometry, balls);
  EXPECT_GT(expectEventInvariants(p, r), 9) << "the break spreads the rack";
  for (const BallRecord& b : r.final_balls) {
    if (b.pocketed) continue;
    EXPECT_LE(std::abs(b.state.position.x()), table.length_m / 2) << "on the table";
    EXPECT_LE(std::abs(b.state.position.y()), table.width_m / 2) << "on the table";
  }
  const SimulationResult again = simulate(p, geometry, balls);
  ASSERT_EQ(again.events.size(), r.events.size());
  for (std::size_t i = 0; i < r.events.size(); ++i)
    EXPECT_EQ(again.events[i].time_s, r.events[i].time_s);
}

// contactNormal is the frame the loop resolves every cushion and jaw impact in: each impact's
// `before` ball taken into that frame and through the cushion model gives the event's `after` ball
// to the bit, over a break on the shipped table and an off-centre hit on a lone jaw (no ball there
// is also pressed into a cushion, which would add its slide along it).
TEST(ShotSimulator, ContactNormalGivesTheFrameOfEveryCushionImpact) {
  const SimulationParams p = poolSimulationParams();
  int impacts = 0, same = 0, jaws = 0;
  auto check = [&](const TableGeometry& geometry, const std::vector<BallState>& balls) {
    for (const Event& e : simulate(p, geometry, balls).events) {
      if (e.kind != EventKind::Cushion && e.kind != EventKind::Jaw) continue;
      const BallState& before = e.before[0];
      const Eigen::Vector2d normal = contactNormal(geometry, e.kind, e.index, before.position);
      EXPECT_NEAR(normal.norm(), 1, 1e-15);
      const ContactFrame frame(normal);
      const physics::BallVelocity local = frame.toLocal(before);
      if (!(local.v.y() > 0)) continue;
      ++impacts;
      jaws += e.kind == EventKind::Jaw;
      BallState expected = before;
      frame.toTable(p.cushion->resolve(p, local), &expected);
      same += expected.velocity == e.after[0].velocity &&
              expected.angular_velocity == e.after[0].angular_velocity;
    }
  };
  const Table table = builtinTable("pool-9ft");
  std::vector<BallState> rack;
  for (const PlacedBall& placed : placeRack("9-ball", table, builtinBallSet("pool")))
    rack.push_back(ballAt(placed.position_m.x(), placed.position_m.y()));
  const Eigen::Vector2d aim = (rack[1].position - rack[0].position).normalized();
  rack[0].velocity = {8 * aim.x(), 8 * aim.y() + 0.05, 0};
  check(geometryOf(table), rack);
  TableGeometry jaw;
  jaw.jaws.push_back({{1.0, 0.0}, 0.01, M_PI / 2, 3 * M_PI / 2});  // faces -x
  BallState ball = ballAt(0, 0.02, 1.5, 0);
  ball.angular_velocity = {0, 1.5 / p.ball.radius_m, 0};  // rolling
  check(jaw, {ball});
  EXPECT_GE(impacts, 10) << "the break meets the cushions";
  EXPECT_GE(jaws, 1) << "the lone jaw is met";
  EXPECT_EQ(same, impacts) << same << " of " << impacts << " impacts reproduced";
}

// Regression (found by `baize stress`, seed 1, shot 7432): a ball at a few um/s that came to rest a
// rounding before its predicted state change kept the stale prediction, and the loop then asked for
// an infinite advance. The shot must simply end.
TEST(ShotSimulator, ABallComingToRestARoundingEarlyIsPredictedAgain) {
  const SimulationParams p = poolSimulationParams();
  BallState slow = ballAt(0.13630586533558975, 0.08167873891585165, -2.931591838660267e-06,
                          4.2454690169681203e-07);
  slow.angular_velocity = {0.00016771138277724617, 0.00025576591871533967, 9.194526899686229e-05};
  const std::vector<BallState> balls = {slow, ballAt(0.07974588202057716, 0.08986963553377428),
                                        ballAt(-0.40104131914652197, -0.2756166797827408)};
  const SimulationResult r = simulate(p, rectangularTable(2.54, 1.27), balls);
  for (const BallRecord& b : r.final_balls) EXPECT_EQ(b.state.velocity.norm(), 0);
}

// Sustained contact. Ball A at rest with topspin (slip u0) touches ball B: A's cloth friction
// presses it into B, which it pushes ahead. With frictionless ball-ball contact the lasting contact
// has a closed form: B rolls under the contact force N (a_B = 5/7 N/m - mu_r g), A slides
// (a_A = mu_s g - N/m); equal accelerations give a = (5 mu_s - 7 mu_r) g / 12 until A's slip,
// closing at (5/2 mu_s g + a), is gone at t* = u0 / (5/2 mu_s g + a); then both roll at v* = a t*.
// The event loop keeps the contact as a train of small bounces (kSustainedContactSpeed_mps), whose
// impulses average to N: B's speed after the push must match v*, and nothing may overlap.
TEST(ShotSimulator, ABallPushedByASpinningBallMovesAsTheLastingContactSays) {
  SimulationParams p = poolSimulationParams();
  p.ball_ball = ballBallModels().read(
      JsonReader({{"friction_law", "constant"}, {"constant_friction", 0}}, "test"),
      ModelDefaults{});
  p.cloth.rolling_friction = 1e-4;  // small, so that B's sliding spells barely matter (see below)
  p.record_trajectories = true;
  const double R = p.ball.radius_m, g = p.cloth.gravity_mps2, mu = p.cloth.sliding_friction;
  const double u0 = 1.0;  // m/s
  BallState a = ballAt(0, 0), b = ballAt(2 * R, 0);
  a.angular_velocity = {0, u0 / R, 0};  // contact point moving -x: friction drives A along +x
  const SimulationResult r = simulate(p, rectangularTable(40, 4), {a, b});
  expectEventInvariants(p, r);
  EXPECT_LT(r.events.size(), 2000u) << "the push must not take a Zeno sequence of events";

  const double accel = (5 * mu - 7 * p.cloth.rolling_friction) * g / 12;
  const double t_end = u0 / (2.5 * mu * g + accel), v_end = accel * t_end;
  // After the push both roll; sample B a little later, allowing for its rolling loss meanwhile.
  const double t_sample = 1.5 * t_end;
  const BallState b_later = sampleTrajectory(p.cloth, r.trajectories[1], t_sample);
  const double expected = v_end - p.cloth.rolling_friction * g * (t_sample - t_end);
  // Tolerance: B slides for a moment after each bounce and misses its rolling resistance then (a
  // share of order 7 mu_r / (5 mu_s) of the acceleration), and the bounce train ripples.
  EXPECT_NEAR(b_later.velocity.x(), expected, 0.01 * expected);
  // Never apart by more than the train's ripple, never overlapping, while the push lasts.
  for (double t = 0; t < t_end; t += 1e-4) {
    const double gap = (sampleTrajectory(p.cloth, r.trajectories[1], t).position -
                        sampleTrajectory(p.cloth, r.trajectories[0], t).position)
                           .norm() -
                       2 * R;
    ASSERT_GE(gap, -kContactTolerance_m) << "at t = " << t;
    ASSERT_LE(gap, 1e-6) << "at t = " << t;
  }
}

// A ball sliding along a cushion with spin that presses it into the cushion stays on the table,
// touches the cushion no closer than R, and comes to rest in a bounded number of events.
TEST(ShotSimulator, ABallPressedIntoACushionSlidesAlongItAndStops) {
  SimulationParams p = poolSimulationParams();
  p.record_trajectories = true;
  const double R = p.ball.radius_m, L = 2.54, W = 1.27;
  BallState ball = ballAt(L / 2 - R, 0, 0, 1.0);  // against the +x cushion, moving along it
  ball.angular_velocity = {0, 20.0, 5.0};         // w_y > 0: friction drives it along +x
  const SimulationResult r = simulate(p, rectangularTable(L, W), {ball});
  expectEventInvariants(p, r);
  int cushion_hits = 0;
  for (const Event& e : r.events) cushion_hits += e.kind == EventKind::Cushion;
  EXPECT_GT(cushion_hits, 10) << "the scene must press the ball into the cushion";
  EXPECT_LT(r.events.size(), 5000u);
  for (double t = 0; t < r.end_time_s; t += 1e-3) {
    const BallState s = sampleTrajectory(p.cloth, r.trajectories[0], t);
    ASSERT_LE(s.position.x(), L / 2 - R + kContactTolerance_m) << "at t = " << t;
  }
}

TEST(ShotSimulator, BadScenesAreRejectedWithTheValue) {
  const SimulationParams p = poolSimulationParams();
  const TableGeometry table = rectangularTable(2.54, 1.27);
  auto message = [&](const std::vector<BallState>& balls) {
    try {
      simulate(p, table, balls);
    } catch (const std::invalid_argument& e) {
      return std::string(e.what());
    }
    return std::string("accepted");
  };
  EXPECT_THAT(message({ballAt(0, 0), ballAt(0.03, 0)}), HasSubstr("ball 1 overlaps ball 0"));
  EXPECT_THAT(message({ballAt(1.27, 0)}), HasSubstr("beyond cushion"));
  EXPECT_THAT(message({ballAt(std::nan(""), 0)}), HasSubstr("ball 0"));
  // Regression (found by fuzzing): a ball far outside the table, where no cushion lies across its
  // normal, was accepted; a ball beyond a corner's diagonal likewise.
  EXPECT_THAT(message({ballAt(0, 0), ballAt(0x1p1017, 0x1p964)}),
              HasSubstr("ball 1 is off the table: its x (m) = "));
  EXPECT_THAT(message({ballAt(0.3, -5)}), HasSubstr("ball 0 is off the table: its y (m) = -5"));
  EXPECT_THAT(message({ballAt(1.5, 0.8)}), HasSubstr("off the table"));
  // Regression (found by fuzzing): a ball touching a cushion with w_z = -5.7e250 rad/s was
  // accepted, and the cloth motion, with no precision left at that spin, moved it through the
  // cushion; speeds and spins beyond the impact models' bounds (cushion_model.h) are refused.
  BallState spinning = ballAt(0, -1.27 / 2 + 0.028575);
  spinning.angular_velocity = {99.7, -839.9, -5.7277780524766055e+250};
  EXPECT_THAT(message({spinning}), HasSubstr("ball 0 angular velocity w_z (rad/s) = "));
  spinning.angular_velocity.z() = 2 * physics::kMaxBallSpin_radps;
  EXPECT_THAT(message({ballAt(0, 0), spinning}), HasSubstr("ball 1 angular velocity w_z"));
  BallState fast = ballAt(0, 0);
  fast.velocity.x() = -2 * physics::kMaxBallSpeed_mps;
  EXPECT_THAT(message({fast}), HasSubstr("ball 0 velocity v_x (m/s) = "));
  SimulationParams wrong = p;
  wrong.cloth.radius_m = 0.03;
  EXPECT_THROW(simulate(wrong, table, {ballAt(0, 0)}), std::invalid_argument);
}

// Given the balls' ids, every refusal names the ball by id instead of by number.
TEST(ShotSimulator, RefusalsNameBallsByIdWhenGiven) {
  const SimulationParams p = poolSimulationParams();
  const TableGeometry table = rectangularTable(2.54, 1.27);
  auto message = [&](const std::vector<BallState>& balls, const std::vector<std::string>& ids) {
    try {
      simulate(p, table, balls, ids);
    } catch (const std::invalid_argument& e) {
      return std::string(e.what());
    }
    return std::string("accepted");
  };
  BallState fast = ballAt(0.5, 0);
  fast.velocity.x() = 1064.79;
  EXPECT_THAT(message({ballAt(0, 0), fast}, {"1", "cue"}),
              HasSubstr("ball 'cue' velocity v_x (m/s) = 1064.79 is not allowed"));
  EXPECT_THAT(message({ballAt(0, 0), fast}, {}), HasSubstr("ball 1 velocity v_x (m/s) = 1064.79"));
  EXPECT_THAT(message({ballAt(0, 0), ballAt(0.03, 0)}, {"cue", "9"}),
              HasSubstr("ball '9' overlaps ball 'cue'"));
  EXPECT_THAT(message({ballAt(1.27, 0)}, {"cue"}), HasSubstr("ball 'cue' is beyond cushion"));
  EXPECT_THAT(message({ballAt(0, 0)}, {"cue", "1"}), HasSubstr("number of ball ids = 2"));
}

// A ball that runs between a pocket's facings without entering its capture circle (a geometry made
// directly, which no scene's table passes: checkCapturesCoverOpenings) leaves the table; the shot
// fails naming the ball, where and when, instead of returning a result with the ball far away.
TEST(ShotSimulator, ABallLeavingTheTableFailsTheShotNamingTheBall) {
  const SimulationParams p = poolSimulationParams();
  const Table table = builtinTable("pool-9ft");
  const double speed_mps = 3, heading_rad = M_PI / 4;
  // From [0.9, 0.3] at 45 degrees into the +x +y corner pocket (number 3).
  const BallState cue =
      ballAt(0.9, 0.3, speed_mps * std::cos(heading_rad), speed_mps * std::sin(heading_rad));
  const BallState resting = ballAt(0, 0);
  TableGeometry geometry = geometryOf(table);
  const SimulationResult caught = simulate(p, geometry, {resting, cue});
  ASSERT_TRUE(caught.final_balls[1].pocketed);
  EXPECT_EQ(caught.final_balls[1].pocket, 3);

  geometry.pockets[3].centre_m += 0.5 * table.pockets[3].axis;  // capture_offset_m 0.045 -> 0.545
  auto leaves = [&](const std::vector<std::string>& ids) {
    try {
      simulate(p, geometry, {resting, cue}, ids);
    } catch (const BallLeftTableError& e) {
      return std::string(e.what());
    }
    return std::string("no error");
  };
  const std::string message = leaves({"1", "cue"});
  EXPECT_THAT(message, HasSubstr("ball 'cue' left the table: at t = "));
  EXPECT_THAT(message, HasSubstr("outside the table's cushion outline"));
  EXPECT_THAT(leaves({}), HasSubstr("ball 1 left the table"));
  // The position it names is off the table, beyond the +x +y corner.
  const std::size_t at = message.find("its centre [");
  ASSERT_NE(at, std::string::npos) << message;
  const std::string numbers = message.substr(at + std::strlen("its centre ["));
  const double x = std::stod(numbers), y = std::stod(numbers.substr(numbers.find(", ") + 2));
  EXPECT_FALSE(insideOutline(geometry.outline, {x, y}));
  EXPECT_GT(x, table.length_m / 2);
  EXPECT_GT(y, table.width_m / 2);

  // Without the outline (not checked), the same shot "succeeds" with the ball off the table: the
  // guard is what turns this into an error.
  geometry.outline.clear();
  const SimulationResult escaped = simulate(p, geometry, {resting, cue});
  EXPECT_FALSE(escaped.final_balls[1].pocketed);
  EXPECT_FALSE(insideOutline(geometryOf(table).outline, escaped.final_balls[1].state.position));
}

// What validation says of a set of balls: its message, or "accepted".
std::string verdict(const SimulationParams& p, const TableGeometry& table,
                    const std::vector<BallState>& balls) {
  try {
    validateSimulationInput(p, table, balls);
  } catch (const std::invalid_argument& e) {
    return e.what();
  }
  return "accepted";
}

// A crowd of resting balls around the table's middle, in rows kCrowdSpacing_m apart (well over a
// diameter): enough balls for validation to take its shortcut for balls far from every cushion.
constexpr double kCrowdSpacing_m = 0.1;
std::vector<BallState> crowdAroundTheMiddle(int columns, int rows) {
  std::vector<BallState> crowd;
  for (int c = 0; c < columns; ++c)
    for (int r = 0; r < rows; ++r)
      crowd.push_back(ballAt(kCrowdSpacing_m * (c - 0.5 * (columns - 1)),
                             kCrowdSpacing_m * (r - 0.5 * (rows - 1))));
  return crowd;
}

// A probe ball's verdict must not depend on how many other balls there are: alone (every cushion
// and jaw checked for it) and as ball 0 of a crowd (which lets validation skip those checks for
// balls in a safe interior), it is rejected with the same message or accepted, on every built-in
// table. Probes lie just either side of where a cushion or a jaw begins to reject a ball, and at
// random all over the table.
TEST(ShotSimulator, ABallNearACushionOrJawGetsTheSameVerdictAloneAndInACrowd) {
  const SimulationParams p = poolSimulationParams();
  const double R = p.ball.radius_m;
  // Offsets (m) from the rejection boundary: below the 1e-9 m contact slack, and just beyond the
  // margins (1e-6 m) a shortcut near the boundary might use.
  const double offsets_m[] = {-1e-5, -2e-6, -1e-6, -1e-8, 0, 1e-8, 1e-6, 2e-6, 1e-5};
  const std::vector<BallState> crowd = crowdAroundTheMiddle(7, 5);
  const double clear_m = 1e-3;  // a crowd ball this much farther than 2R from the probe: no overlap
  std::mt19937 random(7);
  for (const std::string& name : builtinTableNames()) {
    const Table built_in = builtinTable(name);
    const TableGeometry table = geometryOf(built_in);
    std::vector<Eigen::Vector2d> probes;
    for (const CushionSegment& c : table.cushions) {
      for (double s : {0.0, 0.02, 0.5, 0.98, 1.0}) {  // along the cushion
        for (double offset : offsets_m)
          probes.push_back(c.start_m + s * (c.end_m - c.start_m) + (R + offset) * c.inward_normal);
      }
    }
    for (const JawArc& jaw : table.jaws) {
      for (double f : {0.0, 0.5, 1.0}) {  // across its angular range
        const double angle = jaw.start_angle_rad + f * (jaw.end_angle_rad - jaw.start_angle_rad);
        for (double offset : offsets_m) {
          probes.push_back(jaw.centre_m + (jaw.radius_m + R + offset) *
                                              Eigen::Vector2d(std::cos(angle), std::sin(angle)));
        }
      }
    }
    std::uniform_real_distribution<double> x(-0.6 * built_in.length_m, 0.6 * built_in.length_m);
    std::uniform_real_distribution<double> y(-0.6 * built_in.width_m, 0.6 * built_in.width_m);
    for (int k = 0; k < 2000; ++k) probes.push_back({x(random), y(random)});
    int rejected = 0, accepted = 0;
    for (const Eigen::Vector2d& q : probes) {
      std::vector<BallState> alone = {ballAt(q.x(), q.y())};
      std::vector<BallState> crowded = alone;
      for (const BallState& b : crowd)
        if ((b.position - q).norm() > 2 * R + clear_m) crowded.push_back(b);
      ASSERT_GE(crowded.size(), 30u) << "a crowd";
      const std::string expected = verdict(p, table, alone);
      EXPECT_EQ(verdict(p, table, crowded), expected) << name << " at " << q.transpose();
      ++(expected == "accepted" ? accepted : rejected);
    }
    EXPECT_GT(rejected, 100) << name;
    EXPECT_GT(accepted, 100) << name;
  }
}

// The same in closed form on one table: a ball R - 1 um in front of a straight cushion's middle is
// beyond it, one R + 1 um in front is accepted; a ball 1 um closer to a jaw's centre than its
// radius plus R, within its range, is inside it; so many balls are all checked.
TEST(ShotSimulator, BallsJustBeyondACushionOrInsideAJawAreRejectedInACrowd) {
  const SimulationParams p = poolSimulationParams();
  const double R = p.ball.radius_m, step_m = 1e-6;
  const TableGeometry table = geometryOf(builtinTable("pool-9ft"));
  std::vector<BallState> balls = crowdAroundTheMiddle(7, 5);
  for (std::size_t k = 0; k < table.cushions.size(); ++k) {
    const CushionSegment& c = table.cushions[k];
    const Eigen::Vector2d middle = 0.5 * (c.start_m + c.end_m);
    std::vector<BallState> near = balls;
    const Eigen::Vector2d inside = middle + (R + step_m) * c.inward_normal;
    near.push_back(ballAt(inside.x(), inside.y()));
    EXPECT_EQ(verdict(p, table, near), "accepted") << "cushion " << k;
    const Eigen::Vector2d beyond = middle + (R - step_m) * c.inward_normal;
    near.back() = ballAt(beyond.x(), beyond.y());
    EXPECT_THAT(verdict(p, table, near), HasSubstr("ball " + std::to_string(balls.size()) +
                                                   " is beyond cushion " + std::to_string(k)));
  }
  for (std::size_t k = 0; k < table.jaws.size(); ++k) {
    const JawArc& jaw = table.jaws[k];
    const double angle = 0.5 * (jaw.start_angle_rad + jaw.end_angle_rad);
    std::vector<BallState> near = balls;
    const Eigen::Vector2d q = jaw.centre_m + (jaw.radius_m + R - step_m) *
                                                 Eigen::Vector2d(std::cos(angle), std::sin(angle));
    near.push_back(ballAt(q.x(), q.y()));
    EXPECT_THAT(verdict(p, table, near), HasSubstr("ball " + std::to_string(balls.size()) +
                                                   " is inside jaw " + std::to_string(k)));
  }
}

// Resting balls the shot never reaches change nothing: the cue ball's events and end are the same,
// bit for bit, with and without a crowd of them, and the crowd stays where it was. The shot runs
// along the table's long axis between two rows of balls, off the cushions and back; other shots
// strike ball 1, placed along that axis, so that balls start moving and stop among the crowd.
TEST(ShotSimulator, ACrowdOfRestingBallsTheShotNeverReachesChangesNothing) {
  const SimulationParams p = poolSimulationParams();
  const double R = p.ball.radius_m;
  const TableGeometry table = geometryOf(builtinTable("pool-9ft"));
  std::vector<BallState> crowd;
  for (int c = 0; c < 10; ++c) {
    for (double y : {-0.45, -0.3, -0.15, 0.15, 0.3, 0.45})
      crowd.push_back(ballAt(-1.0 + 0.2222 * c, y));
  }
  const BallState cue = ballAt(-1.1, 0, 2.5, 0);  // no spin: every ball stays on y = 0
  std::vector<std::vector<BallState>> shots = {{cue}};
  for (int k = 0; k <= 8; ++k) shots.push_back({cue, ballAt(-0.7 + 0.05 * k, 0)});  // straight on
  for (const std::vector<BallState>& shot : shots) {
    std::vector<BallState> crowded = shot;
    crowded.insert(crowded.end(), crowd.begin(), crowd.end());
    const SimulationResult few = simulate(p, table, shot);
    const SimulationResult many = simulate(p, table, crowded);
    ASSERT_EQ(many.events.size(), few.events.size());
    for (std::size_t e = 0; e < few.events.size(); ++e) {
      EXPECT_EQ(many.events[e].time_s, few.events[e].time_s);
      EXPECT_EQ(many.events[e].kind, few.events[e].kind);
      EXPECT_EQ(many.events[e].ball, few.events[e].ball);
      EXPECT_EQ(many.events[e].other, few.events[e].other);
      EXPECT_EQ(many.events[e].index, few.events[e].index);
      ASSERT_EQ(many.events[e].after.size(), few.events[e].after.size());
      for (std::size_t b = 0; b < few.events[e].after.size(); ++b) {
        EXPECT_EQ(many.events[e].after[b].position, few.events[e].after[b].position);
        EXPECT_EQ(many.events[e].after[b].velocity, few.events[e].after[b].velocity);
        EXPECT_EQ(many.events[e].after[b].angular_velocity,
                  few.events[e].after[b].angular_velocity);
      }
    }
    for (std::size_t i = 0; i < shot.size(); ++i) {
      EXPECT_EQ(many.final_balls[i].state.position, few.final_balls[i].state.position);
      EXPECT_EQ(many.final_balls[i].pocketed, few.final_balls[i].pocketed);
    }
    for (std::size_t i = shot.size(); i < crowded.size(); ++i)
      EXPECT_EQ(many.final_balls[i].state.position, crowded[i].position) << "ball " << i;
    EXPECT_GE(many.skipped_predictions - few.skipped_predictions,
              static_cast<long>(crowd.size() * (crowd.size() - 1) / 2))
        << "the crowd's pairs are skipped";
    // The premise: the moving balls stay more than 2R in y from the nearest rows (at |y| = 0.15).
    double closest = 1e9;
    for (const Event& e : few.events)
      for (const BallState& b : e.before)
        closest = std::min(closest, 0.15 - std::abs(b.position.y()));
    EXPECT_GT(closest, 2 * R) << "the shot never touches the rows";
  }
}

// A ball that has come to rest is still there to be hit: ball 1 rolls a mm and stops, ball 0,
// rolling the other way, comes off the end cushion after that and strikes it along the same line
// (among a crowd of resting balls that neither reaches), and ball 1 moves off again.
TEST(ShotSimulator, ABallThatCameToRestIsStillHit) {
  const SimulationParams p = poolSimulationParams();
  const TableGeometry table = geometryOf(builtinTable("pool-9ft"));
  std::vector<BallState> balls = {ballAt(-0.8, 0, -2.0, 0), ballAt(-0.2, 0, 0.02, 0)};
  for (int c = 0; c < 10; ++c) {
    for (double y : {-0.3, 0.3}) balls.push_back(ballAt(-1.0 + 0.2222 * c, y));
  }
  const SimulationResult r = simulate(p, table, balls);
  double stopped_s = -1, struck_s = -1, cushion_s = -1;
  for (const Event& e : r.events) {
    if (e.kind == EventKind::Cushion && e.ball == 0 && cushion_s < 0) cushion_s = e.time_s;
    if (e.kind == EventKind::StateChange && e.ball == 1 && e.after[0].velocity.isZero(0) &&
        stopped_s < 0)
      stopped_s = e.time_s;
    if (e.kind == EventKind::BallBall && e.ball == 0 && e.other == 1 && struck_s < 0)
      struck_s = e.time_s;
  }
  ASSERT_GT(stopped_s, 0) << "ball 1 stops";
  EXPECT_GT(cushion_s, stopped_s) << "before ball 0 comes off the cushion";
  EXPECT_GT(struck_s, cushion_s) << "and is struck afterwards";
  EXPECT_GT(r.final_balls[1].state.position.x(), -0.15) << "and moves on";
  for (std::size_t i = 2; i < balls.size(); ++i)
    EXPECT_EQ(r.final_balls[i].state.position, balls[i].position) << "ball " << i;
}

TEST(ShotSimulator, AShotThatNeedsTooManyEventsStopsWithAnError) {
  SimulationParams p = poolSimulationParams();
  p.max_events = 3;
  try {
    simulate(p, rectangularTable(2.54, 1.27), {ballAt(0, 0, 3, 0.5)});
    ADD_FAILURE() << "no error";
  } catch (const std::runtime_error& e) {
    EXPECT_THAT(e.what(), HasSubstr("max_events = 3"));
  }
}

}  // namespace
}  // namespace baize::engine
