// The optional "physics" object of a scene file (docs/scenes.md): overrides of the cloth, cushion,
// ball-ball and cue parameters and of the event budget, read strictly, applied on top of the
// table's and ball set's defaults, and validated by the physics validators with the file and key
// path in front of their messages.
#pragma once

#include <functional>
#include <optional>
#include <string>

#include "engine/sim/cushion_contact.h"
#include "engine/io/json_reader.h"
#include "engine/sim/shot_simulator.h"
#include "physics/ball_ball_impact.h"
#include "physics/cue_strike.h"

namespace baize::engine {

// What a scene overrides; an empty field keeps the default of the table and ball set. Units as in
// the parameter structs they map to.
struct PhysicsOverrides {
  // physics.cloth -> physics::ClothParams
  std::optional<double> sliding_friction;   // mu_s (also the cushion model's cloth friction)
  std::optional<double> rolling_friction;   // mu_r
  std::optional<double> spinning_friction;  // mu_sp
  // physics.cushion -> SimulationParams::cushion_model and its options, physics::CushionParams
  std::optional<CushionModelChoice> cushion_model;
  std::optional<double> cushion_restitution;  // e_e
  std::optional<double> cushion_friction;     // mu_w
  std::optional<double> contact_height_m;     // h, nose height above the slate
  std::optional<int> paper_steps;             // N of the paper scheme
  std::optional<double> simple_restitution;   // e of the simple rule
  std::optional<double> cushion_tolerance;    // the exact solver's tolerance
  // physics.ball_ball -> physics::BallBallParams
  std::optional<physics::BallBallModel> ball_ball_model;
  std::optional<double> ball_ball_restitution;
  std::optional<physics::BallBallFrictionLaw> friction_law;
  std::optional<double> friction_fit_a, friction_fit_b, friction_fit_c_s_per_m;
  std::optional<double> constant_friction;
  std::optional<double> ball_friction;        // mu_b (mathavan2014)
  std::optional<double> ball_ball_tolerance;  // integration tolerance (mathavan2014)
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

// Applies the overrides. The cushion model's cloth friction and the ball-ball model's follow the
// cloth's sliding friction (the same cloth), overridden or not.
void applyPhysicsOverrides(const PhysicsOverrides& overrides, SimulationParams* params);
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
