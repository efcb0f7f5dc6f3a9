// The seeded shots of `baize stress`: shot k of seed s is made from a generator seeded with (s, k)
// alone, so any shot can be made again on its own, in any thread. Two families:
//   - states: balls with given velocities and spins (any speed to 16 m/s, any spin up to
//     3 v / R per axis, tiny speeds near the stopping thresholds, grazing passes, two balls
//     reaching a third at nearly the same instant, balls sitting in pocket mouths and against
//     jaws), replayed from a state file (`baize stress --replay`);
//   - cue shots: a scene (docs/scenes.md) on the 9 ft pool or 12 ft snooker table whose cue ball
//     is struck by physics::strikeCueBall (cue elevation to 80 deg, tip offsets to the miscue
//     limit, frozen clusters and racks, balls against rails and jaws), written as a scene file
//     that `baize simulate` runs.
#pragma once

#include <cstdint>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <vector>

#include "engine/io/scene.h"
#include "engine/play/stress_tables.h"
#include "physics/cloth_motion.h"

namespace baize::engine {

enum class StressShotKind {
  Random,            // 1-N balls anywhere, one moving (rectangle)
  GapShot,           // at the gap between two touching balls (rectangle)
  FrozenLine,        // a row of touching balls (rectangle)
  FrozenTriangle,    // three mutually touching balls (rectangle)
  CushionFrozen,     // a ball touching a cushion (rectangle)
  Tiny,              // speeds near the stopping thresholds (rectangle)
  Grazing,           // a pass at 2R plus a tiny offset of either sign (rectangle)
  NearSimultaneous,  // two balls reach a third at nearly the same instant (pool table)
  InTheMouth,        // a ball against a jaw or facing or in a pocket's throat (pool or snooker)
  CueMasse,          // a cue strike: elevation to 80 deg, offsets to the miscue limit
  CueAtPocket,       // a cue strike at a ball frozen to a rail next to a pocket or to a jaw
  CueCluster,        // a cue strike into a frozen cluster or a rack
  CueTiny,           // a cue strike slow enough to stop within millimetres
  Count
};

const char* stressShotKindName(StressShotKind kind);
// Whether `name` is a kind's name (stressShotKindName).
bool isStressShotKindName(const std::string& name);

// Shot k's kind: the kinds take turns.
StressShotKind stressShotKindOf(long shot);

struct StressShot {
  StressShotKind kind = StressShotKind::Random;
  StressTableId table = StressTableId::Rectangle;
  std::vector<physics::BallState> balls;  // as simulate() gets them (cue shots: after the strike)
  // Cue shots: the scene and the scene file's JSON (without "physics"); the scene's balls are in
  // the order the scene loader puts them, which is the order of `balls`.
  std::optional<engine::Scene> scene;
  nlohmann::json scene_json;
};

// The tables the generators use, made once (the 3 StressTableId values in order).
struct StressTables {
  std::vector<StressTable> tables;
  const StressTable& of(StressTableId id) const { return tables[static_cast<int>(id)]; }
};
StressTables makeStressTables();

// Shot `shot` of `seed`, with at most `max_balls` balls (at least 2).
StressShot makeStressShot(const StressTables& tables, std::uint64_t seed, long shot, int max_balls);

// The scene file of a cue shot as `baize simulate` reads it (physics: max_events only).
nlohmann::json sceneFileJson(const StressShot& shot, long max_events);

}  // namespace baize::engine
