// What a least-squares fit can say about its parameters, from the Jacobian at the optimum:
// covariance s^2 (J^T J)^-1 with s^2 the residual variance, standard deviations, correlations, and
// which parameters the data cannot tell apart.
#pragma once

#include <Eigen/Core>
#include <string>
#include <vector>

namespace baize::engine {

// Two parameters whose estimates correlate more than this are reported as not separated: the data
// constrain (nearly) only a combination of them.
inline constexpr double kInseparableCorrelation = 0.95;
// The same for any group: the smallest singular value of the column-normalised Jacobian, relative
// to its largest, below this. Two parameters at correlation c give sqrt((1 - |c|) / (1 + |c|)),
// 0.16 at 0.95; 0.05 flags groups whose weakest combination is ten times worse than that.
inline constexpr double kNearSingularRatio = 0.05;
// A parameter belongs to the weakest combination when its share of it exceeds this.
inline constexpr double kWeakDirectionShare = 0.3;

struct FitUncertainty {
  double residual_variance = 0;       // s^2 = |r|^2 / (m - n); NaN when m == n
  Eigen::VectorXd standard_deviation;  // sqrt of the covariance's diagonal; inf when singular
  Eigen::MatrixXd correlation;         // NaN where undefined
  double singular_ratio = 0;           // smallest / largest singular value, normalised columns
  Eigen::VectorXd weakest_direction;   // the combination the data constrain least (unit)
};

FitUncertainty fitUncertainty(const Eigen::MatrixXd& jacobian, const Eigen::VectorXd& residuals);

// A parameter whose standard deviation reaches this share of its value is reported as poorly
// determined: the data leave even its size open.
inline constexpr double kPoorlyDeterminedShare = 1.0;

// Sentences naming the parameters whose sd reaches kPoorlyDeterminedShare of their value.
std::vector<std::string> poorlyDetermined(const FitUncertainty& uncertainty,
                                          const Eigen::VectorXd& values,
                                          const std::vector<std::string>& names);

// Sentences naming the parameters the data cannot separate, and why; empty when they can.
std::vector<std::string> separationProblems(const FitUncertainty& uncertainty,
                                            const std::vector<std::string>& names);

}  // namespace baize::engine
