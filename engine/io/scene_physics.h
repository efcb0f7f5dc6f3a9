// The optional "physics" object of a scene file (docs/scenes.md): overrides of the cloth, cushion,
// ball-ball and cue parameters and of the event budget, read strictly, applied on top of the
// table's and ball set's defaults, and validated by the physics validators with the file and key
// path in front of their messages.
#pragma once

#include <functional>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>

#include "engine/io/json_reader.h"
#include "engine/io/table.h"
#include "engine/models/model_registry.h"
#include "engine/sim/shot_simulator.h"
#include "physics/cue_strike.h"

namespace baize::engine {

// What a scene overrides; an empty field keeps the default of the table and ball set. Units as in
// the parameter structs they map to.
struct PhysicsOverrides {
  // physics.cloth -> physics::ClothParams
  std::optional<double> sliding_friction;   // mu_s (also the cushion model's cloth friction)
  std::optional<double> rolling_friction;   // mu_r
  std::optional<double> spinning_friction;  // mu_sp
  // physics.cushion and physics.ball_ball, as the file gives them ("model" and the chosen
  // model's keys), already checked by readPhysicsOverrides; applyPhysicsOverrides has the
  // registries (engine/models/model_registry.h) make the models from them.
  std::optional<nlohmann::json> cushion;
  std::optional<nlohmann::json> ball_ball;
  // physics.cushion.valid_normal_speed_mps: the normal speed up to which the cushion model is
  // taken to hold (the table's when not given). Read apart from the model's keys: it changes no
  // result, only which impacts are reported beyond the model's range.
  std::optional<double> valid_normal_speed_mps;
  std::string source;  // the file they came from, for messages
  // physics.cue -> physics::CueStrikeParams
  std::optional<double> cue_mass_kg;
  std::optional<double> tip_restitution;
  std::optional<double> squirt_end_mass_kg;  // given: the strike squirts
  // physics.max_events
  std::optional<long> max_events;
};

// Reads the "physics" object. Throws std::invalid_argument naming the file, the key path and the
// value for an unknown key, a wrong type, an unknown model name or a key that does not apply to
// the chosen model. Ranges are left to validateScenePhysics.
PhysicsOverrides readPhysicsOverrides(const JsonReader& physics);

// Applies the overrides. A cushion or ball_ball group given replaces that model with the one it
// names (or the registry's default), made from `defaults` (the table's and ball set's) and the
// group's keys. The models take the cloth's friction from the cloth, overridden or not.
void applyPhysicsOverrides(const PhysicsOverrides& overrides, const ModelDefaults& defaults,
                           SimulationParams* params);
void applyPhysicsOverrides(const PhysicsOverrides& overrides, physics::CueStrikeParams* cue);

// Validates the parameters a scene runs with, group by group (cloth, cushion, ball_ball, cue); a
// refusal is rethrown as "<source>: physics.<group>: <the validator's message> (<origin>)", where
// `origin()` says where the values came from (the table and ball set files as well as the scene:
// a table's contact height or a ball set's mass may be the value refused); it is called only on
// a refusal.
void validateScenePhysics(const SimulationParams& params, const physics::CueStrikeParams& cue,
                          const std::string& source, const std::function<std::string()>& origin);

// The parameters in the scene format's keys and units (the "physics" object a scene could give to
// get them), for reports: `baize simulate --json` echoes it.
nlohmann::json physicsJson(const SimulationParams& params, const physics::CueStrikeParams& cue);

}  // namespace baize::engine
