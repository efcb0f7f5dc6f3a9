#include "engine/fit/least_squares.h"

#include <gtest/gtest.h>

#include <cmath>

namespace baize::engine {
namespace {

// Residuals y_i - a exp(b t_i) at every x of the batch.
BatchResidualFunction exponential(const std::vector<double>& t, const std::vector<double>& y) {
  return [t, y](const std::vector<Eigen::VectorXd>& xs, std::vector<Eigen::VectorXd>* rs,
                std::vector<bool>* ok) {
    rs->clear();
    ok->clear();
    for (const Eigen::VectorXd& x : xs) {
      Eigen::VectorXd r(t.size());
      for (size_t i = 0; i < t.size(); ++i) r[i] = x[0] * std::exp(x[1] * t[i]) - y[i];
      rs->push_back(r);
      ok->push_back(true);
    }
  };
}

LeastSquaresProblem problemFor(const std::vector<double>& t, const std::vector<double>& y) {
  LeastSquaresProblem p;
  p.residuals = exponential(t, y);
  p.lower = Eigen::Vector2d(-10, -10);
  p.upper = Eigen::Vector2d(10, 10);
  p.difference_step = Eigen::Vector2d(1e-7, 1e-7);
  return p;
}

TEST(LeastSquares, FindsTheParametersOfExactData) {
  std::vector<double> t, y;
  for (int i = 0; i < 10; ++i) {
    t.push_back(0.2 * i);
    y.push_back(2.5 * std::exp(-1.3 * t.back()));
  }
  const LeastSquaresFit fit = fitLeastSquares(problemFor(t, y), Eigen::Vector2d(1, 0));
  EXPECT_NEAR(fit.x[0], 2.5, 1e-6);
  EXPECT_NEAR(fit.x[1], -1.3, 1e-6);
  EXPECT_LT(fit.residuals.norm(), 1e-6);
  EXPECT_NE(fit.stop, LeastSquaresStop::IterationLimit);
}

TEST(LeastSquares, StaysInsideTheBounds) {
  std::vector<double> t = {0, 1, 2}, y = {3, 3, 3};  // best unbounded: a = 3, b = 0
  LeastSquaresProblem p = problemFor(t, y);
  p.upper = Eigen::Vector2d(2, 10);  // a may not reach 3
  const LeastSquaresFit fit = fitLeastSquares(p, Eigen::Vector2d(1, 0.5));
  EXPECT_LE(fit.x[0], 2);
  EXPECT_NEAR(fit.x[0], 2, 1e-6);
}

TEST(LeastSquares, RefusesAStartItCannotEvaluate) {
  LeastSquaresProblem p = problemFor({0, 1}, {1, 1});
  p.residuals = [](const std::vector<Eigen::VectorXd>& xs, std::vector<Eigen::VectorXd>* rs,
                   std::vector<bool>* ok) {
    rs->assign(xs.size(), Eigen::VectorXd::Zero(2));
    ok->assign(xs.size(), false);
  };
  EXPECT_THROW(fitLeastSquares(p, Eigen::Vector2d(1, 0)), std::invalid_argument);
}

}  // namespace
}  // namespace baize::engine
