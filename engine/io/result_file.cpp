#include "engine/io/result_file.h"

#include <algorithm>
#include <climits>
#include <cmath>
#include <stdexcept>

#include "engine/io/json_reader.h"
#include "engine/io/scene_physics.h"
#include "physics/value_text.h"

namespace baize::engine {
namespace {

// A ball's position in a result may lie this far beyond the table's bed and still be on the table
// (on a cushion's nose, in a pocket's mouth or capture circle), m; farther is not a result of it.
constexpr double kBeyondBed_m = 0.5;
// The fastest a ball in a result may move, m/s: a cue ball leaves the tip below 20 m/s
// (physics/cushion_model.h) and no contact adds energy. A file saying more is not a shot of ours,
// and drawing its paths would take as long as the path is long.
constexpr double kMaxSpeed_mps = 20;
// The fastest a ball in a result may spin, rad/s: a ball rolling at kMaxSpeed_mps on the smallest
// shipped ball (snooker, R 26.25 mm) spins at 760 rad/s and a cue adds at most about 500 rad/s
// (physics/cushion_model.h); 1e4 leaves room for any ball set.
constexpr double kMaxSpin_radps = 1e4;
// The longest shot a result may hold, s: a shot on any cloth of the shipped tables is over within
// a minute or two; an hour leaves room for slow cloths of a scene's own, and a longer end is a
// corrupt file (rendering it frame by frame would not end).
constexpr double kMaxShotTime_s = 3600;
// A result's end_time_s and the instant its pieces say the last ball stops or falls may differ by
// this much, s: the event loop adds the state changes' durations to the clock one by one and the
// check here sums them first, which rounds differently by ulps; a microsecond is far above that
// and far below a frame.
constexpr double kEndTimeSlack_s = 1e-6;

const Foul kFouls[] = {Foul::None, Foul::CueBallPocketed, Foul::NoBallHit};
const EventKind kEventKinds[] = {EventKind::StateChange, EventKind::BallBall, EventKind::Cushion,
                                 EventKind::Jaw, EventKind::Pocket};

// ---- writing ----

nlohmann::json pointJson(const Eigen::Vector2d& p) { return {p.x(), p.y()}; }
nlohmann::json vectorJson(const Eigen::Vector3d& v) { return {v.x(), v.y(), v.z()}; }

nlohmann::json stateJson(const physics::BallState& s) {
  return {{"position_m", pointJson(s.position)},
          {"velocity_mps", vectorJson(s.velocity)},
          {"angular_velocity_radps", vectorJson(s.angular_velocity)}};
}

nlohmann::json optionalText(const std::optional<std::string>& text) {
  return text ? nlohmann::json(*text) : nlohmann::json();
}

// ---- reading ----

// A list of names as a message gives what is allowed: "a", "b" or "c".
template <typename Names>
std::string oneOf(const Names& names) {
  std::string text;
  for (std::size_t i = 0; i < names.size(); ++i) {
    text += (i == 0 ? "" : i + 1 == names.size() ? " or " : ", ") + ("\"" + names[i] + "\"");
  }
  return text;
}

// A count written as a JSON integer in [min, INT_MAX].
int count(const JsonReader& reader, const std::string& key, int min = 0) {
  return reader.integer(key, min, INT_MAX);
}

// An array under `key` (possibly empty); each element read by `read(element, its key path)`.
template <typename Read>
void forEach(const JsonReader& reader, const std::string& key, Read read) {
  const nlohmann::json& list = reader.json().at(key);
  if (!list.is_array()) reader.reject(key, "it must be an array");
  for (std::size_t i = 0; i < list.size(); ++i) {
    read(list[i], reader.keyPath(key) + "[" + std::to_string(i) + "]");
  }
}

// `key` must be given exactly when `wanted`; `needed` and `refused` say why when it is not.
void requireWhen(const JsonReader& reader, const char* key, bool wanted, const std::string& needed,
                 const std::string& refused) {
  if (wanted && !reader.has(key)) {
    throw std::invalid_argument(reader.where(key) + " is missing: " + needed);
  }
  if (!wanted && reader.has(key)) reader.reject(key, refused);
}

class ResultReader {
 public:
  ResultReader(const nlohmann::json& document, std::string source)
      : top_(document, source), source_(std::move(source)) {}

