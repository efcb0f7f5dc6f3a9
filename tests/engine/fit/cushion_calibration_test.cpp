#include "engine/fit/cushion_calibration.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <random>
#include <stdexcept>
#include <string>

#include "engine/io/assets_directory.h"
#include "engine/io/scene.h"
#include "engine/io/table.h"
#include "physics/cushion_exact_solver.h"

namespace baize::engine {
namespace {

constexpr double kPi = 3.14159265358979323846;

// The rebound the model gives, as a measurement with Gaussian noise of sd `noise_mps` on the speed
// and `noise_deg` on the angle.
CushionMeasurement synthetic(const physics::CushionParams& p, double speed, double angle_deg,
                             double topspin, double sidespin, std::mt19937_64& random,
                             double noise_mps, double noise_deg) {
  const double unit = speed / p.radius_m;
  const auto result = physics::solveCushionImpactExact(
      p, physics::incomingBall(speed, angle_deg * kPi / 180, topspin * unit, sidespin * unit));
  std::normal_distribution<double> gauss(0, 1);
  CushionMeasurement m;
  m.speed_mps = speed;
  m.angle_deg = angle_deg;
  m.topspin_k = topspin;
  m.sidespin_k = sidespin;
  m.rebound_speed_mps = std::hypot(result.after.v.x(), result.after.v.y()) + noise_mps * gauss(random);
  m.rebound_angle_deg =
      std::atan2(-result.after.v.y(), result.after.v.x()) * 180 / kPi + noise_deg * gauss(random);
  return m;
}

// The rebound speed of a ball rolling head-on into the cushion at `speed_mps`.
double rebound(const physics::CushionParams& p, double speed_mps) {
  const auto result = physics::solveCushionImpactExact(
      p, physics::incomingBall(speed_mps, kPi / 2, speed_mps / p.radius_m, 0));
  return std::hypot(result.after.v.x(), result.after.v.y());
}

physics::CushionParams poolCushion(double e, double mu_w) {
  physics::CushionParams p = calibrationStart(builtinTable("pool-9ft"), builtinBallSet("pool"));
  p.restitution = e;
  p.cushion_friction = mu_w;
  return p;
}

std::vector<CushionMeasurement> syntheticSet(const physics::CushionParams& truth, uint64_t seed) {
  std::mt19937_64 random(seed);
  std::vector<CushionMeasurement> data;
  for (double angle : {30.0, 50.0, 70.0, 90.0}) {
    for (double topspin : {0.0, 1.0}) {
      for (double speed : {0.5, 1.0}) {
        data.push_back(synthetic(truth, speed, angle, topspin, 0, random, 0.01, 0.5));
      }
    }
  }
  return data;
}

// Fitted back from a start away from the truth, within 3 sd, for several noise draws.
TEST(CushionCalibration, FitsSyntheticDataBackWithinItsUncertainty) {
  const physics::CushionParams truth = poolCushion(0.8, 0.2);
  for (uint64_t seed : {1u, 2u, 3u}) {
    CushionCalibrationSetup setup;
    setup.start = poolCushion(0.95, 0.1);
    setup.threads = 2;
    const CushionCalibration fit = calibrateCushion(syntheticSet(truth, seed), setup);
    ASSERT_EQ(fit.values.size(), 2);
    EXPECT_GT(fit.standard_deviation[0], 0);
    EXPECT_GT(fit.standard_deviation[1], 0);
    EXPECT_LT(std::abs(fit.values[0] - truth.restitution), 3 * fit.standard_deviation[0]) << seed;
    EXPECT_LT(std::abs(fit.values[1] - truth.cushion_friction), 3 * fit.standard_deviation[1])
        << seed;
    EXPECT_TRUE(fit.separation_problems.empty()) << seed;
    EXPECT_EQ(fit.points.size(), 16u);
    EXPECT_EQ(fit.residual_count, 32);
  }
}

// Without noise the truth is found to far better than any measurement could give.
TEST(CushionCalibration, FindsTheTruthFromExactData) {
  const physics::CushionParams truth = poolCushion(0.75, 0.18);
  std::mt19937_64 random(7);
  std::vector<CushionMeasurement> data;
  for (double angle : {40.0, 90.0}) {
    for (double topspin : {0.0, 1.0}) data.push_back(synthetic(truth, 1, angle, topspin, 0, random, 0, 0));
  }
  CushionCalibrationSetup setup;
  setup.start = poolCushion(0.98, 0.14);
  const CushionCalibration fit = calibrateCushion(data, setup);
  EXPECT_NEAR(fit.values[0], 0.75, 1e-6);
  EXPECT_NEAR(fit.values[1], 0.18, 1e-6);
  EXPECT_LT(fit.rms_residual_mps, 1e-7);
}

// Head-on rolling impacts give one rebound ratio whatever the speed (the model is linear), so e_e
// and mu_w cannot both be found: the fit says so.
TEST(CushionCalibration, HeadOnRollingDataDoesNotSeparateRestitutionAndFriction) {
  const physics::CushionParams truth = poolCushion(0.8, 0.2);
  std::mt19937_64 random(3);
  std::vector<CushionMeasurement> data;
  for (double speed : {0.3, 0.6, 0.9, 1.2}) {
    data.push_back(synthetic(truth, speed, 90, 1, 0, random, 0.01, 0));
    data.back().rebound_angle_deg.reset();
  }
  CushionCalibrationSetup setup;
  setup.start = poolCushion(0.95, 0.1);
  const CushionCalibration fit = calibrateCushion(data, setup);
  ASSERT_GE(fit.separation_problems.size(), 1u);  // then the sds may say each is poorly determined
  EXPECT_NE(fit.separation_problems[0].find("cannot separate restitution and friction"),
            std::string::npos)
      << fit.separation_problems[0];
}

TEST(CushionCalibration, LeavesOutFastPointsAndCountsThem) {
  const physics::CushionParams truth = poolCushion(0.8, 0.2);
  std::vector<CushionMeasurement> data = syntheticSet(truth, 5);
  data.push_back(data[0]);
  data.back().speed_mps = 2.0;
  CushionCalibrationSetup setup;
  setup.start = truth;
  const CushionCalibration fit = calibrateCushion(data, setup);
  EXPECT_EQ(fit.left_out, 1);
  EXPECT_EQ(fit.points.size(), data.size() - 1);
}

TEST(CushionCalibration, RefusesFewerValuesThanParameters) {
  const physics::CushionParams truth = poolCushion(0.8, 0.2);
  std::mt19937_64 random(1);
  std::vector<CushionMeasurement> data = {synthetic(truth, 1, 90, 1, 0, random, 0, 0)};
  data[0].rebound_angle_deg.reset();
  CushionCalibrationSetup setup;
  setup.start = truth;
  try {
    calibrateCushion(data, setup);
    FAIL() << "one value fitted two parameters";
  } catch (const std::invalid_argument& refused) {
    EXPECT_NE(std::string(refused.what()).find("fewer than the 2 parameters"), std::string::npos)
        << refused.what();
  }
}

// The threads split the impacts; each is solved alone, so the fit is the same to the bit.
TEST(CushionCalibration, ThreadsDoNotChangeTheResult) {
  const std::vector<CushionMeasurement> data = syntheticSet(poolCushion(0.8, 0.2), 9);
  CushionCalibrationSetup setup;
  setup.start = poolCushion(0.9, 0.15);
  const CushionCalibration one = calibrateCushion(data, setup);
  setup.threads = 3;
  const CushionCalibration three = calibrateCushion(data, setup);
  EXPECT_EQ(one.values, three.values);
  EXPECT_EQ(one.standard_deviation, three.standard_deviation);
}

// The paper's head-on rolling snooker rebounds (assets/measurements) below 1.5 m/s, on the snooker
// table: with mu_w held at the paper's 0.14 the restitution fitted agrees with its 0.98 within
// 2 sd; fitting both, the tool says the data cannot separate them.
TEST(CushionCalibration, ThePapersSnookerDataAgreeWithItsValues) {
  const auto data = readCushionMeasurements(assetsDirectory() +
                                            "/measurements/snooker-head-on-rolling.csv");
  CushionCalibrationSetup setup;
  setup.start = calibrationStart(builtinTable("snooker-12ft"), builtinBallSet("snooker"));
  ASSERT_EQ(setup.start.cushion_friction, 0.14);
  setup.fitted = {CushionFitParameter::Restitution};
  const CushionCalibration fit = calibrateCushion(data, setup);
  EXPECT_EQ(fit.points.size(), 7u);
  EXPECT_EQ(fit.left_out, 9);
  EXPECT_LT(std::abs(fit.values[0] - 0.98), 2 * fit.standard_deviation[0]);
  EXPECT_LT(fit.standard_deviation[0], 0.03);  // the data do say something
  setup.fitted = {CushionFitParameter::Restitution, CushionFitParameter::Friction};
  const CushionCalibration both = calibrateCushion(data, setup);
  ASSERT_GE(both.separation_problems.size(), 1u);
  EXPECT_NE(both.separation_problems[0].find("cannot separate restitution and friction"),
            std::string::npos);
}

// The pool tables ship e_e fitted to the published pool figures with mu_w held at 0.14
// (docs/calibrate.md): fitting again gives the shipped value to its rounding.
TEST(CushionCalibration, PoolTablesCarryTheValueFittedToThePoolFigures) {
  const auto data =
      readCushionMeasurements(assetsDirectory() + "/measurements/pool-rail-figures.csv");
  for (const char* name : {"pool-7ft", "pool-8ft", "pool-9ft"}) {
    const Table table = builtinTable(name);
    CushionCalibrationSetup setup;
    setup.start = calibrationStart(table, builtinBallSet("pool"));
    setup.fitted = {CushionFitParameter::Restitution};
    const CushionCalibration fit = calibrateCushion(data, setup);
    EXPECT_NEAR(table.cushion_restitution, fit.values[0], 0.005) << name;  // shipped to 2 digits
    EXPECT_EQ(table.cushion_friction, 0.14) << name;
    // The figures' spread: a few hundredths to a tenth.
    EXPECT_GT(fit.standard_deviation[0], 0.02);
    EXPECT_LT(fit.standard_deviation[0], 0.15);
  }
}

physics::CushionImpactResult poolRail(double angle_deg, double topspin, double sidespin) {
  const physics::CushionParams p =
      calibrationStart(builtinTable("pool-9ft"), builtinBallSet("pool"));
  const double unit = 1.0 / p.radius_m;  // V0 = 1 m/s
  return physics::solveCushionImpactExact(
      p, physics::incomingBall(1, angle_deg * kPi / 180, topspin * unit, sidespin * unit));
}

// A ball rolling head-on into a pool rail at the pool defaults comes back at about 0.7 of its
// speed (Alciatore's figure; within the fit's sd of it) close to stun: its spin about the axis
// across its new path is well under half of rolling (it arrives with 1, rolling the other way).
TEST(CushionCalibration, ARollingBallLeavesAPoolRailNearStun) {
  const physics::CushionImpactResult r = poolRail(90, 1, 0);
  const double rebound_mps = -r.after.v.y();
  EXPECT_NEAR(rebound_mps, 0.7, 0.084);
  const double radius_m = builtinBallSet("pool").radius_m;
  // Rolling away (toward -y) would be w_x = +v/R; the spin left is a share of that.
  const double rolling_share = r.after.w.x() * radius_m / rebound_mps;
  EXPECT_LT(std::abs(rolling_share), 0.5) << rolling_share;
}

// Running english (sidespin with the ball's motion along the rail) sends a rolling ball off a
// pool rail at a wider angle, along the rail; reverse english shortens it.
TEST(CushionCalibration, EnglishTurnsThePoolReboundTheWayPlayersKnow) {
  const auto angle = [](const physics::CushionImpactResult& r) {
    return std::atan2(-r.after.v.y(), r.after.v.x()) * 180 / kPi;
  };
  const double running = angle(poolRail(45, 1, 1));
  const double none = angle(poolRail(45, 1, 0));
  const double reverse = angle(poolRail(45, 1, -1));
  EXPECT_LT(running, none - 3);
  EXPECT_GT(reverse, none + 1);
  EXPECT_LT(none, 45);  // a rolling ball comes off flatter than it came in
}

physics::CushionParams snookerCushion() {
  return calibrationStart(builtinTable("snooker-12ft"), builtinBallSet("snooker"));
}

// Head-on rolling impacts from 0.3 to 3.5 m/s, as the paper measured them, made by `truth`.
std::vector<CushionMeasurement> headOnRolling(const physics::CushionParams& truth, double noise_mps,
                                              uint64_t seed) {
  std::mt19937_64 random(seed);
  std::vector<CushionMeasurement> data;
  for (double speed = 0.3; speed < 3.55; speed += 0.2) {
    data.push_back(synthetic(truth, speed, 90, 1, 0, random, noise_mps, 0));
    data.back().rebound_angle_deg.reset();
  }
  return data;
}

CushionCalibrationSetup speedDependenceSetup(std::vector<CushionFitParameter> fitted) {
  CushionCalibrationSetup setup;
  setup.start = snookerCushion();
  setup.fitted = std::move(fitted);
  setup.max_speed_mps = std::numeric_limits<double>::infinity();  // the fast points are the point
  setup.threads = 2;
  return setup;
}

// Data made with a known knee and exponent (and e_e) plus noise are fitted back within 3 sd, from
// the fit's own start (kSpeedDependenceFitStart, e_e the table's).
TEST(CushionCalibration, FitsASyntheticSpeedDependenceBackWithinItsUncertainty) {
  physics::CushionParams truth = snookerCushion();
  truth.restitution = 0.95;
  truth.restitution_speed_dependence = physics::RestitutionSpeedDependence{1.8, 0.4};
  for (uint64_t seed : {1u, 2u, 3u}) {
    const CushionCalibrationSetup setup = speedDependenceSetup(
        {CushionFitParameter::Restitution, CushionFitParameter::KneeSpeed,
         CushionFitParameter::FalloffExponent});
    const CushionCalibration fit = calibrateCushion(headOnRolling(truth, 0.01, seed), setup);
    ASSERT_EQ(fit.values.size(), 3);
    EXPECT_EQ(fit.left_out, 0);
    const double expected[] = {0.95, 1.8, 0.4};
    for (int i = 0; i < 3; ++i) {
      EXPECT_GT(fit.standard_deviation[i], 0) << i;
      EXPECT_LT(std::abs(fit.values[i] - expected[i]), 3 * fit.standard_deviation[i])
          << "parameter " << i << " seed " << seed << ": " << fit.values[i] << " +- "
          << fit.standard_deviation[i];
    }
    ASSERT_TRUE(fit.params.restitution_speed_dependence);
    EXPECT_EQ(fit.params.restitution_speed_dependence->knee_speed_mps, fit.values[1]);
  }
}

// The law shipped for the snooker cushion: a scene's "physics" value
// (assets/measurements/snooker-speed-dependence.json), read as a scene reads it.
physics::RestitutionSpeedDependence shippedSnookerLaw() {
  nlohmann::json scene = {{"table", "snooker-12ft"},
                          {"ball_set", "snooker"},
                          {"balls", {{"cue", {0.0, 0.0}}}},
                          {"shot", {{"heading_deg", 0}, {"speed_mps", 1}}}};
  const std::string file = assetsDirectory() + "/measurements/snooker-speed-dependence.json";
  scene["physics"] = JsonReader::parseFile(file);
  const nlohmann::json law = simulationParamsFor(sceneFromJson(scene, file))
                                 .cushion->parametersJson()
                                 .at("restitution_speed_dependence");
  return {law.at("knee_speed_mps").get<double>(), law.at("falloff_exponent").get<double>()};
}

CushionCalibration fitOfTheFullSnookerData() {
  const auto data = readCushionMeasurements(assetsDirectory() +
                                            "/measurements/snooker-head-on-rolling.csv");
  return calibrateCushion(data, speedDependenceSetup({CushionFitParameter::KneeSpeed,
                                                      CushionFitParameter::FalloffExponent}));
}

// The paper's head-on snooker rebounds, all sixteen, with e_e and mu_w held at the table's (the
// paper's) values: the fitted knee and exponent are those shipped for it, to their
// rounding, and they follow the data far better than a constant e_e does.
TEST(CushionCalibration, TheFullSnookerDataGiveTheShippedSpeedDependence) {
  const CushionCalibration fit = fitOfTheFullSnookerData();
  EXPECT_EQ(fit.points.size(), 16u);
  const physics::RestitutionSpeedDependence shipped = shippedSnookerLaw();
  EXPECT_NEAR(shipped.knee_speed_mps, fit.values[0], 0.005);  // shipped to 2 decimals
  EXPECT_NEAR(shipped.falloff_exponent, fit.values[1], 0.005);
  EXPECT_LT(fit.standard_deviation[0], 0.5);  // the data do fix them
  EXPECT_LT(fit.standard_deviation[1], 0.15);
  double constant_squares = 0;
  for (const CalibratedPoint& p : fit.points) {
    const double constant = rebound(snookerCushion(), p.measured.speed_mps);
    constant_squares += std::pow(constant - p.measured.rebound_speed_mps, 2);
  }
  EXPECT_LT(fit.rms_residual_mps, 0.5 * std::sqrt(constant_squares / 16));
}

// With the shipped law on, a ball rolling head-on into the snooker cushion comes back at a ratio
// that falls with speed above the knee while the rebound speed still grows (it levels off), and
// the paper's points above the knee lie within 2.5 rms residuals of the fit; with e_e constant the
// fastest lie far outside.
TEST(CushionCalibration, TheShippedLawLevelsOffAHeadOnRollingRebound) {
  physics::CushionParams with_law = snookerCushion();
  with_law.restitution_speed_dependence = shippedSnookerLaw();
  const double knee = with_law.restitution_speed_dependence->knee_speed_mps;
  double previous_ratio = 1, previous_rebound = 0;
  for (double speed : {knee, knee + 0.5, knee + 1, 5.0, 8.0, 12.0}) {
    const double speed_out = rebound(with_law, speed);
    EXPECT_LT(speed_out / speed, previous_ratio) << speed;
    EXPECT_GT(speed_out, previous_rebound) << speed;
    previous_ratio = speed_out / speed;
    previous_rebound = speed_out;
  }
  // Below the knee the law changes nothing.
  EXPECT_EQ(rebound(with_law, 1.0), rebound(snookerCushion(), 1.0));
  const CushionCalibration fit = fitOfTheFullSnookerData();
  int fast = 0;
  for (const CushionMeasurement& m : readCushionMeasurements(
           assetsDirectory() + "/measurements/snooker-head-on-rolling.csv")) {
    if (m.speed_mps <= knee) continue;
    ++fast;
    EXPECT_LT(std::abs(rebound(with_law, m.speed_mps) - m.rebound_speed_mps),
              2.5 * fit.rms_residual_mps)
        << m.speed_mps;
  }
  EXPECT_GE(fast, 5);
  EXPECT_GT(rebound(snookerCushion(), 3.42) - 2.75, 5 * fit.rms_residual_mps);
}

TEST(CushionCalibration, ParameterNamesAreTheSceneKeys) {
  for (const std::string& name : fitParameterNames()) {
    ASSERT_TRUE(fitParameterNamed(name)) << name;
    EXPECT_EQ(fitParameterName(*fitParameterNamed(name)), name);
  }
  EXPECT_FALSE(fitParameterNamed("mu_w"));
}

}  // namespace
}  // namespace baize::engine
