#include "physics/cloth_motion.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>
#include <random>
#include <stdexcept>
#include <string>
#include <vector>

#include "tests/physics/fp_trap_support.h"
#include "tests/physics/rejection_test_support.h"

namespace baize::physics {
namespace {

using Eigen::Vector2d;
using Eigen::Vector3d;
using test::expectRejected;

// Closed-form values against the formulas they come from: a few dozen roundings of the inputs.
constexpr double kRoundingRelative = 1e-13;
// Specific energy may rise by rounding only (relative to the starting energy).
constexpr double kEnergyRoundingRelative = 1e-13;
// Within one state the exact motion is a quadratic in t, which RK4 integrates exactly: only the
// rounding of its steps remains (relative to the speeds and distances involved).
constexpr double kRk4WithinStateRelative = 1e-11;

constexpr double kInfinity = std::numeric_limits<double>::infinity();

BallState makeBall(const Vector2d& position, const Vector3d& velocity,
                   const Vector3d& angular_velocity) {
  BallState ball;
  ball.position = position;
  ball.velocity = velocity;
  ball.angular_velocity = angular_velocity;
  return ball;
}

Vector2d planar(const Vector3d& a) { return a.head<2>(); }

// w x z for the spin w: the direction a spin sends the ball once the cloth grips.
Vector2d crossZ(const Vector3d& w) { return {w.y(), -w.x()}; }

// A ball rolling with velocity v (no slip): w_xy = z x v / R.
Vector3d rollingSpin(const ClothParams& params, const Vector2d& v, double spin_z) {
  return {-v.y() / params.radius_m, v.x() / params.radius_m, spin_z};
}

std::vector<ClothParams> bothCloths() { return {poolCloth(), snookerCloth()}; }

// ---- Closed-form values -------------------------------------------------------------------------

TEST(ClothMotionTest, StunShotRollsOnAtFiveSeventhsAfterSliding12v2Over49MuG) {
  for (const ClothParams& params : bothCloths()) {
    const double mu_g = params.sliding_friction * params.gravity_mps2;
    for (double speed : {0.3, 1.0, 2.5, 6.0}) {
      for (double heading : {0.0, 0.7, 2.0, -2.9}) {
        const Vector2d direction(std::cos(heading), std::sin(heading));
        const Vector2d start(0.4, -0.2);
        const BallState stun =
            makeBall(start, {speed * direction.x(), speed * direction.y(), 0}, Vector3d::Zero());
        ASSERT_EQ(motionState(params, stun), MotionState::Sliding);
        const double slide_time = timeToStateChange(params, stun);
        EXPECT_NEAR(slide_time, 2 * speed / (7 * mu_g), kRoundingRelative * slide_time);

        const BallState rolling = advanceWithinState(params, stun, slide_time);
        EXPECT_EQ(motionState(params, rolling), MotionState::Rolling);
        EXPECT_NEAR(planar(rolling.velocity).norm(), 5.0 / 7.0 * speed, kRoundingRelative * speed);
        EXPECT_NEAR(planar(rolling.velocity).dot(direction), 5.0 / 7.0 * speed,
                    kRoundingRelative * speed);  // straight on
        const double slide_distance = 12 * speed * speed / (49 * mu_g);
        EXPECT_NEAR((rolling.position - start).norm(), slide_distance,
                    kRoundingRelative * slide_distance);
        EXPECT_NEAR((rolling.position - start).dot(direction), slide_distance,
                    kRoundingRelative * slide_distance);
        // Rolling exactly: the slip is zero to rounding, the spin locked to the velocity.
        EXPECT_LE(contactSlip(params, rolling).norm(), kRoundingRelative * speed);
      }
    }
  }
}

TEST(ClothMotionTest, VelocityAtRollingIsFiveSeventhsV0PlusTwoSeventhsRWCrossZForAnyMuS) {
  std::mt19937_64 rng(21);
  std::uniform_real_distribution<double> speed(-3, 3);
  std::uniform_real_distribution<double> spin(-150, 150);
  for (int trial = 0; trial < 200; ++trial) {
    const BallState ball =
        makeBall({0, 0}, {speed(rng), speed(rng), 0}, {spin(rng), spin(rng), spin(rng)});
    const Vector2d v0 = planar(ball.velocity);
    for (double mu_s : {0.05, 0.2, 0.35, 0.9}) {
      ClothParams params = poolCloth();
      params.sliding_friction = mu_s;
      const Vector2d expected =
          5.0 / 7.0 * v0 + 2.0 / 7.0 * params.radius_m * crossZ(ball.angular_velocity);
      const double slide_time = timeToStateChange(params, ball);
      const BallState at_end = advanceWithinState(params, ball, slide_time);
      const double scale = v0.norm() + params.radius_m * ball.angular_velocity.norm();
      EXPECT_NEAR((planar(at_end.velocity) - expected).norm(), 0, kRoundingRelative * scale);
      // The exact rolling state set at the transition continues the sliding motion without a jump:
      // just before it, the sliding formulas give the same velocity and spin.
      const BallState just_before = advanceWithinState(params, ball, slide_time * (1 - 1e-9));
      const double jump_allowed =
          1e-9 * (mu_s * params.gravity_mps2 * slide_time) * 3.5 + kRoundingRelative * scale;
      EXPECT_NEAR((just_before.velocity - at_end.velocity).norm(), 0, jump_allowed);
      EXPECT_NEAR(
          params.radius_m *
              (planar(just_before.angular_velocity) - planar(at_end.angular_velocity)).norm(),
          0, jump_allowed);
    }
  }
}

TEST(ClothMotionTest, RollingBallStopsAfterVSquaredOverTwoMuRG) {
  for (const ClothParams& params : bothCloths()) {
    const double mu_r_g = params.rolling_friction * params.gravity_mps2;
    for (double speed : {0.05, 0.8, 3.0}) {
      const Vector2d v(0.6 * speed, -0.8 * speed);
      const BallState rolling = makeBall({1, 1}, {v.x(), v.y(), 0}, rollingSpin(params, v, 0));
      ASSERT_EQ(motionState(params, rolling), MotionState::Rolling);
      const double roll_time = timeToStateChange(params, rolling);
      EXPECT_NEAR(roll_time, speed / mu_r_g, kRoundingRelative * roll_time);
      // Half way: speed halved, spin still locked to it.
      const BallState half = advanceWithinState(params, rolling, roll_time / 2);
      EXPECT_NEAR(planar(half.velocity).norm(), speed / 2, kRoundingRelative * speed);
      EXPECT_LE(contactSlip(params, half).norm(), kRoundingRelative * speed);
      const BallState stopped = advanceWithinState(params, rolling, roll_time);
      const double distance = speed * speed / (2 * mu_r_g);
      EXPECT_NEAR((stopped.position - rolling.position).norm(), distance,
                  kRoundingRelative * distance);
      EXPECT_EQ(stopped.velocity, Vector3d::Zero());
      EXPECT_EQ(stopped.angular_velocity, Vector3d::Zero());
      EXPECT_EQ(motionState(params, stopped), MotionState::Stationary);
      EXPECT_EQ(timeToStateChange(params, stopped), kInfinity);
      // Far later the ball is where it stopped.
      EXPECT_EQ(advance(params, rolling, roll_time + 100).position, stopped.position);
    }
  }
}

TEST(ClothMotionTest, TimeToRestSumsTheStatesAndEndsWhereAdvanceFindsTheBallAtRest) {
  for (const ClothParams& params : bothCloths()) {
    const double g = params.gravity_mps2;
    // A stun shot without spin: sliding 2 v / (7 mu_s g), then rolling at 5/7 v until it stops.
    for (double speed : {0.05, 1.0, 4.0}) {
      const BallState stun = makeBall({0.1, 0.2}, {0, speed, 0}, Vector3d::Zero());
      const double expected = 2 * speed / (7 * params.sliding_friction * g) +
                              5.0 / 7.0 * speed / (params.rolling_friction * g);
      EXPECT_NEAR(timeToRest(params, stun), expected, kRoundingRelative * expected);
    }
    // Any motion (sidespin outlasting the roll included): at that time advance() has the ball at
    // rest, and a little before it not yet (a millionth of it before, the speed or spin left is
    // far above the thresholds that count as rest).
    std::mt19937_64 rng(44);
    std::uniform_real_distribution<double> speed(-3, 3);
    std::uniform_real_distribution<double> spin(-150, 150);
    for (int trial = 0; trial < 200; ++trial) {
      const BallState ball =
          makeBall({0, 0}, {speed(rng), speed(rng), 0}, {spin(rng), spin(rng), spin(rng)});
      const double rest = timeToRest(params, ball);
      ASSERT_GT(rest, 0);
      EXPECT_EQ(motionState(params, advance(params, ball, rest)), MotionState::Stationary);
      EXPECT_NE(motionState(params, advance(params, ball, rest * (1 - 1e-6))),
                MotionState::Stationary);
    }
    EXPECT_EQ(timeToRest(params, makeBall({0.3, 0}, Vector3d::Zero(), Vector3d::Zero())), 0);
  }
  BallState bad = makeBall({0, 0}, {1, 0, 0}, Vector3d::Zero());
  bad.velocity.z() = 0.5;
  EXPECT_THROW(timeToRest(poolCloth(), bad), std::invalid_argument);
}

TEST(ClothMotionTest, DrawShotSlowsReversesOrStopsAsTheFormulasSay) {
  const ClothParams params = snookerCloth();
  const double speed = 1.5;
  const double mu_g = params.sliding_friction * params.gravity_mps2;
  const double mu_r_g = params.rolling_friction * params.gravity_mps2;
  // Backspin w_y = -k V / R: the slip V (1 + k) points forward, friction pulls back at mu_s g, and
  // the ball rolls on at V (5 - 2k) / 7: forward for k < 5/2, dead for k = 5/2, back for k > 5/2.
  for (double k : {1.0, 2.5, 4.0}) {
    SCOPED_TRACE("k = " + std::to_string(k));
    const BallState draw = makeBall({0, 0}, {speed, 0, 0}, {0, -k * speed / params.radius_m, 0});
    const double slide_time = timeToStateChange(params, draw);
    EXPECT_NEAR(slide_time, 2 * speed * (1 + k) / (7 * mu_g), kRoundingRelative * slide_time);
    // Velocity falls linearly in time at mu_s g along -x, no sideways component.
    for (double fraction : {0.25, 0.5, 0.75}) {
      const BallState mid = advanceWithinState(params, draw, fraction * slide_time);
      EXPECT_NEAR(mid.velocity.x(), speed - mu_g * fraction * slide_time,
                  kRoundingRelative * speed);
      EXPECT_EQ(mid.velocity.y(), 0);
      EXPECT_EQ(mid.position.y(), 0);
    }
    const BallState after = advanceWithinState(params, draw, slide_time);
    const double final_speed = speed * (5 - 2 * k) / 7;
    EXPECT_NEAR(after.velocity.x(), final_speed, kRoundingRelative * speed);
    // Where it comes to rest: the slide, then the roll in the direction of final_speed.
    const double slide_x = speed * slide_time - 0.5 * mu_g * slide_time * slide_time;
    const double rest_x =
        slide_x + std::copysign(final_speed * final_speed / (2 * mu_r_g), final_speed);
    const BallState rest = advance(params, draw, 1000);
    EXPECT_EQ(motionState(params, rest), MotionState::Stationary);
    EXPECT_NEAR(rest.position.x(), rest_x, kRoundingRelative * std::abs(rest_x) + 1e-15);
    if (k == 2.5) {
      // Dead stop when the slide ends: no rolling phase at all.
      EXPECT_NE(motionState(params, after), MotionState::Rolling);
      EXPECT_NEAR(rest.position.x(), slide_x, kRoundingRelative * slide_x);
    }
    if (k == 4.0) {
      // The ball stops moving forward at V / (mu_s g), still sliding, having gone V^2 / (2 mu_s g),
      // then comes back.
      const double turn_time = speed / mu_g;
      ASSERT_LT(turn_time, slide_time);
      const double furthest = speed * speed / (2 * mu_g);
      EXPECT_NEAR(advanceWithinState(params, draw, turn_time).position.x(), furthest,
                  kRoundingRelative * furthest);
      EXPECT_LT(advanceWithinState(params, draw, 0.99 * turn_time).position.x(), furthest);
      EXPECT_LT(advanceWithinState(params, draw, 1.01 * turn_time).position.x(), furthest);
      EXPECT_LT(after.velocity.x(), 0);
    }
  }
}

TEST(ClothMotionTest, SidespinDecaysLinearlyAndIndependently) {
  for (const ClothParams& params : bothCloths()) {
    const double decel = spinDeceleration(params);
    for (double side : {35.0, -35.0}) {
      const BallState with_side = makeBall({0, 0}, {1.2, 0.3, 0}, {20, -10, side});
      BallState without_side = with_side;
      without_side.angular_velocity.z() = 0;
      const double stop_time = std::abs(side) / decel;
      for (double t : {0.0, 0.1, 0.5, 1.0, 2.0, 5.0, 12.0, 30.0}) {
        const BallState a = advance(params, with_side, t);
        const BallState b = advance(params, without_side, t);
        const double expected = t < stop_time ? side - std::copysign(decel * t, side) : 0.0;
        EXPECT_NEAR(a.angular_velocity.z(), expected, kRoundingRelative * std::abs(side));
        // Side spin changes nothing else: no swerve on the cloth in this model.
        EXPECT_EQ(a.position, b.position) << "t = " << t;
        EXPECT_EQ(a.velocity, b.velocity) << "t = " << t;
        EXPECT_EQ(planar(a.angular_velocity), planar(b.angular_velocity)) << "t = " << t;
      }
    }
    // A ball only spinning about z: Spinning until |w_z| / decel, then Stationary.
    const BallState spinner = makeBall({0.5, 0.5}, Vector3d::Zero(), {0, 0, 44});
    EXPECT_EQ(motionState(params, spinner), MotionState::Spinning);
    const double spin_time = timeToStateChange(params, spinner);
    EXPECT_NEAR(spin_time, 44 / decel, kRoundingRelative * spin_time);
    const BallState done = advanceWithinState(params, spinner, spin_time);
    EXPECT_EQ(done.angular_velocity.z(), 0);
    EXPECT_EQ(motionState(params, done), MotionState::Stationary);
    EXPECT_EQ(done.position, spinner.position);
  }
  EXPECT_NEAR(spinDeceleration(poolCloth()), 10, kRoundingRelative * 10);
  EXPECT_NEAR(spinDeceleration(snookerCloth()), 22, kRoundingRelative * 22);
}

// ---- Invariants ---------------------------------------------------------------------------------

BallState randomBall(std::mt19937_64& rng, const ClothParams& params) {
  std::uniform_real_distribution<double> speed(-4, 4);
  std::uniform_real_distribution<double> surface_speed(-4, 4);  // R w, m/s
  std::uniform_real_distribution<double> place(-1, 1);
  const double r = params.radius_m;
  return makeBall({place(rng), place(rng)}, {speed(rng), speed(rng), 0},
                  {surface_speed(rng) / r, surface_speed(rng) / r, surface_speed(rng) / r});
}

TEST(ClothMotionTest, EnergyNeverGrowsAlongTheMotion) {
  std::mt19937_64 rng(22);
  for (const ClothParams& params : bothCloths()) {
    for (int trial = 0; trial < 100; ++trial) {
      const BallState ball = randomBall(rng, params);
      const double start_energy = specificKineticEnergy(params, ball);
      double previous = start_energy;
      BallState state = ball;
      // Step through the whole motion, landing on every state change too.
      // Long enough for the slowest: 5.7 m/s rolls for 5.7 / (mu_r g) < 60 s.
      for (int step = 0; step < 4000 && motionState(params, state) != MotionState::Stationary;
           ++step) {
        const double dt = std::min(0.02, timeToStateChange(params, state));
        state = advanceWithinState(params, state, dt);
        const double energy = specificKineticEnergy(params, state);
        EXPECT_LE(energy, previous + kEnergyRoundingRelative * start_energy) << "trial " << trial;
        previous = energy;
      }
      EXPECT_EQ(motionState(params, state), MotionState::Stationary);
      EXPECT_EQ(specificKineticEnergy(params, state), 0);
    }
  }
}

// currentMotion() gives what the three checked functions give, and advancing within the state it
// found gives advanceWithinState()'s result, bit for bit, through a whole motion.
TEST(ClothMotionTest, CurrentMotionAndAdvanceWithinKnownStateMatchTheCheckedFunctions) {
  std::mt19937_64 rng(23);
  for (const ClothParams& params : bothCloths()) {
    for (int trial = 0; trial < 50; ++trial) {
      BallState state = randomBall(rng, params);
      for (int change = 0; change < 4; ++change) {
        const CurrentMotion motion = currentMotion(params, state);
        EXPECT_EQ(motion.state, motionState(params, state));
        EXPECT_EQ(motion.duration_s, timeToStateChange(params, state));
        const PositionQuadratic path = positionQuadratic(params, state);
        EXPECT_EQ(motion.path.linear_mps, path.linear_mps);
        EXPECT_EQ(motion.path.quadratic_mps2, path.quadratic_mps2);
        if (motion.state == MotionState::Stationary) break;
        for (double part : {0.25, 1.0}) {
          const double dt = part * motion.duration_s;
          const BallState known =
              advanceWithinKnownState(params, state, motion.state, motion.duration_s, dt);
          const BallState checked = advanceWithinState(params, state, dt);
          EXPECT_EQ(known.position, checked.position) << "trial " << trial;
          EXPECT_EQ(known.velocity, checked.velocity) << "trial " << trial;
          EXPECT_EQ(known.angular_velocity, checked.angular_velocity) << "trial " << trial;
          if (part == 1.0) state = known;
        }
      }
    }
  }
  // A step beyond the state's end is refused as advanceWithinState refuses it.
  const BallState rolling = makeBall({0, 0}, {1, 0, 0}, rollingSpin(poolCloth(), {1, 0}, 0));
  const CurrentMotion motion = currentMotion(poolCloth(), rolling);
  EXPECT_THROW(advanceWithinKnownState(poolCloth(), rolling, motion.state, motion.duration_s,
                                       2 * motion.duration_s),
               std::invalid_argument);
}

TEST(ClothMotionTest, SlidingLosesEnergyAtMuSGTimesSlipSpeed) {
  // Friction at the contact does work at the rate -mu_s g |u| per unit mass, and |u| falls at
  // (7/2) mu_s g: E(t) = E0 - mu_s g (|u0| t - (7/4) mu_s g t^2) (without spin about z).
  std::mt19937_64 rng(23);
  const ClothParams params = poolCloth();
  const double mu_g = params.sliding_friction * params.gravity_mps2;
  for (int trial = 0; trial < 100; ++trial) {
    BallState ball = randomBall(rng, params);
    ball.angular_velocity.z() = 0;
    const double slip = contactSlip(params, ball).norm();
    const double e0 = specificKineticEnergy(params, ball);
    const double slide_time = timeToStateChange(params, ball);
    for (double fraction : {0.3, 0.7, 1.0}) {
      const double t = fraction * slide_time;
      const double expected = e0 - mu_g * (slip * t - 1.75 * mu_g * t * t);
      EXPECT_NEAR(specificKineticEnergy(params, advanceWithinState(params, ball, t)), expected,
                  kRoundingRelative * 10 * e0);
    }
  }
}

BallState mirrored(const BallState& b) {
  // Reflection y -> -y; angular velocity is a pseudovector: (w_x, w_y, w_z) -> (-w_x, w_y, -w_z).
  return makeBall({b.position.x(), -b.position.y()}, {b.velocity.x(), -b.velocity.y(), 0},
                  {-b.angular_velocity.x(), b.angular_velocity.y(), -b.angular_velocity.z()});
}

BallState rotatedQuarterTurn(const BallState& b) {
  // Rotation by +90 degrees about z: (x, y) -> (-y, x) for every vector.
  return makeBall({-b.position.y(), b.position.x()}, {-b.velocity.y(), b.velocity.x(), 0},
                  {-b.angular_velocity.y(), b.angular_velocity.x(), b.angular_velocity.z()});
}

void expectSameState(const BallState& a, const BallState& b, const std::string& context) {
  EXPECT_EQ(a.position, b.position) << context;
  EXPECT_EQ(a.velocity, b.velocity) << context;
  EXPECT_EQ(a.angular_velocity, b.angular_velocity) << context;
}

TEST(ClothMotionTest, MirrorAndQuarterTurnSymmetryHoldBitForBit) {
  std::mt19937_64 rng(24);
  const ClothParams params = poolCloth();
  for (int trial = 0; trial < 100; ++trial) {
    const BallState ball = randomBall(rng, params);
    for (double t : {0.05, 0.3, 1.0, 4.0, 40.0}) {
      const std::string context = "trial " + std::to_string(trial) + ", t = " + std::to_string(t);
      expectSameState(advance(params, mirrored(ball), t), mirrored(advance(params, ball, t)),
                      context);
      expectSameState(advance(params, rotatedQuarterTurn(ball), t),
                      rotatedQuarterTurn(advance(params, ball, t)), context);
    }
  }
}

TEST(ClothMotionTest, AdvancingInTwoLegsMatchesOneLeg) {
  std::mt19937_64 rng(25);
  std::uniform_real_distribution<double> duration(0, 6);
  const ClothParams params = snookerCloth();
  for (int trial = 0; trial < 200; ++trial) {
    const BallState ball = randomBall(rng, params);
    const double t1 = duration(rng), t2 = duration(rng);
    const BallState one = advance(params, ball, t1 + t2);
    const BallState two = advance(params, advance(params, ball, t1), t2);
    // Rounding of the split time moves a transition by ulps: errors of order ulps of the scales.
    constexpr double kLegsTolerance = 1e-12;  // m, m/s and R rad/s
    EXPECT_NEAR((one.position - two.position).norm(), 0, kLegsTolerance) << "trial " << trial;
    EXPECT_NEAR((one.velocity - two.velocity).norm(), 0, kLegsTolerance) << "trial " << trial;
    EXPECT_NEAR(params.radius_m * (one.angular_velocity - two.angular_velocity).norm(), 0,
                kLegsTolerance)
        << "trial " << trial;
  }
}

TEST(ClothMotionTest, PositionQuadraticIsTheClosedFormPath) {
  std::mt19937_64 rng(26);
  const ClothParams params = poolCloth();
  for (int trial = 0; trial < 200; ++trial) {
    BallState ball = randomBall(rng, params);
    // Visit every state of the motion.
    while (motionState(params, ball) != MotionState::Stationary) {
      const MotionState state = motionState(params, ball);
      const double span = timeToStateChange(params, ball);
      const PositionQuadratic path = positionQuadratic(params, ball);
      EXPECT_EQ(path.constant_m, ball.position);
      if (state == MotionState::Sliding || state == MotionState::Rolling) {
        EXPECT_EQ(path.linear_mps, planar(ball.velocity));
        // Half the deceleration, opposite the slip (sliding) or the velocity (rolling).
        const double mu =
            state == MotionState::Sliding ? params.sliding_friction : params.rolling_friction;
        const Vector2d against = state == MotionState::Sliding
                                     ? Vector2d(-planar(contactSlip(params, ball)).normalized())
                                     : Vector2d(-planar(ball.velocity).normalized());
        EXPECT_NEAR((path.quadratic_mps2 - 0.5 * mu * params.gravity_mps2 * against).norm(), 0,
                    kRoundingRelative);
      } else {
        EXPECT_EQ(path.linear_mps, Vector2d::Zero());
        EXPECT_EQ(path.quadratic_mps2, Vector2d::Zero());
      }
      for (double fraction : {0.0, 0.37, 1.0}) {
        EXPECT_EQ(path.at(fraction * span),
                  advanceWithinState(params, ball, fraction * span).position);
      }
      ball = advanceWithinState(params, ball, span);
    }
  }
}

TEST(ClothMotionTest, ThresholdsClassifyRoundingAsRest) {
  const ClothParams params = poolCloth();
  const double r = params.radius_m;
  // Rolling at 1 m/s with a slip far below the threshold: rolling.
  const BallState nearly_rolling =
      makeBall({0, 0}, {1, 0, 0}, {0, (1 - 0.5 * kSlipSpeedEpsilon_mps) / r, 0});
  EXPECT_EQ(motionState(params, nearly_rolling), MotionState::Rolling);
  const BallState slipping =
      makeBall({0, 0}, {1, 0, 0}, {0, (1 - 4 * kSlipSpeedEpsilon_mps) / r, 0});
  EXPECT_EQ(motionState(params, slipping), MotionState::Sliding);
  EXPECT_EQ(motionState(params, makeBall({0, 0}, {0.5 * kSpeedEpsilon_mps, 0, 0},
                                         {0, 0.5 * kSpeedEpsilon_mps / r, 1})),
            MotionState::Spinning);
  EXPECT_EQ(
      motionState(params, makeBall({0, 0}, Vector3d::Zero(), {0, 0, 0.5 * kSpinEpsilon_radps})),
      MotionState::Stationary);
  // A ball spinning in place about a horizontal axis slips: it is sliding, and the cloth drives it
  // the way the spin rolls (w_y > 0 is topspin for +x: slip u = (-R w_y, 0), friction along +x).
  const BallState spinning_in_place = makeBall({0, 0}, Vector3d::Zero(), {0, 50, 0});
  EXPECT_EQ(motionState(params, spinning_in_place), MotionState::Sliding);
  EXPECT_GT(advance(params, spinning_in_place, 0.01).velocity.x(), 0);
}

// ---- Floating-point exceptions ------------------------------------------------------------------

// Every entry point with invalid operations, division by zero and overflow trapped, on the states
// where a direction is undefined or a duration is zero: slip exactly zero (rolling), slip just at
// and just beyond the threshold, speed exactly zero with spin, spin exactly zero, nothing moving,
// each axis alone, and fast random states. Each is advanced to its state change, through it, and
// far beyond (at rest at last), and energy never grows along the way.
TEST(ClothMotionTest, NoFloatingPointExceptionAtZeroSlipSpeedOrSpin) {
  std::vector<BallState> balls;
  for (const ClothParams& params : bothCloths()) {
    const double r = params.radius_m;
    balls.push_back(makeBall({0, 0}, {1, 0, 0}, rollingSpin(params, {1, 0}, 0)));  // u = 0 exactly
    balls.push_back(makeBall({0, 0}, {0, -2, 0}, rollingSpin(params, {0, -2}, 5)));
    balls.push_back(makeBall({0, 0}, {1, 0, 0}, {0, (1 - kSlipSpeedEpsilon_mps) / r, 0}));
    balls.push_back(makeBall({0, 0}, {1, 0, 0}, {0, (1 - 2 * kSlipSpeedEpsilon_mps) / r, 0}));
  }
  balls.push_back(makeBall({0.1, 0.2}, Vector3d::Zero(), Vector3d::Zero()));  // at rest
  balls.push_back(makeBall({0, 0}, Vector3d::Zero(), {0, 0, 30}));            // spinning only
  balls.push_back(makeBall({0, 0}, Vector3d::Zero(), {40, 0, 0}));            // slip, no speed
  balls.push_back(makeBall({0, 0}, {3, 0, 0}, Vector3d::Zero()));             // stun
  balls.push_back(makeBall({0, 0}, {kSpeedEpsilon_mps, 0, 0}, Vector3d::Zero()));
  balls.push_back(makeBall({0, 0}, {0, 0, 0}, {0, 0, kSpinEpsilon_radps}));
  std::mt19937_64 rng(61);
  std::uniform_real_distribution<double> unit(-1, 1);
  for (int i = 0; i < 200; ++i) {
    balls.push_back(makeBall({unit(rng), unit(rng)}, {16 * unit(rng), 16 * unit(rng), 0},
                             {500 * unit(rng), 500 * unit(rng), 500 * unit(rng)}));
  }
  for (const ClothParams& params : bothCloths()) {
    for (const BallState& ball : balls) {
      double change_s = 0;
      BallState at_change, beyond, at_rest;
      {
        test::FloatingPointTraps traps;
        change_s = timeToStateChange(params, ball);
        motionState(params, ball);
        positionQuadratic(params, ball);
        if (std::isfinite(change_s)) {
          at_change = advanceWithinState(params, ball, change_s);
          beyond = advance(params, ball, 2 * change_s);
        }
        at_rest = advance(params, ball, 1e3);  // seconds: everything has stopped
      }
      const double energy = specificKineticEnergy(params, ball);
      if (std::isfinite(change_s)) {
        EXPECT_GE(change_s, 0);
        EXPECT_LE(specificKineticEnergy(params, at_change), energy * (1 + kEnergyRoundingRelative));
        EXPECT_LE(specificKineticEnergy(params, beyond), energy * (1 + kEnergyRoundingRelative));
      } else {
        EXPECT_EQ(motionState(params, ball), MotionState::Stationary);
      }
      EXPECT_EQ(motionState(params, at_rest), MotionState::Stationary);
      EXPECT_TRUE(at_rest.position.allFinite());
    }
  }
}

// ---- Against a numerical integration of the equations of motion ---------------------------------

// The equations of motion, integrated by RK4 independently of the closed form. Friction at the
// contact C = -R z: sliding, F = -mu_s m g u_hat gives dv/dt = -mu_s g u_hat and, with torque
// (-R z) x F and I = (2/5) m R^2, dw/dt = (5 mu_s g / (2R)) z x u_hat. Rolling: dv/dt = -mu_r g
// v_hat with w_xy following v. Spin about z: dw_z/dt = -(spin deceleration) sign(w_z). The
// right-hand side jumps where the slip, the speed or w_z reaches zero. As in any integrator of such
// systems, the discrete part of the state (the mode and the friction directions u_hat, v_hat, sign
// w_z) is held over a step, taken from the step's start, and a mode switches at the end of the step
// in which its driving quantity changed sign (evaluating the directions at every stage instead
// makes the stages of a step that straddles the switch cancel exactly, and the integration stalls).
// The instants are not located within the step: the switching costs O(h).
struct Integrator {
  ClothParams params;
  bool rolling = false, stopped = false, spin_stopped = false;

