#include "engine/io/ball_set.h"

#include <algorithm>
#include <cctype>
#include <map>
#include <mutex>
#include <stdexcept>

#include "engine/io/json_reader.h"
#include "engine/io/table.h"

namespace baize::engine {
namespace {

bool isHexColour(const std::string& text) {
  return text.size() == 7 && text[0] == '#' &&
         std::all_of(text.begin() + 1, text.end(),
                     [](char c) { return std::isxdigit(static_cast<unsigned char>(c)) != 0; });
}

}  // namespace

bool BallSet::contains(const std::string& id) const {
  return std::any_of(balls.begin(), balls.end(), [&](const BallSpec& b) { return b.id == id; });
}

const BallSpec& BallSet::ball(const std::string& id) const {
  for (const BallSpec& spec : balls) {
    if (spec.id == id) return spec;
  }
  throw std::invalid_argument("ball id \"" + id + "\" is not allowed: ball set \"" + name +
                              "\" has no such ball");
}

BallSet ballSetFromJson(const nlohmann::json& document, const std::string& source) {
  const JsonReader root(document, source);
  root.requireExactKeys({"name", "description", "radius_m", "mass_kg", "balls"});
  BallSet set;
  set.source = source;
  set.name = root.text("name");
  set.description = root.text("description");
  set.radius_m = root.positiveNumber("radius_m");
  set.mass_kg = root.positiveNumber("mass_kg");
  for (const JsonReader& ball : root.objectArray("balls")) {
    ball.requireExactKeys({"id", "number", "colour", "stripe"});
    BallSpec spec;
    spec.id = ball.text("id");
    if (set.contains(spec.id)) ball.reject("id", "ball ids must be unique in a set");
    spec.number = ball.integer("number", 0, 99);
    spec.colour = ball.text("colour");
    if (!isHexColour(spec.colour)) ball.reject("colour", "it must be \"#rrggbb\" (hexadecimal)");
    spec.stripe = ball.boolean("stripe");
    set.balls.push_back(spec);
  }
  if (!set.contains("cue")) root.reject("balls", "the set must hold a ball with id \"cue\"");
  return set;
}

BallSet loadBallSet(const std::string& path) {
  return ballSetFromJson(JsonReader::parseFile(path), path);
}

std::vector<std::string> builtinBallSetNames() { return {"pool", "snooker"}; }

BallSet builtinBallSet(const std::string& name) {
  // Read once per process, as the built-in tables.
  static std::mutex mutex;
  static std::map<std::string, BallSet> loaded;
  for (const std::string& known : builtinBallSetNames()) {
    if (name != known) continue;
    const std::lock_guard<std::mutex> lock(mutex);
    auto found = loaded.find(name);
    if (found == loaded.end())
      found =
          loaded.emplace(name, loadBallSet(assetsDirectory() + "/balls/" + name + ".json")).first;
    return found->second;
  }
  throw std::invalid_argument("ball set name \"" + name +
                              "\" is not allowed: the built-in sets are pool, snooker");
}

}  // namespace baize::engine
