#include "engine/models/cushion_mathavan2010.h"

namespace baize::engine {

const std::vector<std::string>& mathavan2010Keys() {
  static const std::vector<std::string> keys = {"restitution", "friction", "contact_height_m",
                                                kRestitutionSpeedDependenceKey};
  return keys;
}

namespace {

// Both keys are required: neither has a value that means "unchanged". Ranges are the model's
// validate() (physics::validateRestitutionSpeedDependence).
physics::RestitutionSpeedDependence readSpeedDependence(const JsonReader& law) {
  law.requireExactKeys({"knee_speed_mps", "falloff_exponent"});
  return {law.finiteNumber("knee_speed_mps"), law.finiteNumber("falloff_exponent")};
}

}  // namespace

Mathavan2010Cushion readMathavan2010(const ModelDefaults& defaults, const JsonReader* parameters) {
  Mathavan2010Cushion model;
  model.contact_height_m = defaults.cushion_contact_height_m;
  model.restitution = defaults.cushion_restitution;
  model.cushion_friction = defaults.cushion_friction;
  if (!parameters) return model;
  if (parameters->has("restitution")) model.restitution = parameters->finiteNumber("restitution");
  if (parameters->has("friction")) model.cushion_friction = parameters->finiteNumber("friction");
  if (parameters->has("contact_height_m"))
    model.contact_height_m = parameters->finiteNumber("contact_height_m");
  if (parameters->has(kRestitutionSpeedDependenceKey)) {
    model.restitution_speed_dependence =
        readSpeedDependence(parameters->object(kRestitutionSpeedDependenceKey));
  }
  return model;
}

physics::CushionParams impactParams(const Mathavan2010Cushion& model,
                                    const SimulationParams& shot) {
  physics::CushionParams params;
  params.mass_kg = shot.ball.mass_kg;
  params.radius_m = shot.ball.radius_m;
  params.contact_height_m = model.contact_height_m;
  params.restitution = model.restitution;
  params.cushion_friction = model.cushion_friction;
  params.cloth_friction = shot.cloth.sliding_friction;  // one cloth
  params.restitution_speed_dependence = model.restitution_speed_dependence;
  return params;
}

void writeMathavan2010(const Mathavan2010Cushion& model, nlohmann::json* out) {
  (*out)["restitution"] = model.restitution;
  (*out)["friction"] = model.cushion_friction;
  (*out)["contact_height_m"] = model.contact_height_m;
  if (const auto& law = model.restitution_speed_dependence)
    (*out)[kRestitutionSpeedDependenceKey] = restitutionSpeedDependenceJson(*law);
}

nlohmann::json restitutionSpeedDependenceJson(const physics::RestitutionSpeedDependence& law) {
  return {{"knee_speed_mps", law.knee_speed_mps}, {"falloff_exponent", law.falloff_exponent}};
}

}  // namespace baize::engine