  struct State {
    Vector2d r, v;
    Vector3d w;
  };
  struct Directions {
    Vector2d slip_direction, velocity_direction;
    double spin_sign;
  };

  Vector2d slip(const State& y) const {
    return {y.v.x() - params.radius_m * y.w.y(), y.v.y() + params.radius_m * y.w.x()};
  }

  State rates(const State& y, const Directions& held) const {
    State d;
    d.r = y.v;
    d.v.setZero();
    d.w.setZero();
    const double g = params.gravity_mps2;
    if (!rolling) {
      const Vector2d& u_hat = held.slip_direction;
      d.v = -params.sliding_friction * g * u_hat;
      const Vector2d z_cross_u_hat(-u_hat.y(), u_hat.x());
      d.w.head<2>() = 2.5 * params.sliding_friction * g / params.radius_m * z_cross_u_hat;
    } else if (!stopped) {
      d.v = -params.rolling_friction * g * held.velocity_direction;
      d.w.head<2>() = Vector2d(-d.v.y(), d.v.x()) / params.radius_m;
    }
    if (!spin_stopped) d.w.z() = -held.spin_sign * spinDeceleration(params);
    return d;
  }

  static State add(const State& y, const State& d, double h) {
    return {y.r + h * d.r, y.v + h * d.v, y.w + h * d.w};
  }

