#include "engine/fit/least_squares.h"

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace baize::engine {
namespace {

// Marquardt's damping: start small (near Gauss-Newton), grow on a failed step, shrink on a good
// one; past the limit the step is a vanishing gradient step and nothing better lies near x.
constexpr double kInitialDamping = 1e-3;
constexpr double kDampingGrowth = 10;
constexpr double kDampingShrink = 1.0 / 3.0;
constexpr double kMaxDamping = 1e12;
// Marquardt's scaling uses the diagonal of J^T J; a parameter the residuals do not depend on
// would get a zero there, so the diagonal is kept above this share of its largest entry.
constexpr double kMinScaleShare = 1e-12;

Eigen::VectorXd clamped(const Eigen::VectorXd& x, const LeastSquaresProblem& p) {
  return x.cwiseMax(p.lower).cwiseMin(p.upper);
}

double costOf(const Eigen::VectorXd& r) { return r.squaredNorm(); }

// The residuals at x and the Jacobian there, evaluated in one batch. A step that would leave the
// bounds or the model is taken backwards instead. Returns false if x itself cannot be evaluated.
bool evaluateWithJacobian(const LeastSquaresProblem& p, const Eigen::VectorXd& x,
                          Eigen::VectorXd* r, Eigen::MatrixXd* jacobian) {
  const int n = static_cast<int>(x.size());
  std::vector<Eigen::VectorXd> xs = {x};
  std::vector<double> steps(n);
  for (int i = 0; i < n; ++i) {
    steps[i] = x[i] + p.difference_step[i] <= p.upper[i] ? p.difference_step[i]
                                                         : -p.difference_step[i];
    xs.push_back(x);
    xs.back()[i] += steps[i];
  }
  std::vector<Eigen::VectorXd> rs;
  std::vector<bool> ok;
  p.residuals(xs, &rs, &ok);
  if (!ok[0]) return false;
  *r = rs[0];
  jacobian->resize(r->size(), n);
  for (int i = 0; i < n; ++i) {
    if (!ok[i + 1]) {  // the forward step left the model: step back instead
      std::vector<Eigen::VectorXd> back = {x};
      back[0][i] -= steps[i];
      std::vector<Eigen::VectorXd> rb;
      std::vector<bool> okb;
      p.residuals(back, &rb, &okb);
      if (!okb[0]) return false;
      jacobian->col(i) = (*r - rb[0]) / steps[i];
    } else {
      jacobian->col(i) = (rs[i + 1] - *r) / steps[i];
    }
  }
  return true;
}

bool evaluate(const LeastSquaresProblem& p, const Eigen::VectorXd& x, Eigen::VectorXd* r) {
  std::vector<Eigen::VectorXd> rs;
  std::vector<bool> ok;
  p.residuals({x}, &rs, &ok);
  if (!ok[0] || !rs[0].allFinite()) return false;
  *r = rs[0];
  return true;
}

}  // namespace

LeastSquaresFit fitLeastSquares(const LeastSquaresProblem& p, const Eigen::VectorXd& start) {
  const Eigen::Index n = start.size();
  if (p.lower.size() != n || p.upper.size() != n || p.difference_step.size() != n) {
    throw std::invalid_argument("least squares: bounds, steps and start differ in size");
  }
  LeastSquaresFit fit;
  fit.x = clamped(start, p);
  if (!evaluateWithJacobian(p, fit.x, &fit.residuals, &fit.jacobian)) {
    throw std::invalid_argument("least squares: the model cannot be evaluated at the start");
  }
  double damping = kInitialDamping;
  for (fit.iterations = 1; fit.iterations <= kMaxIterations; ++fit.iterations) {
    const Eigen::MatrixXd normal = fit.jacobian.transpose() * fit.jacobian;
    const Eigen::VectorXd gradient = fit.jacobian.transpose() * fit.residuals;
    const Eigen::VectorXd scale =
        normal.diagonal().cwiseMax(kMinScaleShare * std::max(normal.diagonal().maxCoeff(), 1e-300));
    const double cost = costOf(fit.residuals);
    bool accepted = false;
    Eigen::VectorXd x_new, r_new;
    while (damping <= kMaxDamping) {
      Eigen::MatrixXd damped = normal;
      damped.diagonal() += damping * scale;
      x_new = clamped(fit.x - damped.ldlt().solve(gradient), p);
      if (evaluate(p, x_new, &r_new) && costOf(r_new) < cost) {
        accepted = true;
        break;
      }
      damping *= kDampingGrowth;
    }
    if (!accepted) {
      fit.stop = LeastSquaresStop::NoBetterStep;
      return fit;
    }
    damping = std::max(damping * kDampingShrink, 1e-12);
    const Eigen::VectorXd moved = x_new - fit.x;
    const double cost_drop = cost - costOf(r_new);
    fit.x = x_new;
    if (!evaluateWithJacobian(p, fit.x, &fit.residuals, &fit.jacobian)) {
      throw std::logic_error("least squares: an accepted point could not be evaluated again");
    }
    const Eigen::VectorXd size = fit.x.cwiseAbs().cwiseMax(p.difference_step);
    if ((moved.cwiseAbs().array() <= kStepTolerance * size.array()).all()) {
      fit.stop = LeastSquaresStop::StepNegligible;
      return fit;
    }
    if (cost_drop <= kCostTolerance * cost) {
      fit.stop = LeastSquaresStop::CostStalled;
      return fit;
    }
  }
  fit.iterations = kMaxIterations;
  fit.stop = LeastSquaresStop::IterationLimit;
  return fit;
}

std::string stopText(LeastSquaresStop stop) {
  switch (stop) {
    case LeastSquaresStop::StepNegligible: return "the step became negligible";
    case LeastSquaresStop::CostStalled: return "the sum of squares stopped falling";
    case LeastSquaresStop::NoBetterStep: return "no nearby point has a lower sum of squares";
    case LeastSquaresStop::IterationLimit: return "the iteration limit was reached";
  }
  return "";
}

}  // namespace baize::engine
