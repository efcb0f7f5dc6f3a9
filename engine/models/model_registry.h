// The contact models by name: one registry for cushion models and one for ball-ball models, which
// the scene reader, the CLI, the event loop (through SimulationParams) and the baselines all go
// through. A model is one file pair here plus one registration line in model_registry.cpp (or one
// add() call, as the tests do for a toy model).
//
// Why its own layer: the event loop (engine/sim) calls the model interfaces and may not include the
// JSON reader (engine/io); the models read their parameters with it. So the interfaces live in
// engine/sim, and the models, their JSON reading and this registry in engine/models, between them:
//   physics/ <- engine/sim/ <- engine/models/ <- engine/io/ <- ...
// (engine/io/json_reader is the one engine/io file this layer uses: it includes nothing above
// engine/sim.)
#pragma once

#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "engine/io/json_reader.h"
#include "engine/sim/simulation_params.h"
#include "physics/cushion_model.h"

namespace baize::engine {

// What a model's defaults may depend on besides its own constants: the table and the ball set.
struct ModelDefaults {
  // The table's cushion nose height above the slate; pool: 0.635 of the ball's diameter.
  double cushion_contact_height_m = 0.635 * 2 * BallProperties{}.radius_m;
  // The table's cushion restitution e_e and nose friction mu_w (the Mathavan 2010 model's).
  double cushion_restitution = physics::CushionParams{}.restitution;
  double cushion_friction = physics::CushionParams{}.cushion_friction;
  // The ball set's ball-ball restitution: pool 0.95, snooker 0.89 (physics-notes section 3).
  double ball_ball_restitution = 0.95;
};

// One model as the registry knows it.
template <class Model>
struct ModelEntry {
  std::string name;               // as scene files and the CLI spell it
  std::vector<std::string> keys;  // the parameter keys it reads from its group, besides "model"
  // The model with its defaults, then the keys `parameters` gives (null: none). Reads strictly:
  // throws std::invalid_argument naming the file, key path and value for a wrong type, an unknown
  // choice or a key that does not apply with the others given; ranges are the model's validate().
  std::function<std::shared_ptr<const Model>(const ModelDefaults& defaults,
                                             const JsonReader* parameters)>
      make;
};

template <class Model>
class ModelRegistry {
 public:
  ModelRegistry(std::string group, std::string default_name);

  // Makes `entry` available by its name; throws std::invalid_argument when the name is taken.
  // Not locked: register before shots run (the built-in models are registered on first use).
  void add(ModelEntry<Model> entry);

  const ModelEntry<Model>* find(const std::string& name) const;  // null when unknown
  std::vector<std::string> names() const;                        // in registration order
  const std::string& defaultName() const { return default_name_; }
  // The names as messages list them: "\"exact\", \"paper\" or \"simple\"".
  std::string namesText() const;

  // The named model with its defaults; throws std::invalid_argument for an unknown name.
  std::shared_ptr<const Model> make(const std::string& name, const ModelDefaults& defaults) const;

  // The model a group object chooses ({"model": name, ...its keys}; no "model": the default one),
  // with the parameters it gives. Throws std::invalid_argument naming the file, key path and
  // value for an unknown name, a key no model reads, or a key the chosen model does not read.
  std::shared_ptr<const Model> read(const JsonReader& group, const ModelDefaults& defaults) const;

  // `model` with the parameters `changes` gives (keys of its group) in place of its own; `source`
  // names the changes in messages. A model's parametersJson() holds all its parameters, so no
  // default enters.
  std::shared_ptr<const Model> changed(const Model& model, const nlohmann::json& changes,
                                       const std::string& source) const;

 private:
  std::string group_;  // "cushion", "ball_ball": for messages
  std::string default_name_;
  std::vector<ModelEntry<Model>> entries_;
};

// The registries, with the built-in models registered.
ModelRegistry<CushionContactModel>& cushionModels();
ModelRegistry<BallBallContactModel>& ballBallModels();

// Pool balls and cloth: 57.15 mm, 0.17 kg balls, pool cloth, the exact Mathavan 2010 cushion
// model (nose at 0.635 of the diameter) with the paper's e_e 0.98, mu_w 0.14 (the shipped pool
// table files carry their calibrated values instead, docs/calibrate.md), the frictional ball-ball
// model.
SimulationParams poolSimulationParams();
// The same balls and cloth with the models the registries make from `defaults`.
SimulationParams simulationParamsWith(const BallProperties& ball, const physics::ClothParams& cloth,
                                      const ModelDefaults& defaults);

}  // namespace baize::engine
