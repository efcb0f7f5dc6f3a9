#include "engine/models/model_registry.h"

#include <algorithm>
#include <stdexcept>

#include "engine/models/ball_ball_frictional_model.h"
#include "engine/models/ball_ball_mathavan2014_model.h"
#include "engine/models/cushion_exact_model.h"
#include "engine/models/cushion_paper_model.h"
#include "engine/models/cushion_simple_model.h"
#include "engine/models/cushion_tabulated_model.h"

namespace baize::engine {
namespace {

// "\"a\"", "\"a\" or \"b\"", "\"a\", \"b\" or \"c\"".
std::string quotedList(const std::vector<std::string>& names) {
  std::string text;
  for (std::size_t i = 0; i < names.size(); ++i) {
    if (i > 0) text += i + 1 == names.size() ? " or " : ", ";
    text += "\"" + names[i] + "\"";
  }
  return text;
}

std::string commaList(const std::vector<std::string>& keys) {
  std::string text;
  for (const std::string& key : keys) text += (text.empty() ? "" : ", ") + key;
  return text;
}

bool reads(const std::vector<std::string>& keys, const std::string& key) {
  return std::find(keys.begin(), keys.end(), key) != keys.end();
}

}  // namespace

template <class Model>
ModelRegistry<Model>::ModelRegistry(std::string group, std::string default_name)
    : group_(std::move(group)), default_name_(std::move(default_name)) {}

template <class Model>
void ModelRegistry<Model>::add(ModelEntry<Model> entry) {
  if (entry.name.empty() || find(entry.name) || !entry.make) {
    throw std::invalid_argument(group_ + " model \"" + entry.name +
                                "\" is not allowed: a model needs a name no other " + group_ +
                                " model has, and a make function");
  }
  entries_.push_back(std::move(entry));
}

template <class Model>
const ModelEntry<Model>* ModelRegistry<Model>::find(const std::string& name) const {
  for (const ModelEntry<Model>& entry : entries_) {
    if (entry.name == name) return &entry;
  }
  return nullptr;
}

template <class Model>
std::vector<std::string> ModelRegistry<Model>::names() const {
  std::vector<std::string> names;
  for (const ModelEntry<Model>& entry : entries_) names.push_back(entry.name);
  return names;
}

template <class Model>
std::string ModelRegistry<Model>::namesText() const {
  return quotedList(names());
}

template <class Model>
std::shared_ptr<const Model> ModelRegistry<Model>::make(const std::string& name,
                                                        const ModelDefaults& defaults) const {
  const ModelEntry<Model>* entry = find(name);
  if (!entry) {
    throw std::invalid_argument(group_ + " model \"" + name + "\" is not allowed: it must be " +
                                namesText());
  }
  return entry->make(defaults, nullptr);
}

template <class Model>
std::shared_ptr<const Model> ModelRegistry<Model>::read(const JsonReader& group,
                                                        const ModelDefaults& defaults) const {
  // Every shot of a scene that names a model reads its group: the keys are checked in place, and
  // the lists a refusal names are made only for its message.
  const auto readByAny = [&](const std::string& key) {
    return key == "model" ||
           std::any_of(entries_.begin(), entries_.end(),
                       [&](const ModelEntry<Model>& e) { return reads(e.keys, key); });
  };
  for (const auto& item : group.json().items()) {
    if (readByAny(item.key())) continue;
    std::vector<std::string> known = {"model"};
    for (const ModelEntry<Model>& entry : entries_) {
      for (const std::string& key : entry.keys) {
        if (!reads(known, key)) known.push_back(key);
      }
    }
    group.reject(item.key(), "unknown key; the keys here are " + commaList(known));
  }
  std::string name = default_name_;
  if (group.has("model")) name = group.text("model");
  const ModelEntry<Model>* chosen = find(name);
  if (!chosen) group.reject("model", "it must be " + namesText());
  // A key another model reads but this one does not: say which models read it.
  for (const auto& item : group.json().items()) {
    const std::string& key = item.key();
    if (key == "model" || reads(chosen->keys, key)) continue;
    std::vector<std::string> readers;
    for (const ModelEntry<Model>& entry : entries_) {
      if (reads(entry.keys, key)) readers.push_back(entry.name);
    }
    group.reject(key, "it applies only to model " + quotedList(readers) + "; model \"" + name +
                          "\" takes " + (chosen->keys.empty() ? "none" : commaList(chosen->keys)) +
                          " (the model here is \"" + name + "\")");
  }
  return chosen->make(defaults, &group);
}

template <class Model>
std::shared_ptr<const Model> ModelRegistry<Model>::changed(const Model& model,
                                                           const nlohmann::json& changes,
                                                           const std::string& source) const {
  nlohmann::json group = model.parametersJson();
  group.update(changes);
  return read(JsonReader(group, source, "physics." + group_), ModelDefaults{});
}

template class ModelRegistry<CushionContactModel>;
template class ModelRegistry<BallBallContactModel>;

ModelRegistry<CushionContactModel>& cushionModels() {
  static ModelRegistry<CushionContactModel> registry = [] {
    ModelRegistry<CushionContactModel> models("cushion", "tabulated");
    models.add(exactCushionModel());
    models.add(paperCushionModel());
    models.add(simpleCushionModel());
    models.add(tabulatedCushionModel());
    return models;
  }();
  return registry;
}

ModelRegistry<BallBallContactModel>& ballBallModels() {
  static ModelRegistry<BallBallContactModel> registry = [] {
    ModelRegistry<BallBallContactModel> models("ball_ball", "frictional");
    models.add(frictionalBallBallModel());
    models.add(mathavan2014BallBallModel());
    return models;
  }();
  return registry;
}

SimulationParams simulationParamsWith(const BallProperties& ball, const physics::ClothParams& cloth,
                                      const ModelDefaults& defaults) {
  SimulationParams p;
  p.ball = ball;
  p.cloth = cloth;
  p.cloth.radius_m = ball.radius_m;
  p.cushion = cushionModels().make(cushionModels().defaultName(), defaults);
  p.ball_ball = ballBallModels().make(ballBallModels().defaultName(), defaults);
  return p;
}

SimulationParams poolSimulationParams() {
  return simulationParamsWith(BallProperties{}, physics::poolCloth(), ModelDefaults{});
}

}  // namespace baize::engine