  void step(State& y, double h) {
    const Directions held{slip(y).normalized(), y.v.normalized(), y.w.z() > 0 ? 1.0 : -1.0};
    const State k1 = rates(y, held);
    const State k2 = rates(add(y, k1, h / 2), held);
    const State k3 = rates(add(y, k2, h / 2), held);
    const State k4 = rates(add(y, k3, h), held);
    State next = y;
    next.r += h / 6 * (k1.r + 2 * k2.r + 2 * k3.r + k4.r);
    next.v += h / 6 * (k1.v + 2 * k2.v + 2 * k3.v + k4.v);
    next.w += h / 6 * (k1.w + 2 * k2.w + 2 * k3.w + k4.w);
    if (!rolling && slip(next).dot(slip(y)) <= 0) {
      rolling = true;  // the slip ran out during the step: from here on the ball rolls
      next.w.head<2>() = Vector2d(-next.v.y(), next.v.x()) / params.radius_m;
    } else if (rolling && !stopped && next.v.dot(y.v) <= 0) {
      stopped = true;
      next.v.setZero();
      next.w.head<2>().setZero();
    }
    if (!spin_stopped && next.w.z() * y.w.z() <= 0) {
      spin_stopped = true;
      next.w.z() = 0;
    }
    y = next;
  }
};

struct Deviation {
  double position_m = 0, velocity_mps = 0, surface_speed_mps = 0;  // surface speed: R |dw|
};

// Integrates `ball` with steps of about h and compares with advance() at the sample times.
Deviation integrationDeviation(const ClothParams& params, const BallState& ball,
                               const std::vector<double>& sample_times, double h) {
  Integrator integrator{params};
  integrator.rolling = motionState(params, ball) != MotionState::Sliding;
  integrator.stopped = planar(ball.velocity).norm() <= kSpeedEpsilon_mps;
  integrator.spin_stopped = ball.angular_velocity.z() == 0;
  Integrator::State y{ball.position, planar(ball.velocity), ball.angular_velocity};
  Deviation worst;
  double t = 0;
  for (double sample : sample_times) {
    const int steps = static_cast<int>(std::ceil((sample - t) / h));
    for (int i = 0; i < steps; ++i) integrator.step(y, (sample - t) / steps);
    t = sample;
    const BallState exact = advance(params, ball, t);
    worst.position_m = std::max(worst.position_m, (y.r - exact.position).norm());
    worst.velocity_mps = std::max(worst.velocity_mps, (y.v - planar(exact.velocity)).norm());
    worst.surface_speed_mps =
        std::max(worst.surface_speed_mps, params.radius_m * (y.w - exact.angular_velocity).norm());
  }
  return worst;
}

std::vector<BallState> integrationCases(const ClothParams& params) {
  const double r = params.radius_m;
  return {
      makeBall({0, 0}, {2, 0, 0}, {0, 0, 0}),                   // stun
      makeBall({0, 0}, {1.5, 0, 0}, {0, -4 * 1.5 / r, 20}),     // screw back with side
      makeBall({0.1, 0.2}, {1, 0.4, 0}, {10, 30, -15}),         // curving (slip across v)
      makeBall({0, 0}, {0.8, -0.6, 0}, {1.2 / r, 1.6 / r, 5}),  // overspin
  };
}

TEST(ClothMotionTest, Rk4WithinOneStateMatchesTheClosedFormToRounding) {
  for (const ClothParams& params : bothCloths()) {
    for (const BallState& ball : integrationCases(params)) {
      for (const BallState& start :
           {ball, advance(params, ball, timeToStateChange(params, ball))}) {
        // Stay clear of the state's end and of the spin's stop, where the equations switch.
        double span = 0.9 * timeToStateChange(params, start);
        if (start.angular_velocity.z() != 0) {
          span =
              std::min(span, 0.9 * std::abs(start.angular_velocity.z()) / spinDeceleration(params));
        }
        const Deviation d = integrationDeviation(params, start, {span / 3, span}, span / 1000);
        const double speed =
            planar(start.velocity).norm() + params.radius_m * start.angular_velocity.norm();
        // Positions: relative to the distance travelled plus where the ball started.
        const double distance_scale = speed * span + start.position.norm();
        EXPECT_LE(d.position_m, kRk4WithinStateRelative * distance_scale);
        EXPECT_LE(d.velocity_mps, kRk4WithinStateRelative * speed);
        EXPECT_LE(d.surface_speed_mps, kRk4WithinStateRelative * speed);
      }
    }
  }
}

TEST(ClothMotionTest, Rk4ThroughTheTransitionsConvergesToTheClosedForm) {
  const ClothParams params = poolCloth();
  for (const BallState& ball : integrationCases(params)) {
    const double slide_time = timeToStateChange(params, ball);
    const BallState rolling = advance(params, ball, slide_time);
    const double roll_time = timeToStateChange(params, rolling);
    const std::vector<double> samples{0.5 * slide_time, slide_time + 0.2,
                                      slide_time + 0.5 * roll_time, slide_time + roll_time + 5};
    const double mu_s_g = params.sliding_friction * params.gravity_mps2;
    const double top_speed =
        std::max(planar(ball.velocity).norm(), planar(rolling.velocity).norm());
    // A bound for the cost of not locating the switches: the step that crosses one applies at most
    // one step of the wrong friction, (mu_s + mu_r) g h ~ mu_s g h in speed (doubled for margin),
    // which the roll carries for up to v / (mu_r g) seconds: a position error up to
    // 2 (mu_s / mu_r) v h, v the top speed (at the start, or when rolling sets in after overspin).
    const double velocity_rate = 2 * mu_s_g;
    const double position_rate = 2 * params.sliding_friction / params.rolling_friction * top_speed;
    std::vector<Deviation> deviations;
    for (double h : {8e-4, 4e-4, 2e-4, 1e-4, 5e-5}) {
      const Deviation d = integrationDeviation(params, ball, samples, h);
      EXPECT_LE(d.position_m, position_rate * h) << "h = " << h;
      EXPECT_LE(d.velocity_mps, velocity_rate * h) << "h = " << h;
      EXPECT_LE(d.surface_speed_mps, velocity_rate * h) << "h = " << h;
      deviations.push_back(d);
    }
    // Converging: a sixteenth of the step leaves at most about a third of the deviation (first
    // order gives 1/16 on average; where a switch falls inside its step varies from one h to
    // the next).
    EXPECT_LT(deviations.back().position_m, 0.35 * deviations.front().position_m);
    EXPECT_LT(deviations.back().velocity_mps, 0.35 * deviations.front().velocity_mps);
  }
}

// ---- Inputs -------------------------------------------------------------------------------------

TEST(ClothMotionTest, PresetsAreValidAndMatchTheMeasuredValues) {
  EXPECT_NO_THROW(validateClothParams(poolCloth()));
  EXPECT_NO_THROW(validateClothParams(snookerCloth()));
  const ClothParams snooker = snookerCloth();
  const double rolling_deceleration = snooker.rolling_friction * snooker.gravity_mps2;
  EXPECT_GE(rolling_deceleration, 0.124);  // measured 0.124-0.126 m/s^2
  EXPECT_LE(rolling_deceleration, 0.126);
  const double sliding_deceleration = snooker.sliding_friction * snooker.gravity_mps2;
  EXPECT_GE(sliding_deceleration, 1.75);  // measured 1.75-2.40 m/s^2
  EXPECT_LE(sliding_deceleration, 2.40);
}

TEST(ClothMotionTest, BadParametersAndStatesAreRejected) {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const BallState ball = makeBall({0, 0}, {1, 0, 0}, {0, 0, 0});
  const auto withParam = [&](double ClothParams::*field, double value) {
    ClothParams p = poolCloth();
    p.*field = value;
    return [p, ball] { advance(p, ball, 1); };
  };
  expectRejected(withParam(&ClothParams::radius_m, -0.01), "ball radius R (m) = -0.01");
  expectRejected(withParam(&ClothParams::radius_m, nan), "ball radius R (m) = nan");
  expectRejected(withParam(&ClothParams::gravity_mps2, 0), "gravity g (m/s^2) = 0");
  expectRejected(withParam(&ClothParams::sliding_friction, 1.5), "mu_s = 1.5 is not allowed");
  expectRejected(withParam(&ClothParams::sliding_friction, 0), "mu_s = 0 is not allowed");
  expectRejected(withParam(&ClothParams::rolling_friction, 0.3), "mu_r = 0.3 ");
  expectRejected(withParam(&ClothParams::rolling_friction, -1), "mu_r = -1");
  expectRejected(withParam(&ClothParams::spinning_friction, kInfinity), "mu_sp = inf");
  expectRejected(withParam(&ClothParams::spinning_friction, 0), "mu_sp = 0");
  // Near zero: a state would end beyond the times events are solved in (1e-300 put it at 1e300 s).
  expectRejected(withParam(&ClothParams::rolling_friction, 1e-300), "mu_r = 1e-300 is not allowed");
  expectRejected(withParam(&ClothParams::sliding_friction, 1e-7), "mu_s = 1e-07 is not allowed");
  expectRejected(withParam(&ClothParams::spinning_friction, 1e-300), "mu_sp = 1e-300");
  ClothParams slowest = poolCloth();
  slowest.rolling_friction = kMinClothFriction;
  slowest.spinning_friction = kMinClothFriction;
  const BallState fastest = makeBall({0, 0}, {1e3, 0, 0}, {0, 0, 0});  // the largest speed accepted
  EXPECT_NO_THROW(advance(slowest, fastest, 1));
  EXPECT_LT(timeToStateChange(slowest, advance(slowest, fastest, 10)), 1e9);

  const ClothParams params = poolCloth();
  expectRejected(
      [&] {
        motionState(params, makeBall({0, 0}, {1, 0, 0.5}, {0, 0, 0}));
      },
      "v_z (m/s) = 0.5");
  expectRejected(
      [&] {
        advance(params, makeBall({nan, 0}, {1, 0, 0}, {0, 0, 0}), 1);
      },
      "position x (m) = nan");
  expectRejected(
      [&] {
        advance(params, makeBall({0, 0}, {1, 0, 0}, {0, kInfinity, 0}), 1);
      },
      "w_y (rad/s) = inf");
  expectRejected([&] { advance(params, ball, -1); }, "dt (s) = -1");
  expectRejected([&] { advance(params, ball, nan); }, "dt (s) = nan");
  expectRejected([&] { advanceWithinState(params, ball, 10); }, "dt (s) = 10");
}

}  // namespace
}  // namespace baize::physics
