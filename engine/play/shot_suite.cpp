#include "engine/play/shot_suite.h"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <iomanip>
#include <optional>
#include <set>
#include <sstream>
#include <stdexcept>

#include "engine/io/json_reader.h"

namespace baize::engine {
namespace {

// The longest case name, in bytes: a name is also a PNG file's name (with its ".png"), and file
// names are at most 255 bytes.
constexpr std::size_t kMaxCaseNameChars = 200;

constexpr double kRadToDeg = 180 / M_PI;

std::string fixed(double value, int decimals = 3) {
  std::ostringstream out;
  out << std::fixed << std::setprecision(decimals) << value;
  return out.str();
}

std::string pointText(const Eigen::Vector2d& p) {
  return "[" + fixed(p.x()) + ", " + fixed(p.y()) + "]";
}

std::string pocketText(int pocket) {
  const auto& names = pocketNames();
  return pocket >= 0 && pocket < static_cast<int>(names.size())
             ? names[pocket]
             : "pocket " + std::to_string(pocket);
}

std::string listText(const std::vector<std::string>& ids) {
  std::string text;
  for (const std::string& id : ids) text += (text.empty() ? "" : ", ") + id;
  return "[" + text + "]";
}

std::string pocketedText(const ShotOutcome& outcome) {
  if (outcome.pocketed.empty()) return "pocketed: none";
  std::string text;
  for (const PocketedBall& p : outcome.pocketed) {
    text += (text.empty() ? "" : ", ") + p.ball + " (" + pocketText(p.pocket) + ")";
  }
  return "pocketed: " + text;
}

bool placed(const Scene& scene, const std::string& id) {
  return std::any_of(scene.balls.begin(), scene.balls.end(),
                     [&](const PlacedBall& b) { return b.id == id; });
}

// Distance (m) from point p to the segment a-b.
double distanceToSegment(const Eigen::Vector2d& p, const Eigen::Vector2d& a,
                         const Eigen::Vector2d& b) {
  const Eigen::Vector2d ab = b - a;
  const double length2 = ab.squaredNorm();
  const double t = length2 > 0 ? std::clamp((p - a).dot(ab) / length2, 0.0, 1.0) : 0.0;
  return (a + t * ab - p).norm();
}

// A JSON array of `count` finite numbers at `key` of `object`, or a refusal naming `allowed`.
std::vector<double> numbers(const JsonReader& reader, const nlohmann::json& object,
                            const std::string& key, std::size_t count, const std::string& allowed) {
  const nlohmann::json& value = object.at(key);
  bool ok = value.is_array() && value.size() == count;
  std::vector<double> out;
  for (std::size_t i = 0; ok && i < count; ++i) {
    ok = value[i].is_number() && std::isfinite(value[i].get<double>());
    if (ok) out.push_back(value[i].get<double>());
  }
  if (!ok) reader.reject(key, allowed);
  return out;
}

// A non-empty array of ids of balls placed in the scene.
std::vector<std::string> ballIds(const JsonReader& reader, const nlohmann::json& object,
                                 const std::string& key, const Scene& scene) {
  const nlohmann::json& value = object.at(key);
  const std::string allowed = "a non-empty array of ids (strings) of balls placed in the scene";
  if (!value.is_array() || value.empty()) reader.reject(key, allowed);
  std::vector<std::string> ids;
  for (const nlohmann::json& id : value) {
    if (!id.is_string() || !placed(scene, id.get<std::string>())) reader.reject(key, allowed);
    ids.push_back(id.get<std::string>());
  }
  return ids;
}

std::string objectBall(const JsonReader& reader, const std::string& key, const Scene& scene) {
  const std::string id = reader.text(key);
  if (!placed(scene, id) || id == scene.cue_ball) {
    reader.reject(key, "the id of a ball placed in the scene other than the cue ball");
  }
  return id;
}

void requireTrue(const JsonReader& reader, const std::string& key) {
  if (!reader.boolean(key)) reader.reject(key, "true (leave the key out to expect nothing)");
}

CueBallRegion readRegion(const JsonReader& reader, const nlohmann::json& raw, const Scene& scene,
                         const std::string& where) {
  reader.requireKeys({}, {"circle", "rectangle", "straight_shot_at", "into_pocket"});
  const int forms = static_cast<int>(reader.has("circle")) +
                    static_cast<int>(reader.has("rectangle")) +
                    static_cast<int>(reader.has("straight_shot_at") || reader.has("into_pocket"));
  if (forms != 1) {
    throw std::invalid_argument(where +
                                " is not allowed: give exactly one region: circle [x, y, r], "
                                "rectangle [x0, y0, x1, y1], or straight_shot_at with into_pocket");
  }
  CueBallRegion region;
  if (reader.has("circle")) {
    const auto c = numbers(reader, raw, "circle", 3, "[x, y, r] in metres, three finite numbers");
    if (c[2] <= 0) reader.reject("circle", "[x, y, r] with the radius r > 0");
    region.kind = CueBallRegion::Kind::Circle;
    region.centre_m = {c[0], c[1]};
    region.radius_m = c[2];
  } else if (reader.has("rectangle")) {
    const auto r =
        numbers(reader, raw, "rectangle", 4, "[x0, y0, x1, y1] in metres, four finite numbers");
    if (!(r[0] < r[2] && r[1] < r[3])) {
      reader.reject("rectangle", "[x0, y0, x1, y1] with x0 < x1 and y0 < y1");
    }
    region.kind = CueBallRegion::Kind::Rectangle;
    region.min_m = {r[0], r[1]};
    region.max_m = {r[2], r[3]};
  } else {
    if (!reader.has("straight_shot_at") || !reader.has("into_pocket")) {
      throw std::invalid_argument(where +
                                  " is not allowed: straight_shot_at and into_pocket go together");
    }
    region.kind = CueBallRegion::Kind::StraightShot;
    region.ball = objectBall(reader, "straight_shot_at", scene);
    const nlohmann::json& pocket = raw.at("into_pocket");
    const int count = static_cast<int>(scene.table.pockets.size());
    std::string allowed = "a pocket index 0.." + std::to_string(count - 1) + " or a name (";
    for (int k = 0; k < count; ++k) allowed += (k ? ", " : "") + pocketNames().at(k);
    allowed += ")";
    if (pocket.is_number_integer() && pocket.get<long>() >= 0 && pocket.get<long>() < count) {
      region.pocket = static_cast<int>(pocket.get<long>());
    } else if (pocket.is_string()) {
      const auto& names = pocketNames();
      const auto at = std::find(names.begin(), names.end(), pocket.get<std::string>());
      if (at == names.end()) reader.reject("into_pocket", allowed);
      region.pocket = static_cast<int>(at - names.begin());
    } else {
      reader.reject("into_pocket", allowed);
    }
  }
  return region;
}

std::vector<Expectation> readExpectations(const JsonReader& reader, const nlohmann::json& raw,
                                          const Scene& scene) {
  reader.requireKeys({}, {"pocketed", "not_pocketed", "first_hit", "cue_ball_not_pocketed",
                          "cue_ball_stops_in", "min_cushions_before_object_ball", "no_foul"});
  std::vector<Expectation> out;
  for (const std::string& key : reader.keys()) {  // sorted: a stable report order
    Expectation e;
    if (key == "pocketed" || key == "not_pocketed") {
      e.kind = key == "pocketed" ? Expectation::Kind::Pocketed : Expectation::Kind::NotPocketed;
      e.balls = ballIds(reader, raw, key, scene);
    } else if (key == "first_hit") {
      e.kind = Expectation::Kind::FirstHit;
      e.ball = objectBall(reader, key, scene);
    } else if (key == "cue_ball_not_pocketed") {
      e.kind = Expectation::Kind::CueBallNotPocketed;
      requireTrue(reader, key);
    } else if (key == "no_foul") {
      e.kind = Expectation::Kind::NoFoul;
      requireTrue(reader, key);
    } else if (key == "min_cushions_before_object_ball") {
      e.kind = Expectation::Kind::MinCushionsBeforeObjectBall;
      e.count = reader.integer(key, 0, kMaxCushionsExpected);
    } else {
      e.kind = Expectation::Kind::CueBallStopsIn;
      e.region = readRegion(reader.object(key), raw.at(key), scene, reader.where(key));
    }
    out.push_back(e);
  }
  return out;
}

SuiteCase readCase(const nlohmann::json& raw, const std::string& source, int index) {
  const std::string indexed = "cases[" + std::to_string(index) + "]";
  const JsonReader named(raw, source, indexed);
  const std::string name = named.text("name");
  // The name starts a line of the report and a PNG file's name: printable, and not too long for
  // either.
  const bool printable = std::all_of(name.begin(), name.end(), [](char c) {
    return static_cast<unsigned char>(c) >= 0x20 && c != 0x7f;
  });
  if (!printable || name.size() > kMaxCaseNameChars) {
    named.reject("name", "a case name has at most " + std::to_string(kMaxCaseNameChars) +
                             " characters and no control characters (line breaks, tabs)");
  }
  const JsonReader reader(raw, source, "case \"" + name + "\"");
  reader.requireKeys({"name", "scene", "expect"}, {"description", "shot"});
  if (reader.has("description")) reader.text("description");

  nlohmann::json scene_document;
  std::string scene_source = source;  // an inline scene's files are relative to the suite
  const nlohmann::json& scene = raw.at("scene");
  if (scene.is_string()) {
    const std::string relative = reader.text("scene");
    scene_source = (std::filesystem::path(source).parent_path() / relative).string();
    try {
      scene_document = JsonReader::parseFile(scene_source);
    } catch (const std::invalid_argument& e) {
      throw std::invalid_argument(reader.where("scene") + ": " + e.what());
    }
  } else if (scene.is_object()) {
    scene_document = scene;
  } else {
    reader.reject("scene", "a scene object or the path of a scene file relative to the suite");
  }
  SuiteCase result;
  result.name = name;
  // The case's own shot, when it gives one, replaces the scene's whole and is read where it stands,
  // so that a refusal names it.
  std::optional<JsonReader> own_shot;
  if (reader.has("shot")) own_shot.emplace(reader.object("shot"));
  try {
    result.scene = sceneFromJson(scene_document, scene_source, own_shot ? &*own_shot : nullptr);
  } catch (const std::invalid_argument& e) {
    const std::string message = e.what();
    if (own_shot && message.rfind(reader.where("shot"), 0) == 0) {
      throw std::invalid_argument(message + " (the case's shot replaces the scene's whole)");
    }
    throw std::invalid_argument(reader.where("scene") + ": " + message);
  }
  const JsonReader expect = reader.object("expect");
  if (expect.keys().empty()) reader.reject("expect", "an object with at least one expectation");
  result.expectations = readExpectations(expect, raw.at("expect"), result.scene);
  return result;
}

// One sample's scene: the intended shot with this sample's error.
void setSampleShot(const SuiteCase& suite_case, const ExecutionNoise& noise, std::uint64_t seed,
                   Scene* scene) {
  NormalGenerator normal(seed);
  const ExecutionError error =
      drawExecutionError(noise, suite_case.scene.ball_set.radius_m, &normal);
  scene->shot = perturbedShot(suite_case.scene.shot, error);
}

}  // namespace

const char* expectationKey(Expectation::Kind kind) {
  switch (kind) {
    case Expectation::Kind::Pocketed:
      return "pocketed";
    case Expectation::Kind::NotPocketed:
      return "not_pocketed";
    case Expectation::Kind::FirstHit:
      return "first_hit";
    case Expectation::Kind::CueBallNotPocketed:
      return "cue_ball_not_pocketed";
    case Expectation::Kind::CueBallStopsIn:
      return "cue_ball_stops_in";
    case Expectation::Kind::MinCushionsBeforeObjectBall:
      return "min_cushions_before_object_ball";
    case Expectation::Kind::NoFoul:
      return "no_foul";
  }
  return "?";
}

StraightShotCheck straightShot(const Table& table, double ball_radius_m, const ShotOutcome& outcome,
                               const std::string& ball, int pocket) {
  StraightShotCheck check;
  const FinalBall* object = outcome.ball(ball);
  if (outcome.cue_ball_pocketed) {
    check.reason = "the cue ball is pocketed";
    return check;
  }
  if (object == nullptr || object->pocketed) {
    check.reason = "ball " + ball + (object ? " is pocketed" : " is not on the table");
    return check;
  }
  const double R = ball_radius_m;
  const Eigen::Vector2d mouth = table.pockets.at(pocket).mouth_centre_m;
  const Eigen::Vector2d cue = outcome.cue_ball_final_m;
  const Eigen::Vector2d to_pocket = (mouth - object->position_m).normalized();
  const Eigen::Vector2d ghost = object->position_m - 2 * R * to_pocket;
  const Eigen::Vector2d to_ghost = ghost - cue;
  // A cue ball already at the ghost position (frozen to the ball on the line) is a straight hit.
  check.cut_deg =
      to_ghost.norm() > 0
          ? std::acos(std::clamp(to_ghost.normalized().dot(to_pocket), -1.0, 1.0)) * kRadToDeg
          : 0;
  if (check.cut_deg > kMaxStraightShotCut_deg) {
    check.reason =
        "cut " + fixed(check.cut_deg, 1) + " deg > " + fixed(kMaxStraightShotCut_deg, 0) + " deg";
    return check;
  }
  const double clearance = 2 * R + kStraightShotClearance_m;
  for (const FinalBall& other : outcome.final_balls) {
    if (other.pocketed || other.id == ball || other.id == outcome.cue_ball) continue;
    if (distanceToSegment(other.position_m, cue, ghost) < clearance) {
      check.reason = "ball " + other.id + " blocks the cue ball's path";
      return check;
    }
    if (distanceToSegment(other.position_m, object->position_m, mouth) < clearance) {
      check.reason = "ball " + other.id + " blocks ball " + ball + "'s path to the pocket";
      return check;
    }
  }
  check.clear = true;
  return check;
}

Suite suiteFromJson(const nlohmann::json& document, const std::string& source) {
  const JsonReader root(document, source);
  root.requireKeys({"cases"}, {"description"});
  if (root.has("description")) root.text("description");
  root.objectArray("cases");  // a non-empty array of objects
  Suite suite;
  suite.source = source;
  std::set<std::string> names;
  const nlohmann::json& cases = document.at("cases");
  for (std::size_t i = 0; i < cases.size(); ++i) {
    SuiteCase c = readCase(cases[i], source, static_cast<int>(i));
    if (!names.insert(c.name).second) {
      JsonReader(cases[i], source, "cases[" + std::to_string(i) + "]")
          .reject("name", "a name no other case of the suite has");
    }
    suite.cases.push_back(std::move(c));
  }
  return suite;
}

Suite loadSuite(const std::string& path) {
  return suiteFromJson(JsonReader::parseFile(path), path);
}

ExpectationResult evaluateExpectation(const Expectation& e, const ShotOutcome& outcome,
                                      const Scene& scene) {
  ExpectationResult r;
  r.key = expectationKey(e.kind);
  switch (e.kind) {
    case Expectation::Kind::Pocketed:
    case Expectation::Kind::NotPocketed: {
      const bool want = e.kind == Expectation::Kind::Pocketed;
      r.expected = (want ? "pocketed " : "not pocketed ") + listText(e.balls);
      r.met = std::all_of(e.balls.begin(), e.balls.end(),
                          [&](const std::string& id) { return outcome.wasPocketed(id) == want; });
      r.measured = pocketedText(outcome);
      break;
    }
    case Expectation::Kind::FirstHit:
      r.expected = "first hit " + e.ball;
      r.measured = "first hit " + outcome.first_hit.value_or("none");
      r.met = outcome.first_hit == e.ball;
      break;
    case Expectation::Kind::CueBallNotPocketed: {
      r.expected = "cue ball not pocketed";
      r.met = !outcome.cue_ball_pocketed;
      std::string where;
      for (const PocketedBall& p : outcome.pocketed) {
        if (p.ball == outcome.cue_ball) where = pocketText(p.pocket);
      }
      r.measured = r.met ? "cue ball on the table" : "cue ball pocketed (" + where + ")";
      break;
    }
    case Expectation::Kind::CueBallStopsIn: {
      const CueBallRegion& g = e.region;
      const Eigen::Vector2d at = outcome.cue_ball_final_m;
      r.measured = outcome.cue_ball_pocketed ? "cue ball pocketed" : "cue ball at " + pointText(at);
      if (g.kind == CueBallRegion::Kind::Circle) {
        r.expected = "cue ball within " + fixed(g.radius_m) + " m of " + pointText(g.centre_m);
        const double distance = (at - g.centre_m).norm();
        r.met = !outcome.cue_ball_pocketed && distance <= g.radius_m;
        if (!outcome.cue_ball_pocketed) r.measured += ", " + fixed(distance) + " m from the centre";
      } else if (g.kind == CueBallRegion::Kind::Rectangle) {
        r.expected = "cue ball in " + pointText(g.min_m) + "-" + pointText(g.max_m);
        r.met = !outcome.cue_ball_pocketed && (at.array() >= g.min_m.array()).all() &&
                (at.array() <= g.max_m.array()).all();
      } else {
        r.expected = "straight shot at " + g.ball + " into " + pocketText(g.pocket);
        const StraightShotCheck check =
            straightShot(scene.table, scene.ball_set.radius_m, outcome, g.ball, g.pocket);
        r.met = check.clear;
        if (!outcome.cue_ball_pocketed) {
          r.measured += check.clear ? ", cut " + fixed(check.cut_deg, 1) + " deg, paths clear"
                                    : ", " + check.reason;
        }
      }
      break;
    }
    case Expectation::Kind::MinCushionsBeforeObjectBall:
      r.expected = "at least " + std::to_string(e.count) + " cushions before the first hit";
      r.measured = std::to_string(outcome.cushions_before_first_hit) + " cushions before " +
                   (outcome.first_hit ? "the first hit" : "rest (no ball hit)");
      r.met = outcome.first_hit && outcome.cushions_before_first_hit >= e.count;
      break;
    case Expectation::Kind::NoFoul:
      r.expected = "no foul";
      r.measured = std::string("foul: ") + foulName(outcome.foul);
      r.met = outcome.foul == Foul::None;
      break;
  }
  return r;
}

CaseResult runCase(const SuiteCase& suite_case) {
  CaseResult result;
  result.name = suite_case.name;
  ShotOutcome outcome;
  try {
    outcome = shotOutcome(runScene(suite_case.scene), suite_case.scene.cue_ball);
  } catch (const std::exception& e) {
    result.error = e.what();
    return result;
  }
  result.passed = true;
  for (const Expectation& e : suite_case.expectations) {
    result.expectations.push_back(evaluateExpectation(e, outcome, suite_case.scene));
    result.passed = result.passed && result.expectations.back().met;
  }
  return result;
}

ProbabilityEstimate wilsonEstimate(int successes, int samples, double z) {
  if (samples <= 0 || successes < 0 || successes > samples) {
    throw std::invalid_argument("a probability estimate from " + std::to_string(successes) +
                                " successes in " + std::to_string(samples) +
                                " samples is not allowed: it needs 0 <= successes <= samples, "
                                "samples > 0");
  }
  ProbabilityEstimate p;
  p.successes = successes;
  p.samples = samples;
  const double n = samples;
  p.probability = successes / n;
  const double z2 = z * z;
  const double centre = (p.probability + z2 / (2 * n)) / (1 + z2 / n);
  const double half =
      z / (1 + z2 / n) * std::sqrt(p.probability * (1 - p.probability) / n + z2 / (4 * n * n));
  p.low = std::max(0.0, centre - half);
  p.high = std::min(1.0, centre + half);
  return p;
}

NoisyCaseResult sampleCase(const SuiteCase& suite_case, const ExecutionNoise& noise, int samples,
                           std::uint64_t seed, std::uint64_t case_index) {
  validateExecutionNoise(noise);
  if (samples < 1) {
    throw std::invalid_argument("noise samples = " + std::to_string(samples) +
                                " is not allowed: at least 1");
  }
  const std::size_t count = suite_case.expectations.size();
  std::vector<int> met(count, 0);
  int whole = 0;
  NoisyCaseResult result;
  result.samples = samples;
  Scene scene = suite_case.scene;
  for (int s = 0; s < samples; ++s) {
    setSampleShot(suite_case, noise, sampleSeed(seed, case_index, static_cast<std::uint64_t>(s)),
                  &scene);
    ShotOutcome outcome;
    try {
      outcome = shotOutcome(runScene(scene), scene.cue_ball);
    } catch (const std::invalid_argument&) {  // the strike refused the perturbed tip offset
      ++result.miscues;
      continue;
    } catch (const std::runtime_error&) {  // the event budget ran out
      ++result.failed_runs;
      continue;
    }
    bool all = true;
    for (std::size_t k = 0; k < count; ++k) {
      const bool ok = evaluateExpectation(suite_case.expectations[k], outcome, scene).met;
      met[k] += ok;
      all = all && ok;
    }
    whole += all;
  }
  for (int m : met) result.expectations.push_back(wilsonEstimate(m, samples));
  result.whole_case = wilsonEstimate(whole, samples);
  return result;
}

}  // namespace baize::engine
