#include "tools/baize/cushion_run.h"

#include <cmath>
#include <sstream>

#include "physics/cushion_tabulated_solver.h"

namespace baize::tools {
namespace {
constexpr double kPi = 3.14159265358979323846;
constexpr double kRadiansPerDegree = kPi / 180.0;
}  // namespace

std::string solverName(SolverKind kind) {
  switch (kind) {
    case SolverKind::Paper:
      return "paper";
    case SolverKind::Exact:
      return "exact";
    case SolverKind::Tabulated:
      return "tabulated";
  }
  return "unknown";
}

double defaultTolerance(SolverKind kind) {
  return kind == SolverKind::Tabulated ? physics::kTabulatedFallbackTolerance
                                       : physics::ExactSolverOptions{}.tolerance;
}

SolverSetting tabulatedDefault() {
  SolverSetting setting;
  setting.kind = SolverKind::Tabulated;
  setting.exact_tolerance = defaultTolerance(SolverKind::Tabulated);
  return setting;
}

std::string settingLabel(const SolverSetting& setting) {
  if (setting.kind == SolverKind::Paper) return "N=" + std::to_string(setting.paper_steps);
  if (setting.exact_tolerance == defaultTolerance(setting.kind)) return "default";
  std::ostringstream label;
  label << "tol=" << setting.exact_tolerance;
  return label.str();
}

physics::BallVelocity incomingBallOf(const CushionShot& shot, double radius_m) {
  const double spin_unit_radps = shot.speed_mps / radius_m;  // V0 / R
  return physics::incomingBall(shot.speed_mps, shot.angle_deg * kRadiansPerDegree,
                               shot.topspin_k * spin_unit_radps, shot.sidespin_k * spin_unit_radps);
}

physics::CushionImpactResult solveCushionShot(const physics::CushionParams& params,
                                              const physics::BallVelocity& incoming,
                                              const SolverSetting& setting, bool record_trace) {
  if (setting.kind == SolverKind::Paper) {
    physics::PaperSolverOptions options;
    options.steps = setting.paper_steps;
    options.record_trace = record_trace;
    return physics::solveCushionImpactPaper(params, incoming, options);
  }
  // The table's fallback keeps its own options (error share, step control) at whatever tolerance
  // is asked for.
  physics::ExactSolverOptions options = setting.kind == SolverKind::Tabulated
                                            ? physics::tabulatedFallbackOptions()
                                            : physics::ExactSolverOptions{};
  options.tolerance = setting.exact_tolerance;
  if (record_trace) {
    const double impact_scale_Ns = (1 + params.restitution) * params.mass_kg * incoming.v.y();
    options.trace_spacing_Ns = impact_scale_Ns / kTraceSamples;
  }
  if (setting.kind == SolverKind::Tabulated)
    return physics::solveCushionImpactTabulated(params, incoming, options);
  return physics::solveCushionImpactExact(params, incoming, options);
}

Rebound reboundOf(const physics::BallVelocity& after) {
  return {std::hypot(after.v.x(), after.v.y()),
          std::atan2(-after.v.y(), after.v.x()) / kRadiansPerDegree};
}

}  // namespace baize::tools
