// Result files (docs/results.md): what a shot did, written by `baize simulate --json` and, one per
// line, by `baize batch`, and read back by `baize render`. One versioned schema with one writer and
// one reader. A result is self-contained: it embeds its scene (table and ball-set files in place),
// so it renders with no other file.
#pragma once

#include <Eigen/Core>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <vector>

#include "engine/io/scene.h"
#include "engine/sim/shot_simulator.h"
#include "physics/cloth_motion.h"
#include "physics/cue_strike.h"

namespace baize::engine {

// The top-level "format" and "version" of every result; a reader refuses any other version.
inline constexpr const char* kResultFormat = "baize-result";
inline constexpr int kResultVersion = 1;

struct PocketedBall {
  std::string ball;
  int pocket = 0;  // index into Table::pockets (counterclockwise from the bottom-left corner)
};

enum class Foul {
  None,
  CueBallPocketed,  // the cue ball fell into a pocket
  NoBallHit,        // the cue ball touched no other ball
};

const char* foulName(Foul foul);

// A ball's state at a time asked for (`baize simulate --sample`).
struct ResultSample {
  std::string ball;
  double time_s = 0;
  bool pocketed = false;     // in a pocket by then
  physics::BallState state;  // on the table: its state then
  int pocket = -1;           // in a pocket: which (Table::pockets), since fell_at_s
  double fell_at_s = 0;
};

// One result. Ball i of the per-ball lists, the trajectories and the events is the scene's ball i.
struct ShotResult {
  std::string source;                // where the scene was read from (for people; never opened)
  std::optional<long> line;          // `baize batch`: the input line
  std::optional<nlohmann::json> id;  // `baize batch`: the line's "id", echoed
  Scene scene;                       // written as scene.document
  nlohmann::json physics;            // the parameters the shot ran with (physicsJson)
  SimulationParams params;           // the same, applied (not written: read from `physics`)
  double end_time_s = 0;             // when the last ball stopped or fell
  std::optional<std::string> first_ball_hit;  // the first ball the cue ball touched
  int cushions_before_first_hit = 0;          // the cue ball's cushion and jaw contacts before it
  std::vector<PocketedBall> pocketed;         // in the order they fell
  Foul foul = Foul::None;
  long event_count = 0;
  std::vector<std::optional<Eigen::Vector2d>> final_positions_m;  // per ball; none: pocketed
  std::vector<int> cushion_contacts;                              // per ball, cushions and jaws
  // Indices of the cushion and jaw events whose normal speed was above the scene's
  // physics.cushion.valid_normal_speed_mps (engine/play/model_range.h), in order.
  std::vector<long> beyond_model_range;
  long predictions_solved = 0;
  long predictions_skipped = 0;
  std::optional<std::vector<Trajectory>> trajectories;  // per ball, when recorded
  std::optional<std::vector<Event>> events;             // every event with its states
  std::vector<ResultSample> samples;

  std::vector<std::string> ballIds() const;  // the scene's, in its order
};

// The one writer. Doubles are written in shortest round-trip form: reading gives the same bits.
nlohmann::json resultJson(const ShotResult& result);

// The one reader. Refuses (std::invalid_argument naming `source`, the key path, the value and what
// is allowed) another format or version, a failed batch line, an unknown or missing key, a wrong
// type, an embedded scene that is not valid or names a file, ids not of the scene, positions off
// the table, speeds, spins and times out of range, pieces out of time order and an end time that
// is not when the last piece stops.
ShotResult resultFromJson(const nlohmann::json& document, const std::string& source);
ShotResult loadResult(const std::string& path);

// Whether a parsed document says it is a result ("format": "baize-result"), whatever its version.
bool isResultDocument(const nlohmann::json& document);

}  // namespace baize::engine
