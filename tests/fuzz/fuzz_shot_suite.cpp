// Fuzz target: engine::suiteFromJson (the shot-suite reader) on arbitrary bytes. Bytes that are not
// JSON are refused by the JSON parser (its exceptions are fine); a document is either refused with
// std::invalid_argument or gives a suite that keeps the reader's promises: at least one case,
// unique case names, at least one expectation per case, every ball it names placed in the case's
// scene, regions of the allowed shapes and pockets the table has. Every expectation is then judged
// against the outcome of a shot that moved nothing (a cheap, valid outcome: the shots themselves
// are the scene_parser target's work), which must not throw, and a straight shot it calls clear
// must have a finite cut within the limit. Any other exception, a crash or a hang is a finding.
#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <exception>
#include <nlohmann/json.hpp>
#include <set>
#include <stdexcept>
#include <string>

#include "engine/play/shot_outcome.h"
#include "engine/play/shot_suite.h"
#include "tests/fuzz/fuzz_json.h"
#include "tests/fuzz/fuzz_support.h"

namespace {

using baize::engine::CueBallRegion;
using baize::engine::Expectation;
using baize::engine::kMaxCushionsExpected;
using baize::engine::Scene;
using baize::fuzz::check;

bool placed(const Scene& scene, const std::string& id) {
  return std::any_of(scene.balls.begin(), scene.balls.end(),
                     [&](const baize::engine::PlacedBall& b) { return b.id == id; });
}

void checkRegion(const CueBallRegion& g, const Scene& scene) {
  switch (g.kind) {
    case CueBallRegion::Kind::Circle:
      check(baize::fuzz::allFinite({g.centre_m.x(), g.centre_m.y(), g.radius_m}) && g.radius_m > 0,
            "a circle region is not finite or its radius is not positive");
      break;
    case CueBallRegion::Kind::Rectangle:
      check(g.min_m.allFinite() && g.max_m.allFinite() && (g.min_m.array() < g.max_m.array()).all(),
            "a rectangle region is not finite or its corners are not ordered");
      break;
    case CueBallRegion::Kind::StraightShot:
      check(placed(scene, g.ball) && g.ball != scene.cue_ball,
            "a straight shot is at a ball not placed in the scene, or at the cue ball");
      check(g.pocket >= 0 && g.pocket < static_cast<int>(scene.table.pockets.size()),
            "a straight shot is into a pocket the table does not have");
      break;
  }
}

void checkExpectation(const Expectation& e, const Scene& scene) {
  switch (e.kind) {
    case Expectation::Kind::Pocketed:
    case Expectation::Kind::NotPocketed:
      check(!e.balls.empty(), "a pocketed or not_pocketed expectation names no ball");
      for (const std::string& id : e.balls) {
        check(placed(scene, id), "an expectation names a ball not placed in the scene: " + id);
      }
      break;
    case Expectation::Kind::FirstHit:
      check(placed(scene, e.ball) && e.ball != scene.cue_ball,
            "first_hit names a ball not placed in the scene, or the cue ball");
      break;
    case Expectation::Kind::MinCushionsBeforeObjectBall:
      check(e.count >= 0 && e.count <= kMaxCushionsExpected,
            "min_cushions_before_object_ball is out of its range");
      break;
    case Expectation::Kind::CueBallStopsIn:
      checkRegion(e.region, scene);
      break;
    case Expectation::Kind::CueBallNotPocketed:
    case Expectation::Kind::NoFoul:
      break;
  }
}

// The outcome of a shot after which every ball is where the scene placed it.
baize::engine::ShotOutcome nothingMoved(const Scene& scene) {
  baize::engine::ShotOutcome outcome;
  outcome.cue_ball = scene.cue_ball;
  outcome.foul = baize::engine::Foul::NoBallHit;
  for (const baize::engine::PlacedBall& b : scene.balls) {
    outcome.final_balls.push_back({b.id, b.position_m, false});
    if (b.id == scene.cue_ball) outcome.cue_ball_final_m = b.position_m;
  }
  return outcome;
}

void judge(const Expectation& e, const Scene& scene) {
  const baize::engine::ShotOutcome outcome = nothingMoved(scene);
  try {
    const baize::engine::ExpectationResult r =
        baize::engine::evaluateExpectation(e, outcome, scene);
    check(!r.key.empty() && !r.expected.empty() && !r.measured.empty(),
          "a judged expectation has no key, expected or measured text");
  } catch (const std::exception& x) {
    baize::fuzz::fail(std::string("judging an expectation threw: ") + x.what());
  }
  if (e.kind == Expectation::Kind::CueBallStopsIn &&
      e.region.kind == CueBallRegion::Kind::StraightShot) {
    const baize::engine::StraightShotCheck s = baize::engine::straightShot(
        scene.table, scene.ball_set.radius_m, outcome, e.region.ball, e.region.pocket);
    check(!s.clear || (std::isfinite(s.cut_deg) && s.cut_deg >= 0 &&
                       s.cut_deg <= baize::engine::kMaxStraightShotCut_deg),
          "a straight shot called clear has a cut that is not finite or beyond the limit");
    check(s.clear || !s.reason.empty(), "a straight shot not clear gives no reason");
  }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  nlohmann::json document;
  if (!baize::fuzz::parseJson(data, size, &document)) return 0;
  baize::engine::Suite suite;
  try {
    // A folder that does not exist: a scene, table or ball-set file named by the suite is not
    // found (built-in tables and ball sets load).
    suite = baize::engine::suiteFromJson(document, "fuzz-no-such-folder/suite.json");
  } catch (const std::invalid_argument&) {
    return 0;
  }
  check(!suite.cases.empty(), "a loaded suite has no case");
  std::set<std::string> names;
  for (const baize::engine::SuiteCase& c : suite.cases) {
    check(names.insert(c.name).second, "two cases of a loaded suite share the name " + c.name);
    check(!c.expectations.empty(), "a loaded case has no expectation");
    check(placed(c.scene, c.scene.cue_ball), "a loaded case's cue ball is not placed");
    for (const Expectation& e : c.expectations) {
      checkExpectation(e, c.scene);
      judge(e, c.scene);
    }
  }
  return 0;
}
