#include "engine/io/scene_physics.h"

#include <cmath>
#include <limits>
#include <stdexcept>

#include "physics/cloth_motion.h"
#include "physics/cushion_exact_solver.h"
#include "physics/cushion_model.h"
#include "physics/cushion_paper_solver.h"
#include "physics/cushion_simple_model.h"

namespace baize::engine {
namespace {

using physics::kMaxPaperSteps;  // the paper scheme's largest step count
// max_events is read as a JSON integer, which the reader holds as an int.
constexpr int kMaxEventBudget = std::numeric_limits<int>::max();

std::optional<double> number(const JsonReader& object, const char* key) {
  if (!object.has(key)) return std::nullopt;
  return object.finiteNumber(key);
}

// Refuses `key` when it is given but does not apply to the model chosen.
void requireApplies(const JsonReader& object, const char* key, bool applies,
                    const std::string& why) {
  if (object.has(key) && !applies) object.reject(key, "it applies only to " + why);
}

void readCloth(const JsonReader& cloth, PhysicsOverrides* o) {
  cloth.requireKeys({}, {"sliding_friction", "rolling_friction", "spinning_friction"});
  o->sliding_friction = number(cloth, "sliding_friction");
  o->rolling_friction = number(cloth, "rolling_friction");
  o->spinning_friction = number(cloth, "spinning_friction");
}

void readCushion(const JsonReader& cushion, PhysicsOverrides* o) {
  cushion.requireKeys({}, {"model", "restitution", "friction", "contact_height_m", "paper_steps",
                           "simple_restitution", "tolerance"});
  CushionModelChoice model = CushionModelChoice::Mathavan2010Exact;
  if (cushion.has("model")) {
    const std::string name = cushion.text("model");
    if (name == "exact") {
      model = CushionModelChoice::Mathavan2010Exact;
    } else if (name == "paper") {
      model = CushionModelChoice::Mathavan2010Paper;
    } else if (name == "simple") {
      model = CushionModelChoice::SimpleRestitution;
    } else {
      cushion.reject("model", "it must be \"exact\", \"paper\" or \"simple\"");
    }
    o->cushion_model = model;
  }
  const std::string here = std::string(" (the model here is \"") + cushionModelName(model) + "\")";
  const bool seed = model != CushionModelChoice::SimpleRestitution;
  for (const char* key : {"restitution", "friction", "contact_height_m"}) {
    requireApplies(cushion, key, seed,
                   "the Mathavan 2010 cushion model, \"exact\" or \"paper\"; \"simple\" takes "
                   "simple_restitution" +
                       here);
  }
  requireApplies(cushion, "paper_steps", model == CushionModelChoice::Mathavan2010Paper,
                 "model \"paper\"" + here);
  requireApplies(cushion, "tolerance", model == CushionModelChoice::Mathavan2010Exact,
                 "model \"exact\"" + here);
  requireApplies(cushion, "simple_restitution", model == CushionModelChoice::SimpleRestitution,
                 "model \"simple\"" + here);
  o->cushion_restitution = number(cushion, "restitution");
  o->cushion_friction = number(cushion, "friction");
  o->contact_height_m = number(cushion, "contact_height_m");
  if (cushion.has("paper_steps"))
    o->paper_steps = cushion.integer("paper_steps", 1, kMaxPaperSteps);
  o->simple_restitution = number(cushion, "simple_restitution");
  o->cushion_tolerance = number(cushion, "tolerance");
}

void readBallBall(const JsonReader& ball_ball, PhysicsOverrides* o) {
  ball_ball.requireKeys(
      {}, {"model", "restitution", "friction_law", "friction_fit_a", "friction_fit_b",
           "friction_fit_c_s_per_m", "constant_friction", "ball_friction", "tolerance"});
  physics::BallBallModel model = physics::BallBallModel::FrictionalInelastic;
  if (ball_ball.has("model")) {
    const std::string name = ball_ball.text("model");
    if (name == "frictional") {
      model = physics::BallBallModel::FrictionalInelastic;
    } else if (name == "mathavan2014") {
      model = physics::BallBallModel::Mathavan2014;
    } else {
      ball_ball.reject("model", "it must be \"frictional\" or \"mathavan2014\"");
    }
    o->ball_ball_model = model;
  }
  const bool frictional = model == physics::BallBallModel::FrictionalInelastic;
  const std::string here =
      std::string(" (the model here is \"") + (frictional ? "frictional" : "mathavan2014") + "\")";
  physics::BallBallFrictionLaw law = physics::BallBallFrictionLaw::AlciatoreFit;
  requireApplies(ball_ball, "friction_law", frictional, "model \"frictional\"" + here);
  if (ball_ball.has("friction_law")) {
    const std::string name = ball_ball.text("friction_law");
    if (name == "alciatore") {
      law = physics::BallBallFrictionLaw::AlciatoreFit;
    } else if (name == "constant") {
      law = physics::BallBallFrictionLaw::Constant;
    } else {
      ball_ball.reject("friction_law", "it must be \"alciatore\" or \"constant\"");
    }
    o->friction_law = law;
  }
  const bool fit = frictional && law == physics::BallBallFrictionLaw::AlciatoreFit;
  for (const char* key : {"friction_fit_a", "friction_fit_b", "friction_fit_c_s_per_m"}) {
    requireApplies(ball_ball, key, fit, "model \"frictional\" with friction_law \"alciatore\"");
  }
  requireApplies(ball_ball, "constant_friction",
                 frictional && law == physics::BallBallFrictionLaw::Constant,
                 "model \"frictional\" with friction_law \"constant\"");
  for (const char* key : {"ball_friction", "tolerance"}) {
    requireApplies(ball_ball, key, !frictional, "model \"mathavan2014\"" + here);
  }
  o->ball_ball_restitution = number(ball_ball, "restitution");
  o->friction_fit_a = number(ball_ball, "friction_fit_a");
  o->friction_fit_b = number(ball_ball, "friction_fit_b");
  o->friction_fit_c_s_per_m = number(ball_ball, "friction_fit_c_s_per_m");
  o->constant_friction = number(ball_ball, "constant_friction");
  o->ball_friction = number(ball_ball, "ball_friction");
  o->ball_ball_tolerance = number(ball_ball, "tolerance");
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
  if (physics.has("cushion")) readCushion(physics.object("cushion"), &o);
  if (physics.has("ball_ball")) readBallBall(physics.object("ball_ball"), &o);
  if (physics.has("cue")) readCue(physics.object("cue"), &o);
  if (physics.has("max_events")) o.max_events = physics.integer("max_events", 1, kMaxEventBudget);
  return o;
}

void applyPhysicsOverrides(const PhysicsOverrides& o, SimulationParams* p) {
  setIf(o.sliding_friction, &p->cloth.sliding_friction);
  setIf(o.rolling_friction, &p->cloth.rolling_friction);
  setIf(o.spinning_friction, &p->cloth.spinning_friction);
  // One cloth: the impact models' cloth friction is the cloth's sliding friction.
  p->cushion.cloth_friction = p->cloth.sliding_friction;
  p->ball_ball.cloth_friction = p->cloth.sliding_friction;

  setIf(o.cushion_model, &p->cushion_model);
  setIf(o.cushion_restitution, &p->cushion.restitution);
  setIf(o.cushion_friction, &p->cushion.cushion_friction);
  setIf(o.contact_height_m, &p->cushion.contact_height_m);
  setIf(o.paper_steps, &p->cushion_paper_steps);
  setIf(o.simple_restitution, &p->cushion_simple.restitution);
  setIf(o.cushion_tolerance, &p->cushion_solver.tolerance);

  setIf(o.ball_ball_model, &p->ball_ball.model);
  setIf(o.ball_ball_restitution, &p->ball_ball.restitution);
  setIf(o.friction_law, &p->ball_ball.friction_law);
  setIf(o.friction_fit_a, &p->ball_ball.friction_fit_a);
  setIf(o.friction_fit_b, &p->ball_ball.friction_fit_b);
  setIf(o.friction_fit_c_s_per_m, &p->ball_ball.friction_fit_c_s_per_m);
  setIf(o.constant_friction, &p->ball_ball.constant_friction);
  setIf(o.ball_friction, &p->ball_ball.ball_friction);
  setIf(o.ball_ball_tolerance, &p->ball_ball.tolerance);

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
  validateGroup(source, origin, "cushion", [&] {
    physics::validateCushionParams(p.cushion);
    validateCushionContactParams(p);
    if (p.cushion_model == CushionModelChoice::Mathavan2010Exact)
      physics::validateExactSolverOptions(p.cushion_solver);
  });
  validateGroup(source, origin, "ball_ball", [&] { physics::validateBallBallParams(p.ball_ball); });
  validateGroup(source, origin, "cue", [&] { physics::validateCueStrikeParams(cue); });
}

nlohmann::json physicsJson(const SimulationParams& p, const physics::CueStrikeParams& cue) {
  nlohmann::json out;
  out["cloth"] = {{"sliding_friction", p.cloth.sliding_friction},
                  {"rolling_friction", p.cloth.rolling_friction},
                  {"spinning_friction", p.cloth.spinning_friction}};
  nlohmann::json& cushion = out["cushion"];
  cushion["model"] = cushionModelName(p.cushion_model);
  if (p.cushion_model == CushionModelChoice::SimpleRestitution) {
    cushion["simple_restitution"] = p.cushion_simple.restitution;
  } else {
    cushion["restitution"] = p.cushion.restitution;
    cushion["friction"] = p.cushion.cushion_friction;
    cushion["contact_height_m"] = p.cushion.contact_height_m;
    if (p.cushion_model == CushionModelChoice::Mathavan2010Paper) {
      cushion["paper_steps"] = p.cushion_paper_steps;
    } else {
      cushion["tolerance"] = p.cushion_solver.tolerance;
    }
  }
  nlohmann::json& ball_ball = out["ball_ball"];
  ball_ball["restitution"] = p.ball_ball.restitution;
  if (p.ball_ball.model == physics::BallBallModel::FrictionalInelastic) {
    ball_ball["model"] = "frictional";
    if (p.ball_ball.friction_law == physics::BallBallFrictionLaw::AlciatoreFit) {
      ball_ball["friction_law"] = "alciatore";
      ball_ball["friction_fit_a"] = p.ball_ball.friction_fit_a;
      ball_ball["friction_fit_b"] = p.ball_ball.friction_fit_b;
      ball_ball["friction_fit_c_s_per_m"] = p.ball_ball.friction_fit_c_s_per_m;
    } else {
      ball_ball["friction_law"] = "constant";
      ball_ball["constant_friction"] = p.ball_ball.constant_friction;
    }
  } else {
    ball_ball["model"] = "mathavan2014";
    ball_ball["ball_friction"] = p.ball_ball.ball_friction;
    ball_ball["tolerance"] = p.ball_ball.tolerance;
  }
  out["cue"] = {{"mass_kg", cue.cue_mass_kg}, {"tip_restitution", cue.tip_restitution}};
  if (cue.end_mass_kg) out["cue"]["squirt_end_mass_kg"] = *cue.end_mass_kg;
  out["max_events"] = p.max_events;
  return out;
}

}  // namespace baize::engine
