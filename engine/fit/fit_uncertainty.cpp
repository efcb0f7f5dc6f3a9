#include "engine/fit/fit_uncertainty.h"

#include <Eigen/SVD>
#include <cmath>
#include <limits>

#include "physics/value_text.h"

namespace baize::engine {

FitUncertainty fitUncertainty(const Eigen::MatrixXd& jacobian, const Eigen::VectorXd& residuals) {
  const Eigen::Index m = jacobian.rows();
  const Eigen::Index n = jacobian.cols();
  const double nan = std::numeric_limits<double>::quiet_NaN();
  FitUncertainty u;
  u.residual_variance = m > n ? residuals.squaredNorm() / static_cast<double>(m - n) : nan;
  // Normalised columns: the correlations and the conditioning do not depend on the parameters'
  // units; a column of zeros (a parameter the data ignore) keeps norm 1 and a zero singular value.
  Eigen::VectorXd norms = jacobian.colwise().norm().transpose();
  for (Eigen::Index i = 0; i < n; ++i)
    if (!(norms[i] > 0)) norms[i] = 1;
  const Eigen::MatrixXd normalised = jacobian * norms.cwiseInverse().asDiagonal();
  const Eigen::JacobiSVD<Eigen::MatrixXd> svd(normalised, Eigen::ComputeThinV);
  const Eigen::VectorXd sigma = svd.singularValues();
  u.singular_ratio = sigma[0] > 0 ? sigma[n - 1] / sigma[0] : 0;
  u.weakest_direction = svd.matrixV().col(n - 1);
  // (J^T J)^-1 = D^-1 V S^-2 V^T D^-1 with D the column norms.
  Eigen::MatrixXd inverse = Eigen::MatrixXd::Constant(n, n, nan);
  if (sigma[n - 1] > 0) {
    const Eigen::MatrixXd v = svd.matrixV();
    inverse = norms.cwiseInverse().asDiagonal() * v * sigma.cwiseAbs2().cwiseInverse().asDiagonal() *
              v.transpose() * norms.cwiseInverse().asDiagonal();
  }
  u.standard_deviation.resize(n);
  u.correlation = Eigen::MatrixXd::Constant(n, n, nan);
  for (Eigen::Index i = 0; i < n; ++i) {
    u.standard_deviation[i] = sigma[n - 1] > 0
                                  ? std::sqrt(u.residual_variance * inverse(i, i))
                                  : std::numeric_limits<double>::infinity();
    for (Eigen::Index j = 0; j < n; ++j) {
      if (sigma[n - 1] > 0) u.correlation(i, j) = inverse(i, j) / std::sqrt(inverse(i, i) * inverse(j, j));
    }
  }
  return u;
}

std::vector<std::string> separationProblems(const FitUncertainty& u,
                                            const std::vector<std::string>& names) {
  std::vector<std::string> problems;
  const Eigen::Index n = u.weakest_direction.size();
  for (Eigen::Index i = 0; i < n; ++i) {
    for (Eigen::Index j = i + 1; j < n; ++j) {
      const double c = u.correlation(i, j);
      if (std::isnan(c) || std::abs(c) > kInseparableCorrelation) {
        problems.push_back(
            "the data cannot separate " + names[i] + " and " + names[j] + ": their estimates " +
            (std::isnan(c) ? std::string("are not determined (J^T J is singular)")
                           : "correlate at " + physics::valueText(c)) +
            ", so the data fix only a combination of them; add points that change the rebound "
            "differently (other angles, spins or speeds), or fix one of them");
      }
    }
  }
  if (problems.empty() && n > 1 && u.singular_ratio < kNearSingularRatio) {
    std::string group;
    for (Eigen::Index i = 0; i < n; ++i) {
      if (std::abs(u.weakest_direction[i]) > kWeakDirectionShare)
        group += (group.empty() ? "" : ", ") + names[i];
    }
    problems.push_back("the data nearly fail to separate " + group +
                       ": J^T J is near singular (smallest to largest singular value of the "
                       "normalised Jacobian " +
                       physics::valueText(u.singular_ratio) + ", below " +
                       physics::valueText(kNearSingularRatio) + ")");
  }
  return problems;
}

std::vector<std::string> poorlyDetermined(const FitUncertainty& u, const Eigen::VectorXd& values,
                                          const std::vector<std::string>& names) {
  std::vector<std::string> notes;
  for (Eigen::Index i = 0; i < values.size(); ++i) {
    const double sd = u.standard_deviation[i];
    if (std::isfinite(sd) && sd >= kPoorlyDeterminedShare * std::abs(values[i])) {
      notes.push_back(names[i] + " is poorly determined: its standard deviation " +
                      physics::valueText(sd) + " is as large as its value " +
                      physics::valueText(values[i]) + "; the data hardly constrain it");
    }
  }
  return notes;
}

}  // namespace baize::engine
