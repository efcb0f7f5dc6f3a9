// Fitting the Mathavan 2010 cushion model to measured impacts (docs/calibrate.md): the parameters
// chosen (restitution e_e and nose friction mu_w by default; the nose height and the cloth friction
// on request) minimise the squared differences between the measured rebounds and those the exact
// solver gives. Each evaluation solves every impact exactly; impacts run on threads.
#pragma once

#include <Eigen/Core>
#include <optional>
#include <string>
#include <vector>

#include "engine/fit/cushion_measurements.h"
#include "engine/fit/least_squares.h"
#include "engine/io/ball_set.h"
#include "engine/io/table.h"
#include "physics/cushion_model.h"

namespace baize::engine {

enum class CushionFitParameter {
  Restitution,
  Friction,
  ContactHeight,
  SlidingFriction,
  KneeSpeed,        // the speed dependence of the restitution (physics/cushion_restitution_speed.h)
  FalloffExponent,
};

// Named as a scene's physics groups name them: "restitution", "friction", "contact_height_m"
// (physics.cushion), "sliding_friction" (physics.cloth), "knee_speed_mps" and "falloff_exponent"
// (physics.cushion.restitution_speed_dependence).
std::string fitParameterName(CushionFitParameter parameter);
std::optional<CushionFitParameter> fitParameterNamed(const std::string& name);
std::vector<std::string> fitParameterNames();

// The rigid model's range as the paper fitted it: points faster than this are left out by default.
inline constexpr double kDefaultCalibrationMaxSpeed_mps = 1.5;

// Whether `parameter` belongs to the restitution's speed dependence.
bool isSpeedDependenceParameter(CushionFitParameter parameter);

// Where a fit of the speed dependence starts when the start values have none: the knee at the
// paper's stated range of the rigid model (2.5 m/s), the exponent midway in [0, 1].
inline constexpr physics::RestitutionSpeedDependence kSpeedDependenceFitStart{2.5, 0.5};

struct CushionCalibrationSetup {
  // The ball, the values held fixed and the fitted ones' start. Fitting the speed dependence
  // starts from its law, or kSpeedDependenceFitStart when it has none.
  physics::CushionParams start;
  std::vector<CushionFitParameter> fitted = {CushionFitParameter::Restitution,
                                             CushionFitParameter::Friction};
  double max_speed_mps = kDefaultCalibrationMaxSpeed_mps;  // faster points are left out
  int threads = 1;  // impacts solved at once; the result does not depend on it
};

// The starting parameters of a table and ball set: its ball, its cushion's nose height,
// restitution and friction, and the cloth friction of its kind.
physics::CushionParams calibrationStart(const Table& table, const BallSet& ball_set);

struct CalibratedPoint {
  CushionMeasurement measured;
  double fitted_speed_mps = 0;  // the model's rebound at the fitted parameters
  double fitted_angle_deg = 0;
};

struct CushionCalibration {
  std::vector<CushionFitParameter> fitted;
  physics::CushionParams params;       // at the optimum (the fixed ones as given)
  Eigen::VectorXd values;              // the fitted parameters, in `fitted` order
  Eigen::VectorXd standard_deviation;  // inf where the data do not determine them
  Eigen::MatrixXd correlation;         // NaN where undefined
  std::vector<bool> at_bound;          // the value sits on its range's end
  // fit_uncertainty's separationProblems, then its poorlyDetermined notes
  std::vector<std::string> separation_problems;
  std::vector<CalibratedPoint> points;           // those fitted, in file order
  int left_out = 0;                              // points above max_speed_mps
  int residual_count = 0;                        // speeds plus the angles measured
  double rms_residual_mps = 0;  // angle residuals count as rebound speed x angle error (rad)
  int iterations = 0;
  LeastSquaresStop stop = LeastSquaresStop::IterationLimit;
};

// Fits. Throws std::invalid_argument when the points kept give fewer residuals than parameters,
// when a point cannot be solved at the start (naming its line), or when the start is refused by
// the model (validateCushionParams' message).
CushionCalibration calibrateCushion(const std::vector<CushionMeasurement>& measurements,
                                    const CushionCalibrationSetup& setup);

}  // namespace baize::engine