  ShotResult read() {
    checkFormat();
    top_.requireKeys({"format", "version", "source", "scene", "physics", "end_time_s",
                      "first_ball_hit", "cushions_before_first_hit", "pocketed", "foul",
                      "event_count", "final_positions_m", "cushion_contacts", "predictions"},
                     {"line", "id", "trajectories", "events", "samples", "beyond_model_range"});
    r_.source = top_.text("source");
    if (top_.has("line")) r_.line = count(top_, "line", 1);
    if (top_.has("id")) r_.id = top_.json().at("id");
    readScene();
    readPhysics();
    r_.end_time_s = top_.nonNegativeNumber("end_time_s");
    if (!(r_.end_time_s <= kMaxShotTime_s)) {
      top_.reject("end_time_s", "a shot must end within " + physics::valueText(kMaxShotTime_s) +
                                    " s of the strike");
    }
    readOutcome();
    if (top_.has("trajectories")) readTrajectories();
    if (top_.has("events")) readEvents();
    if (top_.has("samples")) readSamples();
    if (top_.has("beyond_model_range")) readBeyondModelRange();
    return std::move(r_);
  }

 private:
  // Format and version first: a file of another kind or version is named as such, not as a
  // result with unknown keys.
  void checkFormat() const {
    if (top_.has("error") && !top_.has("scene")) {
      top_.reject("error", "a failed batch line holds no result to read");
    }
    if (!top_.has("format") || top_.json().at("format") != kResultFormat) {
      const std::string allowed = std::string("\"") + kResultFormat +
                                  "\": a result of baize simulate --json or baize batch "
                                  "(docs/results.md)";
      if (!top_.has("format")) {
        throw std::invalid_argument(top_.where("format") + " is missing: it must be " + allowed);
      }
      top_.reject("format", "it must be " + allowed);
    }
    if (!top_.has("version")) {
      throw std::invalid_argument(top_.where("version") + " is missing: it must be " +
                                  std::to_string(kResultVersion));
    }
    const nlohmann::json& version = top_.json().at("version");
    if (!version.is_number_integer() || version.get<long long>() != kResultVersion) {
      top_.reject("version", "this baize reads version " + std::to_string(kResultVersion) +
                                 " of the result format only");
    }
  }

  // The embedded scene, read as a scene is; it must hold its table and ball set in place or by
  // built-in name, never as a file to open.
  void readScene() {
    const JsonReader scene = top_.object("scene");
    for (const char* key : {"table", "ball_set"}) {
      const nlohmann::json& value = scene.json().value(key, nlohmann::json());
      const std::string text = value.is_string() ? value.get<std::string>() : "";
      if (text.size() > 5 && text.compare(text.size() - 5, 5, ".json") == 0) {
        scene.reject(key,
                     "a result's scene holds its table and ball set in place (or by built-in "
                     "name), never as a file");
      }
    }
    r_.scene = sceneFromJson(scene.json(), top_.where("scene"));
    for (const PlacedBall& b : r_.scene.balls) ids_.push_back(b.id);
  }

  // The parameters the shot ran with, read and checked as a scene's physics on top of its scene.
  void readPhysics() {
    const JsonReader physics = top_.object("physics");
    r_.physics = physics.json();
    const PhysicsOverrides ran = readPhysicsOverrides(physics);
    r_.params = simulationParamsFor(r_.scene);
    applyPhysicsOverrides(ran, modelDefaultsFor(r_.scene), &r_.params);
    physics::CueStrikeParams cue = cueStrikeParamsFor(r_.scene);
    applyPhysicsOverrides(ran, &cue);
    validateScenePhysics(r_.params, cue, source_,
                         [] { return std::string("the physics the result was run with"); });
  }

  int ballIndex(const JsonReader& reader, const std::string& key) const {
    const std::string id = reader.text(key);
    const auto found = std::find(ids_.begin(), ids_.end(), id);
    if (found == ids_.end()) reader.reject(key, "one of the scene's balls: " + oneOf(ids_));
    return static_cast<int>(found - ids_.begin());
  }

