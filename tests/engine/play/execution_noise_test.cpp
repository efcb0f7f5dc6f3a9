#include "engine/play/execution_noise.h"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

namespace baize::engine {
namespace {

constexpr double kPoolRadius_m = 0.028575;
constexpr double kDegToRad = M_PI / 180;
// Statistical checks allow this many standard errors: a correct generator fails one of them with
// probability below 1e-5 for any seed (and the seeds are fixed, so the outcome never changes).
constexpr double kStandardErrors = 5;

struct Moments {
  double mean = 0;
  double variance = 0;
};

Moments moments(const std::vector<double>& x) {
  Moments m;
  for (double v : x) m.mean += v;
  m.mean /= x.size();
  for (double v : x) m.variance += (v - m.mean) * (v - m.mean);
  m.variance /= x.size() - 1;
  return m;
}

TEST(NormalGenerator, TheSameSeedGivesTheSameDeviatesAndAnotherSeedOthers) {
  NormalGenerator a(42), b(42), c(43);
  int differ = 0;
  for (int i = 0; i < 1000; ++i) {
    const double x = a.next();
    EXPECT_EQ(x, b.next());
    differ += x != c.next();
  }
  EXPECT_EQ(differ, 1000);
}

TEST(NormalGenerator, DeviatesHaveMeanZeroVarianceOneAndNormalTails) {
  constexpr int kSamples = 200000;
  NormalGenerator normal(7);
  std::vector<double> x(kSamples);
  int beyond_two = 0;
  for (double& v : x) {
    v = normal.next();
    beyond_two += std::abs(v) > 2;
  }
  const Moments m = moments(x);
  EXPECT_NEAR(m.mean, 0, kStandardErrors / std::sqrt(kSamples));
  // The sample variance of normal deviates has standard error sqrt(2 / (n - 1)).
  EXPECT_NEAR(m.variance, 1, kStandardErrors * std::sqrt(2.0 / (kSamples - 1)));
  // P(|Z| > 2) = 0.0455003; a binomial count's standard error.
  const double p = 0.04550026;
  EXPECT_NEAR(beyond_two / double(kSamples), p,
              kStandardErrors * std::sqrt(p * (1 - p) / kSamples));
}

TEST(ExecutionNoise, EachErrorHasTheConfiguredSigmaAndNoBias) {
  constexpr int kSamples = 100000;
  ExecutionNoise noise;  // the defaults
  NormalGenerator normal(2024);
  std::vector<double> side, height, elevation, aim, speed;
  for (int i = 0; i < kSamples; ++i) {
    const ExecutionError e = drawExecutionError(noise, kPoolRadius_m, &normal);
    side.push_back(e.side_offset);
    height.push_back(e.height_offset);
    elevation.push_back(e.elevation_rad);
    aim.push_back(e.heading_rad);
    speed.push_back(e.speed_mps);
  }
  const struct {
    const std::vector<double>& values;
    double sigma;
  } expected[] = {{side, 0.0005 / kPoolRadius_m},
                  {height, 0.0005 / kPoolRadius_m},
                  {elevation, 0.1 * kDegToRad},
                  {aim, 0.125 * kDegToRad},
                  {speed, 0.075}};
  for (const auto& e : expected) {
    const Moments m = moments(e.values);
    EXPECT_NEAR(m.mean, 0, kStandardErrors * e.sigma / std::sqrt(kSamples));
    // The sample standard deviation has standard error sigma / sqrt(2 (n - 1)).
    EXPECT_NEAR(std::sqrt(m.variance), e.sigma,
                kStandardErrors * e.sigma / std::sqrt(2.0 * (kSamples - 1)));
  }
}

TEST(ExecutionNoise, ErrorsAreUncorrelated) {
  constexpr int kSamples = 100000;
  NormalGenerator normal(99);
  double sum = 0;
  ExecutionNoise noise;
  noise.tip_offset_sigma_m = kPoolRadius_m;  // unit sigma on the offsets
  for (int i = 0; i < kSamples; ++i) {
    const ExecutionError e = drawExecutionError(noise, kPoolRadius_m, &normal);
    sum += e.side_offset * e.height_offset;
  }
  // The mean product of independent unit normals has standard error 1 / sqrt(n).
  EXPECT_NEAR(sum / kSamples, 0, kStandardErrors / std::sqrt(kSamples));
}

TEST(ExecutionNoise, ZeroSigmasLeaveTheShotAsIntended) {
  ExecutionNoise none{0, 0, 0, 0};
  NormalGenerator normal(1);
  physics::CueShot shot{1.5, 0.3, 0.05, 0.1, -0.2};
  const physics::CueShot same =
      perturbedShot(shot, drawExecutionError(none, kPoolRadius_m, &normal));
  EXPECT_EQ(same.speed_mps, shot.speed_mps);
  EXPECT_EQ(same.heading_rad, shot.heading_rad);
  EXPECT_EQ(same.elevation_rad, shot.elevation_rad);
  EXPECT_EQ(same.side_offset, shot.side_offset);
  EXPECT_EQ(same.height_offset, shot.height_offset);
}

TEST(ExecutionNoise, ElevationFoldsAtLevelAndSpeedStopsAtZero) {
  physics::CueShot shot{0.05, 0, 0.001, 0, 0};
  ExecutionError error;
  error.elevation_rad = -0.003;
  error.speed_mps = -0.2;
  const physics::CueShot p = perturbedShot(shot, error);
  EXPECT_DOUBLE_EQ(p.elevation_rad, 0.002);
  EXPECT_EQ(p.speed_mps, 0.0);
}

TEST(ExecutionNoise, SampleSeedsDependOnEveryArgument) {
  EXPECT_EQ(sampleSeed(1, 2, 3), sampleSeed(1, 2, 3));
  EXPECT_NE(sampleSeed(1, 2, 3), sampleSeed(2, 2, 3));
  EXPECT_NE(sampleSeed(1, 2, 3), sampleSeed(1, 3, 3));
  EXPECT_NE(sampleSeed(1, 2, 3), sampleSeed(1, 2, 4));
  EXPECT_NE(sampleSeed(0, 1, 0), sampleSeed(0, 0, 1));  // case and sample do not commute
}

TEST(ExecutionNoise, NegativeOrNonFiniteSigmasAreRefused) {
  ExecutionNoise noise;
  noise.aim_sigma_deg = -1;
  EXPECT_THROW(validateExecutionNoise(noise), std::invalid_argument);
  noise = ExecutionNoise{};
  noise.speed_sigma_mps = NAN;
  EXPECT_THROW(validateExecutionNoise(noise), std::invalid_argument);
  EXPECT_NO_THROW(validateExecutionNoise(ExecutionNoise{}));
}

}  // namespace
}  // namespace baize::engine
