#include "engine/fit/fit_uncertainty.h"

#include <gtest/gtest.h>

#include <cmath>

namespace baize::engine {
namespace {

// A straight line y = a + b x through points with known residuals: the textbook covariance.
TEST(FitUncertainty, MatchesTheStraightLineFormulas) {
  const int m = 5;
  Eigen::MatrixXd j(m, 2);
  Eigen::VectorXd r(m);
  for (int i = 0; i < m; ++i) {
    j(i, 0) = 1;
    j(i, 1) = i;
    r[i] = (i % 2 ? 0.1 : -0.1);
  }
  const FitUncertainty u = fitUncertainty(j, r);
  const double s2 = r.squaredNorm() / (m - 2);
  const double sxx = 10;  // sum (x - 2)^2 over 0..4
  EXPECT_NEAR(u.residual_variance, s2, 1e-15);
  EXPECT_NEAR(u.standard_deviation[1], std::sqrt(s2 / sxx), 1e-12);
  EXPECT_NEAR(u.standard_deviation[0], std::sqrt(s2 * (1.0 / m + 4 / sxx)), 1e-12);
  // cov(a, b) = -mean(x) s2 / sxx.
  EXPECT_NEAR(u.correlation(0, 1),
              -2 * s2 / sxx / (u.standard_deviation[0] * u.standard_deviation[1]), 1e-12);
  EXPECT_TRUE(separationProblems(u, {"a", "b"}).empty());
}

TEST(FitUncertainty, NamesParametersTheDataCannotSeparate) {
  Eigen::MatrixXd j(3, 2);
  j << 1, 2.001, 2, 4, 3, 6.002;  // nearly proportional columns
  const FitUncertainty u = fitUncertainty(j, Eigen::Vector3d(0.1, -0.1, 0.1));
  EXPECT_GT(std::abs(u.correlation(0, 1)), kInseparableCorrelation);
  const auto problems = separationProblems(u, {"restitution", "friction"});
  ASSERT_EQ(problems.size(), 1u);
  EXPECT_NE(problems[0].find("cannot separate restitution and friction"), std::string::npos);
}

TEST(FitUncertainty, ASingularJacobianLeavesTheParametersUndetermined) {
  Eigen::MatrixXd j(3, 2);
  j << 1, 0, 2, 0, 3, 0;  // the second parameter changes nothing
  const FitUncertainty u = fitUncertainty(j, Eigen::Vector3d(0.1, -0.1, 0.1));
  EXPECT_TRUE(std::isinf(u.standard_deviation[1]));
  EXPECT_EQ(separationProblems(u, {"a", "b"}).size(), 1u);
}

TEST(FitUncertainty, NamesAParameterWhoseSdReachesItsValue) {
  FitUncertainty u;
  u.standard_deviation = Eigen::Vector2d(0.01, 0.3);
  EXPECT_TRUE(poorlyDetermined(u, Eigen::Vector2d(0.7, 0.31), {"a", "b"}).empty());
  const auto notes = poorlyDetermined(u, Eigen::Vector2d(0.7, 0.2), {"a", "b"});
  ASSERT_EQ(notes.size(), 1u);
  EXPECT_EQ(notes[0].rfind("b is poorly determined", 0), 0u) << notes[0];
}

}  // namespace
}  // namespace baize::engine