  int pocketIndex(const JsonReader& reader, const std::string& key) const {
    const std::vector<std::string>& names = pocketNames();
    const std::string name = reader.text(key);
    const auto found = std::find(names.begin(), names.end(), name);
    if (found == names.end()) reader.reject(key, "a pocket: " + oneOf(names));
    return static_cast<int>(found - names.begin());
  }

  // A per-ball object: exactly the scene's ids as keys, each value read by `read(reader, id)`.
  template <typename Read>
  void forEachBall(const std::string& key, Read read) const {
    const JsonReader balls = top_.object(key);
    for (const std::string& id : balls.keys()) {
      if (std::find(ids_.begin(), ids_.end(), id) == ids_.end()) {
        balls.reject(id, "unknown ball; the keys here are the scene's balls: " + oneOf(ids_));
      }
    }
    for (const std::string& id : ids_) {
      if (!balls.has(id)) {
        throw std::invalid_argument(balls.where(id) +
                                    " is missing: every ball of the scene has an entry here");
      }
      read(balls, id);
    }
  }

  Eigen::Vector2d positionOnTable(const JsonReader& reader, const std::string& key) const {
    const Eigen::Vector2d p = reader.point(key);
    if (!(std::abs(p.x()) <= r_.scene.table.length_m / 2 + kBeyondBed_m &&
          std::abs(p.y()) <= r_.scene.table.width_m / 2 + kBeyondBed_m)) {
      reader.reject(key, "it is off the table (beyond its bed by more than " +
                             physics::valueText(kBeyondBed_m) + " m)");
    }
    return p;
  }

  Eigen::Vector3d boundedVector(const JsonReader& reader, const std::string& key, double bound,
                                const std::string& unit) const {
    const std::vector<double> v = reader.finiteNumbers(key, 3);
    for (const double c : v) {
      if (!(std::abs(c) <= bound)) {
        reader.reject(key, "each component must be of magnitude at most " +
                               physics::valueText(bound) + " " + unit +
                               " (faster is not a shot; docs/results.md)");
      }
    }
    return {v[0], v[1], v[2]};
  }

  double timeInShot(const JsonReader& reader, const std::string& key) const {
    const double t = reader.nonNegativeNumber(key);
    if (!(t <= r_.end_time_s)) {
      reader.reject(key,
                    "it must lie in [0, end_time_s = " + physics::valueText(r_.end_time_s) + "] s");
    }
    return t;
  }

  physics::BallState state(const JsonReader& reader) const {
    physics::BallState s;
    s.position = positionOnTable(reader, "position_m");
    s.velocity = boundedVector(reader, "velocity_mps", kMaxSpeed_mps, "m/s");
    s.angular_velocity = boundedVector(reader, "angular_velocity_radps", kMaxSpin_radps, "rad/s");
    if (s.velocity.z() != 0) reader.reject("velocity_mps", "its z component must be 0");
    return s;
  }

