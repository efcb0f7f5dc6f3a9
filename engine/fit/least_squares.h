// Bounded nonlinear least squares: Levenberg-Marquardt with Marquardt's diagonal scaling and a
// forward-difference Jacobian, for small problems (a few parameters, a few hundred residuals)
// whose residuals are costly (each one an exact cushion-impact solve). No knowledge of cushions.
#pragma once

#include <Eigen/Core>
#include <functional>
#include <string>
#include <vector>

namespace baize::engine {

// The residuals at several parameter vectors at once (the solver asks for the point and its
// difference steps together, so a caller can spread them over threads); ok[i] false where the
// model cannot be evaluated (it refuses those parameters): the solver treats that as no better.
using BatchResidualFunction = std::function<void(const std::vector<Eigen::VectorXd>& xs,
                                                 std::vector<Eigen::VectorXd>* residuals,
                                                 std::vector<bool>* ok)>;

struct LeastSquaresProblem {
  BatchResidualFunction residuals;
  Eigen::VectorXd lower;            // box bounds, each x_i in [lower_i, upper_i]
  Eigen::VectorXd upper;
  Eigen::VectorXd difference_step;  // forward-difference step of each parameter (> 0)
};

// Why the iteration stopped.
enum class LeastSquaresStop {
  StepNegligible,  // the last accepted step moved every parameter by under kStepTolerance
  CostStalled,     // the sum of squares fell by under kCostTolerance of itself
  NoBetterStep,    // the damping grew past its limit without finding a lower sum of squares
  IterationLimit,  // kMaxIterations reached
};

struct LeastSquaresFit {
  Eigen::VectorXd x;          // the parameters at the optimum found
  Eigen::VectorXd residuals;  // there
  Eigen::MatrixXd jacobian;   // d residuals / d x there (forward or, at an upper bound, backward)
  int iterations = 0;         // Jacobians computed
  LeastSquaresStop stop = LeastSquaresStop::IterationLimit;
};

// Relative sizes below which the iteration stops (see LeastSquaresStop). The residuals come from
// an adaptive solver accurate to about 1e-9 of the speeds: finer changes of the cost are its noise.
inline constexpr double kStepTolerance = 1e-9;
inline constexpr double kCostTolerance = 1e-12;
inline constexpr int kMaxIterations = 200;

// Minimises |r(x)|^2 from `start` (projected into the bounds). Throws std::invalid_argument when
// the sizes disagree or the residuals cannot be evaluated at the start.
LeastSquaresFit fitLeastSquares(const LeastSquaresProblem& problem, const Eigen::VectorXd& start);

std::string stopText(LeastSquaresStop stop);

}  // namespace baize::engine
