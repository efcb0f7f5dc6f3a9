// What the two Mathavan 2010 cushion models ("exact" and "paper") share: the model's own
// parameters (restitution, nose friction, nose height), read from and written to a scene's
// "physics.cushion" object, and the physics parameters of one impact made from them and the shot.
#pragma once

#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <vector>

#include "engine/io/json_reader.h"
#include "engine/models/model_registry.h"
#include "physics/cushion_model.h"

namespace baize::engine {

// The Mathavan 2010 model's own parameters; the ball and cloth come from the shot.
struct Mathavan2010Cushion {
  double contact_height_m = 0;                                          // h, nose above the slate
  double restitution = physics::CushionParams{}.restitution;            // e_e
  double cushion_friction = physics::CushionParams{}.cushion_friction;  // mu_w
  // e_e falling with the normal incident speed above a knee; none (the default): constant.
  std::optional<physics::RestitutionSpeedDependence> restitution_speed_dependence;
};

// The scene key of the speed dependence: an object with knee_speed_mps and falloff_exponent.
inline constexpr const char* kRestitutionSpeedDependenceKey = "restitution_speed_dependence";

// The keys the models read: restitution, friction, contact_height_m,
// restitution_speed_dependence.
const std::vector<std::string>& mathavan2010Keys();

// The defaults (h the table's), then the keys `parameters` gives, if any.
Mathavan2010Cushion readMathavan2010(const ModelDefaults& defaults, const JsonReader* parameters);

// The physics parameters of an impact: these with the shot's ball and cloth friction.
physics::CushionParams impactParams(const Mathavan2010Cushion& model, const SimulationParams& shot);

// The object a scene's physics.cushion.restitution_speed_dependence holds.
nlohmann::json restitutionSpeedDependenceJson(const physics::RestitutionSpeedDependence& law);

// Adds restitution, friction and contact_height_m to `out`, and restitution_speed_dependence
// when the model has one.
void writeMathavan2010(const Mathavan2010Cushion& model, nlohmann::json* out);

}  // namespace baize::engine