  void readOutcome() {
    const nlohmann::json& first = top_.json().at("first_ball_hit");
    if (!first.is_null()) {
      const int ball = ballIndex(top_, "first_ball_hit");
      if (ids_[ball] == r_.scene.cue_ball)
        top_.reject("first_ball_hit", "a ball other than the cue ball");
      r_.first_ball_hit = ids_[ball];
    }
    r_.cushions_before_first_hit = count(top_, "cushions_before_first_hit");
    forEach(top_, "pocketed", [&](const nlohmann::json& item, const std::string& path) {
      const JsonReader fell(item, source_, path);
      fell.requireExactKeys({"ball", "pocket"});
      const int ball = ballIndex(fell, "ball");
      for (const PocketedBall& p : r_.pocketed) {
        if (p.ball == ids_[ball]) fell.reject("ball", "a ball falls once");
      }
      r_.pocketed.push_back({ids_[ball], pocketIndex(fell, "pocket")});
    });
    const std::string foul = top_.text("foul");
    std::vector<std::string> foul_names;
    for (const Foul f : kFouls) foul_names.push_back(foulName(f));
    const auto named = std::find(foul_names.begin(), foul_names.end(), foul);
    if (named == foul_names.end()) top_.reject("foul", oneOf(foul_names));
    r_.foul = kFouls[named - foul_names.begin()];
    r_.event_count = count(top_, "event_count");
    forEachBall("final_positions_m", [&](const JsonReader& balls, const std::string& id) {
      const bool pocketed = std::any_of(r_.pocketed.begin(), r_.pocketed.end(),
                                        [&](const PocketedBall& p) { return p.ball == id; });
      if (pocketed != balls.json().at(id).is_null()) {
        balls.reject(id, pocketed ? "null: the ball is pocketed"
                                  : "[x, y]: the ball is not pocketed (null is for one that is)");
      }
      r_.final_positions_m.push_back(pocketed ? std::nullopt
                                              : std::optional(positionOnTable(balls, id)));
    });
    forEachBall("cushion_contacts", [&](const JsonReader& balls, const std::string& id) {
      r_.cushion_contacts.push_back(count(balls, id));
    });
    const JsonReader predictions = top_.object("predictions");
    predictions.requireExactKeys({"solved", "skipped"});
    r_.predictions_solved = count(predictions, "solved");
    r_.predictions_skipped = count(predictions, "skipped");
  }

  // Event indices, increasing, each below event_count (which events they are is the writer's).
  void readBeyondModelRange() {
    forEach(top_, "beyond_model_range", [&](const nlohmann::json& item, const std::string& path) {
      const long previous = r_.beyond_model_range.empty() ? -1 : r_.beyond_model_range.back();
      if (!item.is_number_integer() || item.get<long>() <= previous ||
          item.get<long>() >= r_.event_count) {
        throw std::invalid_argument(source_ + ": " + path + " = " + item.dump() +
                                    " is not allowed: it must be an event index, below "
                                    "event_count and above the index before it");
      }
      r_.beyond_model_range.push_back(item.get<long>());
    });
  }

  void readTrajectories() {
    std::vector<Trajectory> trajectories;
    forEachBall("trajectories", [&](const JsonReader& balls, const std::string& id) {
      Trajectory trajectory;
      forEach(balls, id, [&](const nlohmann::json& item, const std::string& path) {
        const JsonReader piece(item, source_, path);
        piece.requireExactKeys(
            {"start_time_s", "position_m", "velocity_mps", "angular_velocity_radps", "pocketed"});
        TrajectoryPiece q;
        q.start_time_s = timeInShot(piece, "start_time_s");
        if (!trajectory.empty() && q.start_time_s < trajectory.back().start_time_s) {
          piece.reject("start_time_s", "pieces must be in time order");
        }
        q.state = state(piece);
        q.pocketed = piece.boolean("pocketed");
        trajectory.push_back(q);
      });
      if (trajectory.empty()) balls.reject(id, "a non-empty array of pieces");
      // A path starts at the strike where the scene places its ball: otherwise it is not of this
      // scene's shot.
      const Eigen::Vector2d& placed = r_.scene.balls[trajectories.size()].position_m;
      if (!(trajectory[0].start_time_s == 0 && trajectory[0].state.position == placed)) {
        balls.reject(id, "pieces starting at 0 s where the scene places the ball, [" +
                             physics::valueText(placed.x()) + ", " +
                             physics::valueText(placed.y()) + "]");
      }
      trajectories.push_back(std::move(trajectory));
    });
    // The shot ends when its last ball stops or falls, which the last piece of each path fixes:
    // an end_time_s beyond it would have pictures and frames drawn long after everything stood
    // still, one before it would cut the shot short.
    double last_stop_s = 0;
    for (const Trajectory& trajectory : trajectories) {
      const TrajectoryPiece& last = trajectory.back();
      const double moving_s = last.pocketed ? 0 : physics::timeToRest(r_.params.cloth, last.state);
      last_stop_s = std::max(last_stop_s, last.start_time_s + moving_s);
    }
    if (!(std::abs(r_.end_time_s - last_stop_s) <= kEndTimeSlack_s)) {
      top_.reject("end_time_s", "it must be when the last ball stops or falls, " +
                                    physics::valueText(last_stop_s) +
                                    " s after the strike by the last piece of each trajectory");
    }
    r_.trajectories = std::move(trajectories);
  }

