#include "engine/fit/cushion_calibration.h"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <thread>

#include "engine/fit/fit_uncertainty.h"
#include "physics/cloth_motion.h"
#include "physics/cushion_exact_solver.h"
#include "physics/value_text.h"

namespace baize::engine {
namespace {

constexpr double kDegreesPerRadian = 180.0 / M_PI;
// Forward-difference step of the dimensionless parameters (the nose height's is this times R).
// The exact solver's rebound is within about 1e-9 V0 of the converged one, so a step of 1e-5
// keeps the derivatives' error near 1e-4 of themselves, and their truncation error is smaller.
constexpr double kDifferenceStep = 1e-5;
// The ranges the model accepts (validateCushionParams), closed where they are open: a value on
// the edge is moved inside by this share.
constexpr double kOpenEdgeShare = 1e-9;

// The law of `p`, made from kSpeedDependenceFitStart when it has none (its parameters fitted).
physics::RestitutionSpeedDependence& speedDependenceOf(physics::CushionParams& p) {
  if (!p.restitution_speed_dependence) p.restitution_speed_dependence = kSpeedDependenceFitStart;
  return *p.restitution_speed_dependence;
}

double& field(physics::CushionParams& p, CushionFitParameter parameter) {
  switch (parameter) {
    case CushionFitParameter::Restitution: return p.restitution;
    case CushionFitParameter::Friction: return p.cushion_friction;
    case CushionFitParameter::ContactHeight: return p.contact_height_m;
    case CushionFitParameter::SlidingFriction: return p.cloth_friction;
    case CushionFitParameter::KneeSpeed: return speedDependenceOf(p).knee_speed_mps;
    case CushionFitParameter::FalloffExponent: return speedDependenceOf(p).falloff_exponent;
  }
  throw std::logic_error("unknown cushion fit parameter");
}

physics::CushionParams paramsAt(const CushionCalibrationSetup& setup, const Eigen::VectorXd& x) {
  physics::CushionParams p = setup.start;
  for (size_t i = 0; i < setup.fitted.size(); ++i) field(p, setup.fitted[i]) = x[i];
  return p;
}

struct Rebound {
  double speed_mps = 0;
  double angle_deg = 0;
};

Rebound solve(const physics::CushionParams& p, const CushionMeasurement& m) {
  const double alpha_rad = m.angle_deg / kDegreesPerRadian;
  const double spin_unit = m.speed_mps / p.radius_m;  // V0 / R, rad/s
  const physics::CushionImpactResult result = physics::solveCushionImpactExact(
      p, physics::incomingBall(m.speed_mps, alpha_rad, m.topspin_k * spin_unit,
                               m.sidespin_k * spin_unit));
  const Eigen::Vector3d& v = result.after.v;
  return {std::hypot(v.x(), v.y()), std::atan2(-v.y(), v.x()) * kDegreesPerRadian};
}

// Speed residual, then the angle's (as a sideways speed) when measured.
int residualsOf(const CushionMeasurement& m, const Rebound& r, double* out) {
  out[0] = r.speed_mps - m.rebound_speed_mps;
  if (!m.rebound_angle_deg) return 1;
  out[1] = (r.angle_deg - *m.rebound_angle_deg) / kDegreesPerRadian * m.rebound_speed_mps;
  return 2;
}

class Evaluator {
 public:
  Evaluator(const std::vector<CushionMeasurement>& points, const CushionCalibrationSetup& setup)
      : points_(points), setup_(setup) {
    for (const CushionMeasurement& m : points_) {
      offsets_.push_back(residual_count_);
      residual_count_ += m.rebound_angle_deg ? 2 : 1;
    }
  }
  int residualCount() const { return residual_count_; }

