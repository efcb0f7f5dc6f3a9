#include "tools/baize/calibrate_report.h"

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <numeric>
#include <string>
#include <vector>

#include "engine/models/cushion_mathavan2010.h"

namespace baize::tools {
namespace {

std::string nameOf(const engine::CushionCalibration& fit, size_t i) {
  return engine::fitParameterName(fit.fitted[i]);
}

// JSON has no NaN or infinity: an undetermined value is null.
nlohmann::json numberOrNull(double value) {
  return std::isfinite(value) ? nlohmann::json(value) : nlohmann::json(nullptr);
}

void printValues(const engine::CushionCalibration& fit, std::ostream& out) {
  for (size_t i = 0; i < fit.fitted.size(); ++i) {
    out << "  " << std::left << std::setw(18) << nameOf(fit, i) << std::right << " = "
        << fit.values[i] << " +- " << fit.standard_deviation[i] << " (1 sd)"
        << (fit.at_bound[i] ? ", at the end of its range" : "") << '\n';
  }
  for (size_t i = 0; i < fit.fitted.size(); ++i) {
    for (size_t j = i + 1; j < fit.fitted.size(); ++j) {
      out << "  correlation " << nameOf(fit, i) << " / " << nameOf(fit, j) << ": "
          << fit.correlation(i, j) << '\n';
    }
  }
  for (const std::string& problem : fit.separation_problems) out << "  NOTE: " << problem << '\n';
}

double speedResidual(const engine::CalibratedPoint& p) {
  return p.fitted_speed_mps - p.measured.rebound_speed_mps;
}

void printPoint(const engine::CalibratedPoint& p, std::ostream& out) {
  const engine::CushionMeasurement& m = p.measured;
  out << "  " << std::setw(5) << m.line << std::setw(9) << m.speed_mps << std::setw(8)
      << m.angle_deg << std::setw(8) << m.topspin_k << std::setw(9) << m.sidespin_k << std::fixed
      << std::setprecision(4) << std::setw(10) << m.rebound_speed_mps << std::setw(10)
      << p.fitted_speed_mps << std::setw(10) << speedResidual(p) << std::setprecision(2);
  if (m.rebound_angle_deg) {
    out << std::setw(9) << *m.rebound_angle_deg << std::setw(9) << p.fitted_angle_deg;
  }
  out << std::defaultfloat << std::setprecision(6) << '\n';
}

void printPoints(const engine::CushionCalibration& fit, std::ostream& out) {
  std::vector<size_t> order(fit.points.size());
  std::iota(order.begin(), order.end(), 0);
  if (fit.points.size() > static_cast<size_t>(kListedPoints)) {
    std::stable_sort(order.begin(), order.end(), [&](size_t a, size_t b) {
      return std::abs(speedResidual(fit.points[a])) > std::abs(speedResidual(fit.points[b]));
    });
    order.resize(kLargestResidualsShown);
    out << "the " << kLargestResidualsShown << " largest speed residuals:\n";
  } else {
    out << "points:\n";
  }
  out << "   line   V0 m/s   alpha topspin sidespin  measured    fitted  residual"
      << "    angle   fitted\n";
  for (size_t i : order) printPoint(fit.points[i], out);
}

}  // namespace

void printCalibration(const engine::CushionCalibration& fit, std::ostream& out) {
  out << std::setprecision(6);
  out << "fitted " << fit.points.size() << " points (" << fit.residual_count
      << " measured values); " << fit.left_out << " left out above the speed limit\n";
  printValues(fit, out);
  out << "  rms residual " << fit.rms_residual_mps << " m/s; " << fit.iterations
      << " iterations, stopped because " << engine::stopText(fit.stop) << '\n';
  printPoints(fit, out);
}

nlohmann::json calibrationJson(const engine::CushionCalibration& fit) {
  nlohmann::json out = nlohmann::json::object();
  nlohmann::json fitted = nlohmann::json::array(), at_bound = nlohmann::json::array();
  nlohmann::json correlation = nlohmann::json::array();
  for (size_t i = 0; i < fit.fitted.size(); ++i) {
    out[nameOf(fit, i)] = fit.values[i];
    out[nameOf(fit, i) + "_sd"] = numberOrNull(fit.standard_deviation[i]);
    fitted.push_back(nameOf(fit, i));
    if (fit.at_bound[i]) at_bound.push_back(nameOf(fit, i));
    nlohmann::json row = nlohmann::json::array();
    for (size_t j = 0; j < fit.fitted.size(); ++j) row.push_back(numberOrNull(fit.correlation(i, j)));
    correlation.push_back(row);
  }
  nlohmann::json points = nlohmann::json::array();
  for (const engine::CalibratedPoint& p : fit.points) {
    nlohmann::json point = {{"line", p.measured.line},
                            {"speed_mps", p.measured.speed_mps},
                            {"angle_deg", p.measured.angle_deg},
                            {"topspin", p.measured.topspin_k},
                            {"sidespin", p.measured.sidespin_k},
                            {"rebound_speed_mps", p.measured.rebound_speed_mps},
                            {"fitted_speed_mps", p.fitted_speed_mps},
                            {"fitted_angle_deg", p.fitted_angle_deg}};
    if (p.measured.rebound_angle_deg) point["rebound_angle_deg"] = *p.measured.rebound_angle_deg;
    points.push_back(point);
  }
  out["fitted"] = fitted;
  out["at_bound"] = at_bound;
  out["correlation"] = correlation;
  out["not_separated"] = fit.separation_problems;
  out["model"] = {{"mass_kg", fit.params.mass_kg},
                  {"radius_m", fit.params.radius_m},
                  {"contact_height_m", fit.params.contact_height_m},
                  {"restitution", fit.params.restitution},
                  {"friction", fit.params.cushion_friction},
                  {"sliding_friction", fit.params.cloth_friction}};
  if (const auto& law = fit.params.restitution_speed_dependence) {
    out["model"][engine::kRestitutionSpeedDependenceKey] =
        engine::restitutionSpeedDependenceJson(*law);
  }
  out["points_fitted"] = fit.points.size();
  out["points_left_out"] = fit.left_out;
  out["rms_residual_mps"] = fit.rms_residual_mps;
  out["iterations"] = fit.iterations;
  out["points"] = points;
  return out;
}

}  // namespace baize::tools
