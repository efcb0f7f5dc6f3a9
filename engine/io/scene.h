// A scene: a table, a ball set, where the balls stand and the shot, read from a JSON file
// (docs/scenes.md), and its simulation through the event loop.
#pragma once

#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "engine/io/ball_set.h"
#include "engine/io/rack.h"
#include "engine/io/scene_physics.h"
#include "engine/io/table.h"
#include "engine/sim/shot_simulator.h"
#include "physics/cue_strike.h"

namespace baize::engine {

struct Scene {
  std::string source;  // the file it came from, for messages
  Table table;
  BallSet ball_set;
  std::vector<PlacedBall> balls;  // the cue ball first
  std::string cue_ball;           // the ball the cue strikes
  physics::CueShot shot;          // heading already resolved from an aim at a ball
  PhysicsOverrides overrides;     // the file's "physics" object; empty: the defaults
  // The scene as read, made self-contained: a table or ball-set file's content in place of its
  // path (built-in names stay names) and a batch line's or suite case's own shot in place of the
  // scene's. Reading it again gives this scene, bit for bit; result files embed it. A program that
  // changes the fields above after reading does not change this.
  nlohmann::json document;
};

// Reads a scene file. Throws std::invalid_argument naming the file, the key and the value for an
// unknown key, a missing one, a wrong type, an unknown table, ball set, rack or ball, a table whose
// pockets would let the set's balls through (checkCapturesCoverOpenings), overlapping balls, a
// ball off the table, an impossible shot or a physics override out of its range.
Scene loadScene(const std::string& path);
// The same from a parsed document named `source`. Its "table" and "ball_set" may also be objects:
// a table or ball-set file's content given in place (as a result file's embedded scene has them).
// Given `own_shot` (a suite case's or a batch line's own "shot", which replaces the scene's whole),
// the shot is read from it, so that a refusal about it names where it stands.
Scene sceneFromJson(const nlohmann::json& document, const std::string& source,
                    const JsonReader* own_shot = nullptr);

// The physics of the scene's table and balls: pool or snooker cloth, the ball set's radius and
// mass, the default models with the table's cushion height, then the scene's overrides.
SimulationParams simulationParamsFor(const Scene& scene);
// What the models' defaults take from the scene's table and ball set (the cushion nose height, the
// ball-ball restitution of snooker balls).
ModelDefaults modelDefaultsFor(const Scene& scene);

// The cue: physics::CueStrikeParams defaults with the ball set's radius and mass, then the scene's
// overrides (a squirt end mass turns squirt on).
physics::CueStrikeParams cueStrikeParamsFor(const Scene& scene);

// A scene's shot ready for the event loop: the cue struck, the balls' states at t = 0 and their
// parameters. Step it with ShotSimulation(params, cachedGeometryOf(scene.table), balls, ball_ids).
struct SceneStart {
  physics::CueStrikeResult strike;
  SimulationParams params;
  std::vector<physics::BallState> balls;
  std::vector<std::string> ball_ids;  // ball i is ball_ids[i]
};
SceneStart sceneStart(const Scene& scene, bool record_trajectories = false);

struct SceneRun {
  physics::CueStrikeResult strike;
  std::vector<std::string> ball_ids;  // ball i of `result` is ball_ids[i]
  SimulationResult result;
};

// Strikes the cue ball and simulates until everything is at rest (recording the balls' trajectories
// when asked). The event loop's std::invalid_argument and BallLeftTableError come with the scene's
// source in front and name the balls by id. `worker`: a thread the caller hands over for solving
// cushion impacts ahead (engine/sim/cushion_impact_worker.h); the result is the same without it.
SceneRun runScene(const Scene& scene, bool record_trajectories = false,
                  CushionImpactWorker* worker = nullptr);

}  // namespace baize::engine