  // Every point at every x, spread over the threads; a refusal or failure marks its x not ok.
  void operator()(const std::vector<Eigen::VectorXd>& xs, std::vector<Eigen::VectorXd>* rs,
                  std::vector<bool>* ok) const {
    const size_t tasks = xs.size() * points_.size();
    std::vector<physics::CushionParams> params(xs.size());
    std::vector<char> valid(xs.size(), 1);
    rs->assign(xs.size(), Eigen::VectorXd::Zero(residual_count_));
    for (size_t k = 0; k < xs.size(); ++k) {
      params[k] = paramsAt(setup_, xs[k]);
      try {
        physics::validateCushionParams(params[k]);
      } catch (const std::invalid_argument&) {
        valid[k] = 0;
      }
    }
    std::vector<char> failed(tasks, 0);  // each task writes only its own
    std::atomic<size_t> next{0};
    const auto work = [&] {
      for (size_t t = next++; t < tasks; t = next++) {
        const size_t k = t / points_.size(), i = t % points_.size();
        if (!valid[k]) continue;
        try {
          residualsOf(points_[i], solve(params[k], points_[i]), (*rs)[k].data() + offsets_[i]);
        } catch (const std::exception&) {
          failed[t] = 1;
        }
      }
    };
    const int threads = std::max(1, std::min<int>(setup_.threads, static_cast<int>(tasks)));
    std::vector<std::thread> pool;
    for (int i = 1; i < threads; ++i) pool.emplace_back(work);
    work();
    for (std::thread& thread : pool) thread.join();
    for (size_t t = 0; t < tasks; ++t)
      if (failed[t]) valid[t / points_.size()] = 0;
    ok->assign(valid.begin(), valid.end());
  }

