#include "python/cushion_bindings.h"

#include <pybind11/numpy.h>
#include <pybind11/stl.h>

#include <cmath>
#include <optional>

#include "physics/cushion_exact_solver.h"
#include "physics/cushion_paper_solver.h"
#include "physics/cushion_restitution_speed.h"

namespace baize::python {
namespace {

namespace py = pybind11;

constexpr double kRadiansPerDegree = 3.14159265358979323846 / 180.0;
// The paper's cushion nose height, in ball radii: h = 7R/5.
constexpr double kPaperContactHeight_R = 7.0 / 5.0;

py::array_t<double> vector3(const Eigen::Vector3d& v) {
  py::array_t<double> out(3);
  auto view = out.mutable_unchecked<1>();
  for (int k = 0; k < 3; ++k) view(k) = v[k];
  return out;
}

void requireFinite(const char* name, double value) {
  if (!std::isfinite(value))
    throw py::value_error(std::string(name) + " = " + std::to_string(value) + " is not finite");
}

// The optional speed dependence of e_e, as a scene's physics.cushion.restitution_speed_dependence:
// a mapping with exactly knee_speed_mps and falloff_exponent.
physics::RestitutionSpeedDependence speedLawOf(const py::dict& given) {
  constexpr const char* kName = "restitution_speed_dependence";
  for (const auto& [key, value] : given) {
    const std::string name = py::str(key);
    if (name != "knee_speed_mps" && name != "falloff_exponent") {
      throw py::value_error(std::string(kName) + " key '" + name +
                            "' is not allowed: the keys are knee_speed_mps and falloff_exponent");
    }
  }
  physics::RestitutionSpeedDependence law;
  for (const auto& [key, field] :
       {std::pair<const char*, double physics::RestitutionSpeedDependence::*>{
            "knee_speed_mps", &physics::RestitutionSpeedDependence::knee_speed_mps},
        {"falloff_exponent", &physics::RestitutionSpeedDependence::falloff_exponent}}) {
    if (!given.contains(key)) {
      throw py::value_error(std::string(kName) + " has no " + key +
                            ": it needs both knee_speed_mps (m/s) and falloff_exponent");
    }
    law.*field = py::cast<double>(given[key]);
  }
  physics::validateRestitutionSpeedDependence(law);  // ValueError naming the key and value
  return law;
}

py::dict cushionImpact(double speed, double angle_deg, double topspin, double sidespin,
                       const std::string& solver, double mass, double radius,
                       std::optional<double> contact_height, double restitution,
                       double cushion_friction, double cloth_friction,
                       const std::optional<py::dict>& restitution_speed_dependence, int steps,
                       std::optional<double> tolerance) {
  for (const auto& [name, value] : {std::pair<const char*, double>{"speed", speed},
                                    {"angle_deg", angle_deg}, {"topspin", topspin},
                                    {"sidespin", sidespin}, {"mass", mass}, {"radius", radius}}) {
    requireFinite(name, value);
  }
  physics::CushionParams params;
  params.mass_kg = mass;
  params.radius_m = radius;
  params.contact_height_m = contact_height.value_or(radius * kPaperContactHeight_R);
  params.restitution = restitution;
  params.cushion_friction = cushion_friction;
  params.cloth_friction = cloth_friction;
  if (restitution_speed_dependence)
    params.restitution_speed_dependence = speedLawOf(*restitution_speed_dependence);
  const double spin_unit_radps = speed / radius;  // V0 / R
  const physics::BallVelocity incoming = physics::incomingBall(
      speed, angle_deg * kRadiansPerDegree, topspin * spin_unit_radps, sidespin * spin_unit_radps);
  physics::CushionImpactResult result;
  if (solver == "exact") {
    physics::ExactSolverOptions options;
    if (tolerance) options.tolerance = *tolerance;
    result = physics::solveCushionImpactExact(params, incoming, options);
  } else if (solver == "paper") {
    physics::PaperSolverOptions options;
    options.steps = steps;
    result = physics::solveCushionImpactPaper(params, incoming, options);
  } else {
    throw py::value_error("solver = '" + solver + "' is not allowed: it must be 'exact' or 'paper'");
  }
  py::dict out;
  out["velocity"] = vector3(result.after.v);
  out["spin"] = vector3(result.after.w);
  out["rebound_speed"] = std::hypot(result.after.v.x(), result.after.v.y());
  out["rebound_angle_deg"] = std::atan2(-result.after.v.y(), result.after.v.x()) / kRadiansPerDegree;
  out["compression_impulse"] = result.compression_impulse_Ns;
  out["final_impulse"] = result.final_impulse_Ns;
  return out;
}

}  // namespace

void bindCushion(py::module_& module) {
  const physics::CushionParams defaults;
  module.def("cushion_impact", &cushionImpact, py::kw_only(), py::arg("speed") = 1.0,
             py::arg("angle_deg") = 90.0, py::arg("topspin") = 1.0, py::arg("sidespin") = 0.0,
             py::arg("solver") = "exact", py::arg("mass") = defaults.mass_kg,
             py::arg("radius") = defaults.radius_m, py::arg("contact_height") = py::none(),
             py::arg("restitution") = defaults.restitution,
             py::arg("cushion_friction") = defaults.cushion_friction,
             py::arg("cloth_friction") = defaults.cloth_friction,
             py::arg("restitution_speed_dependence") = py::none(),
             py::arg("steps") = physics::PaperSolverOptions{}.steps,
             py::arg("tolerance") = py::none(),
             "One cushion impact by the model of Mathavan, Jackson & Parkin (2010), as `baize "
             "cushion`: speed V0 (m/s), angle from the cushion line (90: head-on), topspin and "
             "sidespin in units of V0/R (topspin 1: natural roll), the ball's mass (kg) and radius "
             "(m), the nose height (m; default 7R/5), e_e, mu_w, mu_s, the optional speed dependence of e_e "
             "(a dict with knee_speed_mps and falloff_exponent, as a scene's "
             "physics.cushion.restitution_speed_dependence), the solver ('exact' with "
             "its tolerance or 'paper' with its steps). Returns a dict: velocity and spin after "
             "(numpy 3-vectors in the cushion's frame, m/s and rad/s), rebound_speed (m/s), "
             "rebound_angle_deg, compression_impulse and final_impulse (N s). Values out of range "
             "raise ValueError naming them.");
}

}  // namespace baize::python
