#include "engine/io/scene_physics.h"

#include <cmath>
#include <limits>
#include <stdexcept>

#include "physics/cloth_motion.h"

namespace baize::engine {
namespace {

// max_events is read as a JSON integer, which the reader holds as an int.
constexpr int kMaxEventBudget = std::numeric_limits<int>::max();

std::optional<double> number(const JsonReader& object, const char* key) {
  if (!object.has(key)) return std::nullopt;
  return object.finiteNumber(key);
}

void readCloth(const JsonReader& cloth, PhysicsOverrides* o) {
  cloth.requireKeys({}, {"sliding_friction", "rolling_friction", "spinning_friction"});
  o->sliding_friction = number(cloth, "sliding_friction");
  o->rolling_friction = number(cloth, "rolling_friction");
  o->spinning_friction = number(cloth, "spinning_friction");
}

// Reads a model group once to check it (with placeholder defaults: ranges are checked later, with
// the scene's), and keeps it to make the model from once the defaults are known.
template <class Model>
nlohmann::json readModelGroup(const ModelRegistry<Model>& registry, const JsonReader& group) {
  registry.read(group, ModelDefaults{});
  return group.json();
}

// physics.cushion without valid_normal_speed_mps (kept in `o`, checked here: it belongs to no
// model); empty when the group gave nothing else, so the table's cushion model stays.
std::optional<nlohmann::json> readCushionGroup(const JsonReader& cushion, PhysicsOverrides* o) {
  nlohmann::json model_keys = cushion.json();
  if (cushion.has(kValidNormalSpeedKey)) {
    const double limit = cushion.finiteNumber(kValidNormalSpeedKey);
    if (!(limit > 0)) cushion.reject(kValidNormalSpeedKey, "it must be a speed above 0 m/s");
    o->valid_normal_speed_mps = limit;
    model_keys.erase(kValidNormalSpeedKey);
  }
  if (model_keys.empty()) return std::nullopt;
  return readModelGroup(cushionModels(), JsonReader(model_keys, cushion.source(), cushion.path()));
}

void readCue(const JsonReader& cue, PhysicsOverrides* o) {
  cue.requireKeys({}, {"mass_kg", "tip_restitution", "squirt_end_mass_kg"});
  o->cue_mass_kg = number(cue, "mass_kg");
  o->tip_restitution = number(cue, "tip_restitution");
  o->squirt_end_mass_kg = number(cue, "squirt_end_mass_kg");
}

template <class Value>
void setIf(const std::optional<Value>& value, Value* target) {
  if (value) *target = *value;
}

// Runs `check` (a physics validator); a refusal gets the file and the group's key path in front
// and where the values came from behind.
template <class Check>
void validateGroup(const std::string& source, const std::function<std::string()>& origin,
                   const char* group, const Check& check) {
  try {
    check();
  } catch (const std::invalid_argument& e) {
    throw std::invalid_argument(source + ": physics." + group + ": " + e.what() + " (" + origin() +
                                ")");
  }
}

}  // namespace

PhysicsOverrides readPhysicsOverrides(const JsonReader& physics) {
  physics.requireKeys({}, {"cloth", "cushion", "ball_ball", "cue", "max_events"});
  PhysicsOverrides o;
  if (physics.has("cloth")) readCloth(physics.object("cloth"), &o);
  o.source = physics.source();
  if (physics.has("cushion"))
    o.cushion = readCushionGroup(physics.object("cushion"), &o);
  if (physics.has("ball_ball"))
    o.ball_ball = readModelGroup(ballBallModels(), physics.object("ball_ball"));
  if (physics.has("cue")) readCue(physics.object("cue"), &o);
  if (physics.has("max_events")) o.max_events = physics.integer("max_events", 1, kMaxEventBudget);
  return o;
}

void applyPhysicsOverrides(const PhysicsOverrides& o, const ModelDefaults& defaults,
                           SimulationParams* p) {
  setIf(o.sliding_friction, &p->cloth.sliding_friction);
  setIf(o.rolling_friction, &p->cloth.rolling_friction);
  setIf(o.spinning_friction, &p->cloth.spinning_friction);
  if (o.cushion) {
    p->cushion =
        cushionModels().read(JsonReader(*o.cushion, o.source, "physics.cushion"), defaults);
  }
  if (o.ball_ball) {
    p->ball_ball =
        ballBallModels().read(JsonReader(*o.ball_ball, o.source, "physics.ball_ball"), defaults);
  }
  setIf(o.max_events, &p->max_events);
}

void applyPhysicsOverrides(const PhysicsOverrides& o, physics::CueStrikeParams* cue) {
  setIf(o.cue_mass_kg, &cue->cue_mass_kg);
  setIf(o.tip_restitution, &cue->tip_restitution);
  if (o.squirt_end_mass_kg) cue->end_mass_kg = *o.squirt_end_mass_kg;
}

void validateScenePhysics(const SimulationParams& p, const physics::CueStrikeParams& cue,
                          const std::string& source, const std::function<std::string()>& origin) {
  validateGroup(source, origin, "cloth", [&] { physics::validateClothParams(p.cloth); });
  validateGroup(source, origin, "cushion", [&] { p.cushion->validate(p); });
  validateGroup(source, origin, "ball_ball", [&] { p.ball_ball->validate(p); });
  validateGroup(source, origin, "cue", [&] { physics::validateCueStrikeParams(cue); });
}

nlohmann::json physicsJson(const SimulationParams& p, const physics::CueStrikeParams& cue) {
  nlohmann::json out;
  out["cloth"] = {{"sliding_friction", p.cloth.sliding_friction},
                  {"rolling_friction", p.cloth.rolling_friction},
                  {"spinning_friction", p.cloth.spinning_friction}};
  out["cushion"] = p.cushion->parametersJson();
  out["ball_ball"] = p.ball_ball->parametersJson();
  out["cue"] = {{"mass_kg", cue.cue_mass_kg}, {"tip_restitution", cue.tip_restitution}};
  if (cue.end_mass_kg) out["cue"]["squirt_end_mass_kg"] = *cue.end_mass_kg;
  out["max_events"] = p.max_events;
  return out;
}

}  // namespace baize::engine
