// A shot as the renderer needs it, whichever way it came: a scene simulated now, or a result file
// written by `baize simulate --json` (which names its scene, for the table, balls and cloth).
#pragma once

#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "engine/io/ball_set.h"
#include "engine/io/scene.h"
#include "engine/sim/shot_simulator.h"
#include "engine/io/table.h"
#include "physics/cloth_motion.h"

namespace baize::render {

struct ShotRecord {
  engine::Table table;
  engine::BallSet ball_set;
  physics::ClothParams cloth;                    // to sample the trajectories
  std::vector<std::string> ball_ids;             // ball i is ball_ids[i]
  std::vector<engine::Trajectory> trajectories;  // per ball, exact closed-form pieces
  std::vector<engine::Event> events;             // time, kind, balls and index (no states)
  double end_time_s = 0;                         // when the last ball stopped or fell
};

// The record of a scene run with trajectories recorded; throws std::invalid_argument otherwise.
ShotRecord shotRecordOf(const engine::Scene& scene, const engine::SceneRun& run);

// Reads a scene file (and simulates it) or a result file of `baize simulate --json` (recognised by
// its "trajectories" key). A result's scene is found by its "scene_path" key, else by "scene"
// relative to the working directory. Throws std::invalid_argument naming the file, the key and
// the value when either is malformed or does not match its scene.
ShotRecord loadShotRecord(const std::string& path);
ShotRecord shotRecordFromResultJson(const nlohmann::json& result, const std::string& source);

}  // namespace baize::render
