#include "engine/io/scene.h"

#include <cmath>
#include <filesystem>
#include <stdexcept>

#include "engine/io/json_reader.h"
#include "physics/value_text.h"

namespace baize::engine {
namespace {

// Balls in a scene file may overlap by this much (m) and still count as touching: positions written
// by hand or by another program round to about this.
constexpr double kPlacementSlack_m = 1e-9;

// A cue at this elevation, deg, points straight down: elevations must stay below it.
constexpr double kVerticalCue_deg = 90;
// Largest heading magnitude, deg: programs that write shots need not wrap their headings into one
// turn, but beyond this one ulp of the heading exceeds 1e-10 deg and the aim stops being exact (and
// near 1e306 deg the conversion to radians overflows).
constexpr double kMaxHeading_deg = 1e6;
// A steepest cue elevation suggested in a message is rounded down to 1e-4 deg: readable, and still
// allowed when used as written.
constexpr double kSuggestedElevationScale = 1e4;

// A built-in name, or a file path (relative to the scene's folder) when it ends in ".json".
std::string resolvePath(const std::string& scene_source, const std::string& name) {
  const std::filesystem::path folder = std::filesystem::path(scene_source).parent_path();
  return (folder / name).string();
}

bool isFile(const std::string& name) {
  return name.size() > 5 && name.compare(name.size() - 5, 5, ".json") == 0;
}

void placeOrMove(std::vector<PlacedBall>* balls, const std::string& id, const Eigen::Vector2d& at) {
  for (PlacedBall& b : *balls) {
    if (b.id == id) {
      b.position_m = at;
      return;
    }
  }
  balls->push_back({id, at});
}

// The cue's speed, elevation and tip offsets of `shot`, each checked in the units the scene writes
// them in, so that a refusal names the key and the value as written; then physics' own check,
// which they imply.
void readCueShot(const JsonReader& shot, physics::CueShot* cue) {
  const double speed_mps = shot.finiteNumber("speed_mps");
  if (!(speed_mps > 0 && speed_mps <= physics::kMaxCueSpeed_mps)) {
    shot.reject("speed_mps", "it must lie in (0, " + physics::valueText(physics::kMaxCueSpeed_mps) +
                                 "] m/s: a cue at " +
                                 physics::valueText(physics::kMaxCueSpeed_mps) +
                                 " m/s sends the ball off at about 16 m/s, faster than any "
                                 "measured break (12-14 m/s)");
  }
  cue->speed_mps = speed_mps;

  const double elevation_deg = shot.has("elevation_deg") ? shot.finiteNumber("elevation_deg") : 0;
  cue->elevation_rad = elevation_deg * M_PI / 180;
  if (!(elevation_deg >= 0 && elevation_deg < kVerticalCue_deg && cue->elevation_rad < M_PI / 2)) {
    shot.reject("elevation_deg",
                "it must lie in [0, " + physics::valueText(kVerticalCue_deg) +
                    ") deg: the cue cannot come from below the table or straight down");
  }

  cue->side_offset = shot.has("side") ? shot.finiteNumber("side") : 0;
  cue->height_offset = shot.has("height") ? shot.finiteNumber("height") : 0;
  const double offset = std::hypot(cue->side_offset, cue->height_offset);  // as physics computes it
  if (!(offset <= physics::kMiscueOffsetLimit)) {
    // The larger offset is blamed; the other is named when the scene gives it.
    const bool side_larger = std::abs(cue->side_offset) > std::abs(cue->height_offset);
    const std::string blamed = side_larger ? "side" : "height";
    const std::string other = side_larger ? "height" : "side";
    shot.reject(blamed, (shot.has(other) ? "with " + shot.keyAndValue(other) + " the" : "the") +
                            " tip offset sqrt(side^2 + height^2) = " + physics::valueText(offset) +
                            " must be at most " + physics::valueText(physics::kMiscueOffsetLimit) +
                            " (units of R), or the tip miscues");
  }
  if (!physics::cueMeetsTipPointFirst(*cue)) {
    // Rounded down to 1 / kSuggestedElevationScale deg, so that the value suggested, used as
    // written, is allowed.
    const double steepest_deg =
        std::floor(physics::steepestCueElevationRad(cue->side_offset, cue->height_offset) * 180 /
                   M_PI * kSuggestedElevationScale) /
        kSuggestedElevationScale;
    shot.reject("elevation_deg", "with " + shot.keyAndValue("height") +
                                     (shot.has("side") ? " and " + shot.keyAndValue("side") : "") +
                                     " it must be below " + physics::valueText(steepest_deg) +
                                     " deg: a steeper cue's line enters the ball before the tip "
                                     "reaches its point");
  }
  try {
    physics::validateCueShot(*cue);
  } catch (const std::invalid_argument& e) {
    // Not reached: the checks above imply physics' own.
    throw std::logic_error(std::string("a cue shot passed the scene's checks, not physics': ") +
                           e.what());
  }
}

// The scene's table or ball set under `key`: a built-in name, a file (relative to the scene's
// folder) or the file's content in place. `embedded` becomes what the self-contained document
// holds there: the name, or the object.
template <typename Asset>
Asset sceneAsset(const JsonReader& scene, const char* key, const std::string& kind,
                 nlohmann::json* embedded,
                 Asset (*from_json)(const nlohmann::json&, const std::string&),
                 Asset (*builtin)(const std::string&)) {
  const bool in_place = embedded->is_object();
  const std::string name = in_place ? "" : scene.text(key);
  try {
    if (in_place) return from_json(*embedded, scene.where(key));
    if (!isFile(name)) return builtin(name);
    const std::string path = resolvePath(scene.source(), name);
    *embedded = JsonReader::parseFile(path);
    return from_json(*embedded, path);
  } catch (const std::invalid_argument& e) {
    scene.reject(
        key, "a built-in " + kind + " name, a .json file or a " + kind + " object: " + e.what());
  }
}

}  // namespace

Scene sceneFromJson(const nlohmann::json& document, const std::string& source,
                    const JsonReader* own_shot) {
  const JsonReader scene(document, source);
  if (own_shot) {
    scene.requireKeys({"table", "ball_set"}, {"rack", "balls", "physics", "shot"});
  } else {
    scene.requireKeys({"table", "ball_set", "shot"}, {"rack", "balls", "physics"});
  }
  Scene result;
  result.source = source;
  result.document = document;
  result.table = sceneAsset<Table>(scene, "table", "table", &result.document["table"],
                                   tableFromJson, builtinTable);
  result.ball_set = sceneAsset<BallSet>(scene, "ball_set", "ball set", &result.document["ball_set"],
                                        ballSetFromJson, builtinBallSet);
  // Where the table meets the balls: its pockets must swallow a ball of this radius that passes
  // their facings (a table file alone cannot say; engine/io/table.h).
  try {
    checkCapturesCoverOpenings(result.table, result.ball_set.radius_m);
  } catch (const std::invalid_argument& e) {
    scene.reject("table", "a table whose pockets catch the balls of the set '" +
                              result.ball_set.name + "': " + e.what());
  }
  if (scene.has("rack")) {
    const JsonReader rack = scene.object("rack");
    rack.requireKeys({"name"}, {"jitter_seed", "jitter_m"});
    RackOptions options;
    if (rack.has("jitter_m") && !rack.has("jitter_seed")) {
      rack.reject("jitter_m", "it needs rack.jitter_seed, the seed of the random displacements");
    }
    if (rack.has("jitter_seed")) {
      options.jitter_seed = static_cast<std::uint64_t>(rack.integer("jitter_seed", 0, 1 << 30));
      if (rack.has("jitter_m")) {
        options.jitter_radius_m = rack.finiteNumber("jitter_m");
        if (!(options.jitter_radius_m >= 0 && options.jitter_radius_m <= kMaxJitterRadius_m)) {
          rack.reject("jitter_m", "it must lie in [0, " + physics::valueText(kMaxJitterRadius_m) +
                                      "] m (the rack's gap, twice the jitter, is at most " +
                                      physics::valueText(kMaxGap_m) + " m)");
        }
      }
      // Packed as tightly as the jitter allows without overlaps (docs/scenes.md).
      options.gap_m = jitteredRackGap_m(options.jitter_radius_m);
    }
    try {
      result.balls = placeRack(rack.text("name"), result.table, result.ball_set, options);
    } catch (const std::invalid_argument& e) {
      rack.reject("name", e.what());
    }
  }
  if (scene.has("balls")) {
    const JsonReader placed = scene.object("balls");
    for (const std::string& id : placed.keys()) {
      if (!result.ball_set.contains(id)) {
        placed.reject(id, "a ball of the set '" + result.ball_set.name + "'");
      }
      placeOrMove(&result.balls, id, placed.point(id));
    }
  }
  if (result.balls.empty()) {
    throw std::invalid_argument(source +
                                ": the scene places no balls: give a rack, balls by id, or both");
  }

  const JsonReader shot = own_shot ? *own_shot : scene.object("shot");
  shot.requireKeys({"speed_mps"},
                   {"cue_ball", "aim_at", "heading_deg", "elevation_deg", "side", "height"});
  result.cue_ball = shot.has("cue_ball") ? shot.text("cue_ball") : "cue";
  const auto find = [&](const std::string& id) -> const PlacedBall* {
    for (const PlacedBall& b : result.balls) {
      if (b.id == id) return &b;
    }
    return nullptr;
  };
  const PlacedBall* cue = find(result.cue_ball);
  if (!cue) shot.reject("cue_ball", "a ball placed in the scene");
  if (shot.has("aim_at") == shot.has("heading_deg")) {
    shot.reject(
        shot.has("aim_at") ? "heading_deg" : "aim_at",
        "a shot is aimed either at a ball (aim_at) or along a heading (heading_deg), not both "
        "and not neither");
  }
  double heading_rad = 0;
  if (shot.has("aim_at")) {
    const PlacedBall* target = find(shot.text("aim_at"));
    if (!target || target == cue) shot.reject("aim_at", "another ball placed in the scene");
    const Eigen::Vector2d to = target->position_m - cue->position_m;
    heading_rad = std::atan2(to.y(), to.x());
  } else {
    const double heading_deg = shot.finiteNumber("heading_deg");
    if (!(std::abs(heading_deg) <= kMaxHeading_deg)) {
      shot.reject("heading_deg",
                  "its magnitude must be at most " + physics::valueText(kMaxHeading_deg) + " deg");
    }
    heading_rad = heading_deg * M_PI / 180;
  }
  result.shot.heading_rad = heading_rad;
  readCueShot(shot, &result.shot);
  if (own_shot) result.document["shot"] = own_shot->json();
  if (scene.has("physics")) result.overrides = readPhysicsOverrides(scene.object("physics"));
  validateScenePhysics(simulationParamsFor(result), cueStrikeParamsFor(result), source, [&] {
    return "the values of table '" + result.table.name + "' (" + result.table.source +
           "), ball set '" + result.ball_set.name + "' (" + result.ball_set.source +
           ") and this scene's physics, if any";
  });

  // Where the balls stand: on the table, apart. Between the rails anywhere R clear of them; beyond
  // a rail's line only in a pocket's opening (a ball hanging in the jaws), inside the cushion
  // outline and short of the capture circle, where the event loop's own check (simulate) keeps it
  // clear of the facings and jaw roundings.
  const double R = result.ball_set.radius_m;
  const double x_limit = result.table.length_m / 2 - R, y_limit = result.table.width_m / 2 - R;
  const std::vector<Eigen::Vector2d> outline = cushionOutline(result.table.cushions);
  for (std::size_t i = 0; i < result.balls.size(); ++i) {
    const PlacedBall& b = result.balls[i];
    const bool between_rails = std::abs(b.position_m.x()) <= x_limit + kPlacementSlack_m &&
                               std::abs(b.position_m.y()) <= y_limit + kPlacementSlack_m;
    const bool off_table = !between_rails && !insideOutline(outline, b.position_m);
    // Between the rails too: a small or shallow pocket's circle or deep ends reach in there.
    const bool in_capture = !off_table && inCaptureCircle(result.table, b.position_m);
    if (off_table || in_capture || pastBothDeepEnds(result.table, b.position_m)) {
      const std::string where = source + ": ball '" + b.id + "' at [" +
                                physics::valueText(b.position_m.x()) + ", " +
                                physics::valueText(b.position_m.y()) + "]";
      const std::string why =
          off_table ? " is off the table"
          : in_capture
              ? " is in a pocket: inside its capture circle (it would start pocketed)"
              : " is in a pocket: past both its facings' deep ends, where nothing holds it";
      throw std::invalid_argument(where + why + (off_table ? ": " : "; ") +
                                  "|x| <= " + physics::valueText(x_limit) +
                                  " and |y| <= " + physics::valueText(y_limit) +
                                  " m are allowed, or a place in a pocket's opening short of its "
                                  "capture circle and of the facings' deep ends");
    }
    for (std::size_t j = 0; j < i; ++j) {
      const double distance = (b.position_m - result.balls[j].position_m).norm();
      if (distance < 2 * R - kPlacementSlack_m) {
        throw std::invalid_argument(source + ": balls '" + b.id + "' and '" + result.balls[j].id +
                                    "' overlap: their centres are " + physics::valueText(distance) +
                                    " m apart, at least 2R = " + physics::valueText(2 * R) +
                                    " m is allowed");
      }
    }
  }
  return result;
}

Scene loadScene(const std::string& path) {
  return sceneFromJson(JsonReader::parseFile(path), path);
}

ModelDefaults modelDefaultsFor(const Scene& scene) {
  ModelDefaults defaults;
  defaults.cushion_contact_height_m = scene.table.cushion_contact_height_m;
  defaults.cushion_restitution = scene.table.cushion_restitution;
  defaults.cushion_friction = scene.table.cushion_friction;
  if (scene.table.kind == TableKind::Snooker)
    defaults.ball_ball_restitution = 0.89;  // snooker balls (physics-notes section 3)
  return defaults;
}

SimulationParams simulationParamsFor(const Scene& scene) {
  BallProperties ball;
  ball.mass_kg = scene.ball_set.mass_kg;
  ball.radius_m = scene.ball_set.radius_m;
  const ModelDefaults defaults = modelDefaultsFor(scene);
  SimulationParams p = simulationParamsWith(
      ball, scene.table.kind == TableKind::Snooker ? physics::snookerCloth() : physics::poolCloth(),
      defaults);
  applyPhysicsOverrides(scene.overrides, defaults, &p);
  return p;
}

physics::CueStrikeParams cueStrikeParamsFor(const Scene& scene) {
  physics::CueStrikeParams cue;
  cue.ball_mass_kg = scene.ball_set.mass_kg;
  cue.ball_radius_m = scene.ball_set.radius_m;
  applyPhysicsOverrides(scene.overrides, &cue);
  return cue;
}

SceneStart sceneStart(const Scene& scene, bool record_trajectories) {
  SceneStart start;
  start.params = simulationParamsFor(scene);
  start.params.record_trajectories = record_trajectories;
  start.strike = physics::strikeCueBall(cueStrikeParamsFor(scene), scene.shot);
  start.balls.reserve(scene.balls.size());
  start.ball_ids.reserve(scene.balls.size());
  for (const PlacedBall& b : scene.balls) {
    physics::BallState state;
    state.position = b.position_m;
    if (b.id == scene.cue_ball) {
      state.velocity = start.strike.ball.v;
      state.angular_velocity = start.strike.ball.w;
    }
    start.balls.push_back(state);
    start.ball_ids.push_back(b.id);
  }
  return start;
}

SceneRun runScene(const Scene& scene, bool record_trajectories, CushionImpactWorker* worker) {
  SceneStart start = sceneStart(scene, record_trajectories);
  SceneRun run;
  run.strike = start.strike;
  run.ball_ids = start.ball_ids;
  // The event loop's refusals name balls by id; the scene's file is put in front of them.
  const std::string prefix = scene.source.empty() ? "" : scene.source + ": ";
  try {
    run.result =
        simulate(start.params, cachedGeometryOf(scene.table), start.balls, start.ball_ids, worker);
  } catch (const std::invalid_argument& e) {
    throw std::invalid_argument(prefix + e.what());
  } catch (const BallLeftTableError& e) {
    throw BallLeftTableError(prefix + e.what());
  }
  return run;
}

}  // namespace baize::engine
