// A shot as the renderer needs it, whichever way it came: a scene simulated now, or a result file
// (engine/io/result_file.h: written by `baize simulate --json` or `baize batch`, self-contained).
#pragma once

#include <string>
#include <vector>

#include "engine/io/ball_set.h"
#include "engine/io/result_file.h"
#include "engine/io/scene.h"
#include "engine/io/table.h"
#include "engine/sim/shot_simulator.h"
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

// The record of a result read from `source`: its own trajectories and events, drawn with its
// embedded table and ball set and the cloth it ran with. A result without trajectories (a batch
// line) has its embedded scene simulated again, which must end when the result says and leave the
// balls where it says (bit for bit), or the result came from other physics and is refused.
ShotRecord shotRecordOf(const engine::ShotResult& result, const std::string& source);

// Reads a result file (recognised by its "format", or by "trajectories" for a result written
// before the format was versioned, which is refused naming the format) or a scene file (simulated
// now). Throws
// std::invalid_argument naming the file, the key and the value when either is malformed.
ShotRecord loadShotRecord(const std::string& path);

}  // namespace baize::render
