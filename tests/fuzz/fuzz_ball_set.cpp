// Fuzz target: engine::ballSetFromJson on arbitrary bytes. Bytes that are not JSON are refused by
// the JSON parser (its exceptions are fine); a document is either refused with
// std::invalid_argument or gives a set of positive, finite size with unique ids and a cue ball.
// Any other exception, a crash or a hang is a finding.
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <nlohmann/json.hpp>
#include <set>
#include <stdexcept>

#include "engine/io/ball_set.h"
#include "tests/fuzz/fuzz_json.h"
#include "tests/fuzz/fuzz_support.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  nlohmann::json document;
  if (!baize::fuzz::parseJson(data, size, &document)) return 0;
  baize::engine::BallSet set;
  try {
    set = baize::engine::ballSetFromJson(document, "fuzz-balls.json");
  } catch (const std::invalid_argument&) {
    return 0;
  }
  using baize::fuzz::check;
  check(std::isfinite(set.radius_m) && set.radius_m > 0, "a loaded ball set has a bad radius");
  check(std::isfinite(set.mass_kg) && set.mass_kg > 0, "a loaded ball set has a bad mass");
  check(set.contains("cue"), "a loaded ball set has no cue ball");
  std::set<std::string> ids;
  for (const auto& ball : set.balls) {
    check(ids.insert(ball.id).second, "a loaded ball set repeats the id " + ball.id);
    check(set.ball(ball.id).id == ball.id, "a loaded ball cannot be found by its id " + ball.id);
  }
  return 0;
}