  void readEvents() {
    std::vector<Event> events;
    forEach(top_, "events", [&](const nlohmann::json& item, const std::string& path) {
      const JsonReader event(item, source_, path);
      event.requireKeys({"time_s", "type", "ball", "before", "after"}, {"other", "index"});
      Event e;
      e.time_s = timeInShot(event, "time_s");
      if (!events.empty() && e.time_s < events.back().time_s) {
        event.reject("time_s", "events must be in time order");
      }
      const std::string type = event.text("type");
      std::vector<std::string> type_names;
      for (const EventKind kind : kEventKinds) type_names.push_back(eventKindName(kind));
      const auto named = std::find(type_names.begin(), type_names.end(), type);
      if (named == type_names.end()) event.reject("type", oneOf(type_names));
      e.kind = kEventKinds[named - type_names.begin()];
      e.ball = ballIndex(event, "ball");
      const bool two_balls = e.kind == EventKind::BallBall;
      requireWhen(event, "other", two_balls, "a ball-ball event names the other ball",
                  "only a ball-ball event names another ball");
      if (two_balls) e.other = ballIndex(event, "other");
      const int indices =
          e.kind == EventKind::Cushion  ? static_cast<int>(r_.scene.table.cushions.size())
          : e.kind == EventKind::Jaw    ? static_cast<int>(r_.scene.table.jaw_arcs.size())
          : e.kind == EventKind::Pocket ? static_cast<int>(r_.scene.table.pockets.size())
                                        : 0;
      requireWhen(event, "index", indices > 0, "a cushion, jaw or pocket event numbers it",
                  "only a cushion, jaw or pocket event has an index");
      if (indices > 0) e.index = event.integer("index", 0, indices - 1);
      const std::size_t involved = two_balls ? 2 : 1;
      for (const char* key : {"before", "after"}) {
        const nlohmann::json& states = event.json().at(key);
        if (!states.is_array() || states.size() != involved) {
          event.reject(key, "an array of the states of the event's " + std::to_string(involved) +
                                (involved == 1 ? " ball" : " balls"));
        }
        EventBalls& balls = std::string(key) == "before" ? e.before : e.after;
        forEach(event, key, [&](const nlohmann::json& s, const std::string& state_path) {
          const JsonReader ball(s, source_, state_path);
          ball.requireExactKeys({"position_m", "velocity_mps", "angular_velocity_radps"});
          balls.push_back(state(ball));
        });
      }
      events.push_back(e);
    });
    if (static_cast<long>(events.size()) != r_.event_count) {
      top_.reject("events",
                  "it must list event_count = " + std::to_string(r_.event_count) + " events");
    }
    r_.events = std::move(events);
  }

  void readSamples() {
    forEach(top_, "samples", [&](const nlohmann::json& item, const std::string& path) {
      const JsonReader sample(item, source_, path);
      ResultSample s;
      s.ball = ids_[ballIndex(sample, "ball")];
      s.time_s = sample.nonNegativeNumber("time_s");
      s.pocketed = sample.boolean("pocketed");
      if (s.pocketed) {
        sample.requireExactKeys({"ball", "time_s", "pocketed", "pocket", "fell_at_s"});
        s.pocket = pocketIndex(sample, "pocket");
        s.fell_at_s = timeInShot(sample, "fell_at_s");
      } else {
        sample.requireExactKeys(
            {"ball", "time_s", "pocketed", "position_m", "velocity_mps", "angular_velocity_radps"});
        s.state = state(sample);
      }
      r_.samples.push_back(s);
    });
  }

