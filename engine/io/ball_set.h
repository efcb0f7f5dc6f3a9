// A set of balls as data (assets/balls/*.json, described in docs/tables.md): one radius and mass
// for the whole set, and per ball an id, a colour, a printed number and whether it is striped.
#pragma once

#include <nlohmann/json.hpp>
#include <string>
#include <vector>

namespace baize::engine {

struct BallSpec {
  std::string id;      // unique in the set; the cue ball is "cue"
  int number = 0;      // printed number (pool 1-15), 0 when none
  std::string colour;  // "#rrggbb"
  bool stripe = false;
};

struct BallSet {
  std::string source;  // the file it was read from (or the document's name), for messages
  std::string name;
  std::string description;
  double radius_m = 0;
  double mass_kg = 0;
  std::vector<BallSpec> balls;

  // The ball with this id; throws std::invalid_argument naming the id when the set has none.
  const BallSpec& ball(const std::string& id) const;
  bool contains(const std::string& id) const;
};

// Builds a ball set from a parsed JSON document; `source` names it in error messages.
BallSet ballSetFromJson(const nlohmann::json& document, const std::string& source);

// Reads and validates a ball-set file.
BallSet loadBallSet(const std::string& path);

// The shipped sets: "pool", "snooker".
std::vector<std::string> builtinBallSetNames();
BallSet builtinBallSet(const std::string& name);

}  // namespace baize::engine