 private:
  const std::vector<CushionMeasurement>& points_;
  const CushionCalibrationSetup& setup_;
  std::vector<int> offsets_;
  int residual_count_ = 0;
};

void boundsOf(const CushionCalibrationSetup& setup, LeastSquaresProblem* problem) {
  const size_t n = setup.fitted.size();
  const double R = setup.start.radius_m;
  problem->lower.resize(n);
  problem->upper.resize(n);
  problem->difference_step.resize(n);
  for (size_t i = 0; i < n; ++i) {
    double lower = 0, upper = 1, step = kDifferenceStep;
    switch (setup.fitted[i]) {
      case CushionFitParameter::Restitution: lower = physics::kMinRestitution; break;
      case CushionFitParameter::Friction: upper = 1 - kOpenEdgeShare; break;  // also < tan(theta)
      case CushionFitParameter::ContactHeight:
        lower = R * (1 + kOpenEdgeShare);
        upper = R * (1 + physics::kMaxNoseSinTheta);
        step = kDifferenceStep * R;
        break;
      case CushionFitParameter::SlidingFriction: upper = 1 - kOpenEdgeShare; break;
      case CushionFitParameter::KneeSpeed:  // m/s; the step as for the others, per 1 m/s
        lower = kOpenEdgeShare;
        upper = physics::kMaxKneeSpeed_mps;
        break;
      case CushionFitParameter::FalloffExponent: upper = physics::kMaxFalloffExponent; break;
    }
    problem->lower[i] = lower;
    problem->upper[i] = upper;
    problem->difference_step[i] = step;
  }
}

// A point the model cannot solve at the start is named by its line.
void checkPointsSolve(const std::vector<CushionMeasurement>& points,
                      const physics::CushionParams& start) {
  for (const CushionMeasurement& m : points) {
    try {
      solve(start, m);
    } catch (const std::exception& failed) {
      throw std::invalid_argument("line " + std::to_string(m.line) +
                                  ": the model cannot solve this impact: " + failed.what());
    }
  }
}

}  // namespace

std::string fitParameterName(CushionFitParameter parameter) {
  switch (parameter) {
    case CushionFitParameter::Restitution: return "restitution";
    case CushionFitParameter::Friction: return "friction";
    case CushionFitParameter::ContactHeight: return "contact_height_m";
    case CushionFitParameter::SlidingFriction: return "sliding_friction";
    case CushionFitParameter::KneeSpeed: return "knee_speed_mps";
    case CushionFitParameter::FalloffExponent: return "falloff_exponent";
  }
  return "";
}

namespace {

constexpr CushionFitParameter kAllFitParameters[] = {
    CushionFitParameter::Restitution,     CushionFitParameter::Friction,
    CushionFitParameter::ContactHeight,   CushionFitParameter::SlidingFriction,
    CushionFitParameter::KneeSpeed,       CushionFitParameter::FalloffExponent};

}  // namespace

std::vector<std::string> fitParameterNames() {
  std::vector<std::string> names;
  for (CushionFitParameter p : kAllFitParameters) names.push_back(fitParameterName(p));
  return names;
}

std::optional<CushionFitParameter> fitParameterNamed(const std::string& name) {
  for (CushionFitParameter p : kAllFitParameters) {
    if (fitParameterName(p) == name) return p;
  }
  return std::nullopt;
}

bool isSpeedDependenceParameter(CushionFitParameter parameter) {
  return parameter == CushionFitParameter::KneeSpeed ||
         parameter == CushionFitParameter::FalloffExponent;
}

physics::CushionParams calibrationStart(const Table& table, const BallSet& ball_set) {
  physics::CushionParams p;
  p.mass_kg = ball_set.mass_kg;
  p.radius_m = ball_set.radius_m;
  p.contact_height_m = table.cushion_contact_height_m;
  p.restitution = table.cushion_restitution;
  p.cushion_friction = table.cushion_friction;
  p.cloth_friction = (table.kind == TableKind::Snooker ? physics::snookerCloth()
                                                       : physics::poolCloth())
                         .sliding_friction;
  return p;
}

CushionCalibration calibrateCushion(const std::vector<CushionMeasurement>& measurements,
                                    const CushionCalibrationSetup& setup) {
  physics::validateCushionParams(setup.start);
  CushionCalibration out;
  out.fitted = setup.fitted;
  std::vector<CushionMeasurement> kept;
  for (const CushionMeasurement& m : measurements) {
    if (m.speed_mps > setup.max_speed_mps) {
      ++out.left_out;
    } else {
      kept.push_back(m);
    }
  }
  const Evaluator evaluator(kept, setup);
  out.residual_count = evaluator.residualCount();
  const int n = static_cast<int>(setup.fitted.size());
  if (out.residual_count < n) {
    throw std::invalid_argument(
        std::to_string(kept.size()) + " points at or below the speed limit " +
        physics::valueText(setup.max_speed_mps) + " m/s (" + std::to_string(out.left_out) +
        " left out above it) give " + std::to_string(out.residual_count) +
        " measured values, fewer than the " + std::to_string(n) +
        " parameters fitted: at least as many are needed");
  }
  Eigen::VectorXd start(n);
  physics::CushionParams first = setup.start;  // with a law when its parameters are fitted
  for (int i = 0; i < n; ++i) start[i] = field(first, setup.fitted[i]);
  checkPointsSolve(kept, first);
  LeastSquaresProblem problem;
  problem.residuals = std::cref(evaluator);
  boundsOf(setup, &problem);
  const LeastSquaresFit fit = fitLeastSquares(problem, start);
  out.values = fit.x;
  out.params = paramsAt(setup, fit.x);
  out.iterations = fit.iterations;
  out.stop = fit.stop;
  const FitUncertainty uncertainty = fitUncertainty(fit.jacobian, fit.residuals);
  out.standard_deviation = uncertainty.standard_deviation;
  out.correlation = uncertainty.correlation;
  std::vector<std::string> names;
  for (CushionFitParameter p : setup.fitted) names.push_back(fitParameterName(p));
  out.separation_problems = separationProblems(uncertainty, names);
  for (const std::string& note : poorlyDetermined(uncertainty, fit.x, names))
    out.separation_problems.push_back(note);
  for (int i = 0; i < n; ++i) {
    out.at_bound.push_back(fit.x[i] <= problem.lower[i] || fit.x[i] >= problem.upper[i]);
  }
  out.rms_residual_mps = std::sqrt(fit.residuals.squaredNorm() / out.residual_count);
  for (const CushionMeasurement& m : kept) {
    const Rebound r = solve(out.params, m);
    out.points.push_back({m, r.speed_mps, r.angle_deg});
  }
  return out;
}

}  // namespace baize::engine