  JsonReader top_;
  std::string source_;
  ShotResult r_;
  std::vector<std::string> ids_;  // the scene's balls
};

}  // namespace

const char* foulName(Foul foul) {
  switch (foul) {
    case Foul::None:
      return "none";
    case Foul::CueBallPocketed:
      return "cue ball pocketed";
    case Foul::NoBallHit:
      return "no ball hit";
  }
  return "?";
}

std::vector<std::string> ShotResult::ballIds() const {
  std::vector<std::string> ids;
  for (const PlacedBall& b : scene.balls) ids.push_back(b.id);
  return ids;
}

nlohmann::json resultJson(const ShotResult& r) {
  const std::vector<std::string> ids = r.ballIds();
  const std::vector<std::string>& pockets = pocketNames();
  nlohmann::json out = {{"format", kResultFormat}, {"version", kResultVersion}};
  out["source"] = r.source;
  if (r.line) out["line"] = *r.line;
  if (r.id) out["id"] = *r.id;
  out["scene"] = r.scene.document;
  out["physics"] = r.physics;
  out["end_time_s"] = r.end_time_s;
  out["first_ball_hit"] = optionalText(r.first_ball_hit);
  out["cushions_before_first_hit"] = r.cushions_before_first_hit;
  out["pocketed"] = nlohmann::json::array();
  for (const PocketedBall& p : r.pocketed) {
    out["pocketed"].push_back({{"ball", p.ball}, {"pocket", pockets.at(p.pocket)}});
  }
  out["foul"] = foulName(r.foul);
  out["event_count"] = r.event_count;
  out["predictions"] = {{"solved", r.predictions_solved}, {"skipped", r.predictions_skipped}};
  out["beyond_model_range"] = r.beyond_model_range;
  out["final_positions_m"] = nlohmann::json::object();
  out["cushion_contacts"] = nlohmann::json::object();
  for (std::size_t i = 0; i < ids.size(); ++i) {
    const std::optional<Eigen::Vector2d>& at = r.final_positions_m.at(i);
    out["final_positions_m"][ids[i]] = at ? pointJson(*at) : nlohmann::json();
    out["cushion_contacts"][ids[i]] = r.cushion_contacts.at(i);
  }
  if (r.trajectories) {
    out["trajectories"] = nlohmann::json::object();
    for (std::size_t i = 0; i < ids.size(); ++i) {
      // From each piece's start the ball moves in closed form (physics::advance) from that state
      // until the next piece.
      nlohmann::json& pieces = out["trajectories"][ids[i]] = nlohmann::json::array();
      for (const TrajectoryPiece& piece : r.trajectories->at(i)) {
        nlohmann::json q = stateJson(piece.state);
        q["start_time_s"] = piece.start_time_s;
        q["pocketed"] = piece.pocketed;
        pieces.push_back(std::move(q));
      }
    }
  }
  if (r.events) {
    out["events"] = nlohmann::json::array();
    for (const Event& e : *r.events) {
      nlohmann::json event = {{"time_s", e.time_s},
                              {"type", eventKindName(e.kind)},
                              {"ball", ids.at(e.ball)},
                              {"before", nlohmann::json::array()},
                              {"after", nlohmann::json::array()}};
      if (e.other >= 0) event["other"] = ids.at(e.other);
      if (e.index >= 0) event["index"] = e.index;
      for (const physics::BallState& s : e.before) event["before"].push_back(stateJson(s));
      for (const physics::BallState& s : e.after) event["after"].push_back(stateJson(s));
      out["events"].push_back(std::move(event));
    }
  }
  if (!r.samples.empty()) {
    out["samples"] = nlohmann::json::array();
    for (const ResultSample& s : r.samples) {
      nlohmann::json sample = {{"ball", s.ball}, {"time_s", s.time_s}, {"pocketed", s.pocketed}};
      if (s.pocketed) {
        sample["pocket"] = pockets.at(s.pocket);
        sample["fell_at_s"] = s.fell_at_s;
      } else {
        sample.update(stateJson(s.state));
      }
      out["samples"].push_back(std::move(sample));
    }
  }
  return out;
}

ShotResult resultFromJson(const nlohmann::json& document, const std::string& source) {
  return ResultReader(document, source).read();
}

ShotResult loadResult(const std::string& path) {
  return resultFromJson(JsonReader::parseFile(path), path);
}

bool isResultDocument(const nlohmann::json& document) {
  return document.is_object() && document.contains("format") &&
         document.at("format") == kResultFormat;
}

}  // namespace baize::engine
