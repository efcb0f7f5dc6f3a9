#include "engine/play/shot_suite.h"

#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "tests/engine/error_test_support.h"

namespace baize::engine {
namespace {

constexpr double kPoolRadius_m = 0.028575;

// A suite of one case on the 9 ft table: the cue ball at (-0.5, 0), ball 1 at (0, 0), ball 2 at
// (0.5, 0.3); `expect` is the case's "expect" object.
nlohmann::json oneCase(const std::string& expect) {
  return nlohmann::json::parse(R"({"cases": [{"name": "straight", "scene": {
      "table": "pool-9ft", "ball_set": "pool",
      "balls": {"cue": [-0.5, 0.0], "1": [0.0, 0.0], "2": [0.5, 0.3]},
      "shot": {"aim_at": "1", "speed_mps": 1.0}}, "expect": )" +
                               expect + "}]}");
}

std::string suiteError(const nlohmann::json& document) {
  return invalidArgumentMessage([&] { suiteFromJson(document, "drills.json"); });
}

TEST(SuiteParsing, ReadsEveryExpectationInKeyOrder) {
  const Suite suite = suiteFromJson(
      oneCase(R"({"pocketed": ["1"], "not_pocketed": ["2"], "first_hit": "1", "no_foul": true,
                  "cue_ball_not_pocketed": true, "min_cushions_before_object_ball": 0,
                  "cue_ball_stops_in": {"straight_shot_at": "2", "into_pocket": "top-right"}})"),
      "drills.json");
  ASSERT_EQ(suite.cases.size(), 1u);
  const SuiteCase& c = suite.cases[0];
  EXPECT_EQ(c.name, "straight");
  std::vector<std::string> keys;
  for (const Expectation& e : c.expectations) keys.push_back(expectationKey(e.kind));
  EXPECT_EQ(keys, (std::vector<std::string>{"cue_ball_not_pocketed", "cue_ball_stops_in",
                                            "first_hit", "min_cushions_before_object_ball",
                                            "no_foul", "not_pocketed", "pocketed"}));
  EXPECT_EQ(c.expectations[1].region.kind, CueBallRegion::Kind::StraightShot);
  EXPECT_EQ(c.expectations[1].region.pocket, 3);
}

TEST(SuiteParsing, AShotOverrideReplacesTheScenesShot) {
  nlohmann::json document = oneCase(R"({"no_foul": true})");
  document["cases"][0]["shot"] = {{"heading_deg", 90}, {"speed_mps", 2.5}};
  const Suite suite = suiteFromJson(document, "drills.json");
  EXPECT_DOUBLE_EQ(suite.cases[0].scene.shot.speed_mps, 2.5);
  EXPECT_DOUBLE_EQ(suite.cases[0].scene.shot.heading_rad, M_PI / 2);
}

TEST(SuiteParsing, ErrorsNameTheFileTheCaseAndTheKey) {
  struct {
    const char* expect;
    const char* key;
  } bad[] = {
      {R"({"pocketed": ["1"], "potted": ["1"]})", "potted"},  // unknown key
      {R"({"first_hit": 1})", "first_hit"},                   // wrong type
      {R"({"first_hit": "cue"})", "first_hit"},               // the cue ball itself
      {R"({"pocketed": ["9"]})", "pocketed"},                 // not in the scene
      {R"({"pocketed": []})", "pocketed"},                    // empty
      {R"({"no_foul": false})", "no_foul"},                   // false expects nothing
      {R"({"min_cushions_before_object_ball": -1})", "min_cushions_before_object_ball"},
      {R"({"cue_ball_stops_in": {"circle": [0, 0, -0.1]}})", "circle"},
      {R"({"cue_ball_stops_in": {"circle": [0, 0]}})", "circle"},
      {R"({"cue_ball_stops_in": {"rectangle": [1, 0, 0, 1]}})", "rectangle"},
      {R"({"cue_ball_stops_in": {"circle": [0, 0, 1], "rectangle": [0, 0, 1, 1]}})",
       "cue_ball_stops_in"},
      {R"({"cue_ball_stops_in": {"straight_shot_at": "2", "into_pocket": "corner"}})",
       "into_pocket"},
      {R"({"cue_ball_stops_in": {"straight_shot_at": "2", "into_pocket": 6}})", "into_pocket"},
      {R"({"cue_ball_stops_in": {"straight_shot_at": "2"}})", "cue_ball_stops_in"},
      {R"({})", "expect"},
  };
  for (const auto& b : bad) {
    const std::string message = suiteError(oneCase(b.expect));
    EXPECT_MENTIONS(message, "drills.json");
    EXPECT_MENTIONS(message, "case \"straight\"");
    EXPECT_MENTIONS(message, b.key);
  }
}

TEST(SuiteParsing, CaseLevelErrorsNameTheCase) {
  nlohmann::json document = oneCase(R"({"no_foul": true})");
  document["cases"][0]["shot"] = {{"aim_at", "1"}, {"speed_mps", -1}};
  std::string message = suiteError(document);
  EXPECT_MENTIONS(message, "case \"straight\".shot.speed_mps = -1 is not allowed");

  // A bad key in the case's own shot is named there, not in the scene.
  document = oneCase(R"({"no_foul": true})");
  document["cases"][0]["shot"] = {{"speed_mps", 99}};
  message = suiteError(document);
  EXPECT_MENTIONS(message, "drills.json: case \"straight\".shot.");
  EXPECT_MENTIONS(message, "(the case's shot replaces the scene's whole)");

  // A bad key of the scene's own stays the scene's, even one whose name starts like "shot".
  document = oneCase(R"({"no_foul": true})");
  document["cases"][0]["shot"] = {{"aim_at", "1"}, {"speed_mps", 1}};
  document["cases"][0]["scene"]["shotgun"] = 1;
  message = suiteError(document);
  EXPECT_MENTIONS(message, "case \"straight\".scene: drills.json: shotgun = 1 is not allowed");
  EXPECT_EQ(message.find("replaces the scene's whole"), std::string::npos) << message;

  document = oneCase(R"({"no_foul": true})");
  document["cases"][0]["scene"] = 3;
  EXPECT_MENTIONS(suiteError(document), "case \"straight\".scene");

  document = oneCase(R"({"no_foul": true})");
  document["cases"][0]["scene"] = "no-such-scene.json";
  message = suiteError(document);
  EXPECT_MENTIONS(message, "case \"straight\".scene");
  EXPECT_MENTIONS(message, "no-such-scene.json");

  document = oneCase(R"({"no_foul": true})");
  document["cases"][0]["extra"] = 1;
  EXPECT_MENTIONS(suiteError(document), "case \"straight\".extra");

  document = oneCase(R"({"no_foul": true})");
  document["cases"][0].erase("name");
  EXPECT_MENTIONS(suiteError(document), "cases[0].name");

  document = oneCase(R"({"no_foul": true})");
  document["cases"].push_back(document["cases"][0]);
  message = suiteError(document);
  EXPECT_MENTIONS(message, "cases[1].name");
  EXPECT_MENTIONS(message, "straight");

  // A name starts report lines and names PNG files: no line breaks, at most 200 characters.
  for (const std::string& name :
       {std::string("a\nPASS fake"), std::string("tab\there"), std::string(201, 'n')}) {
    document = oneCase(R"({"no_foul": true})");
    document["cases"][0]["name"] = name;
    EXPECT_MENTIONS(suiteError(document), "cases[0].name");
    EXPECT_MENTIONS(suiteError(document), "at most 200 characters and no control characters");
  }
  document = oneCase(R"({"no_foul": true})");
  document["cases"][0]["name"] = std::string(200, 'n');
  EXPECT_NO_THROW(suiteFromJson(document, "drills.json"));

  EXPECT_MENTIONS(suiteError(nlohmann::json::parse(R"({"cases": []})")), "cases");
  EXPECT_MENTIONS(suiteError(nlohmann::json::parse(R"({"cases": [], "x": 1})")), "x");
}

// A hand-made outcome on the 9 ft table: the cue ball stopped at `cue`, the balls "1" and "2" at
// the given places.
ShotOutcome handMade(const Eigen::Vector2d& cue, const Eigen::Vector2d& one,
                     const Eigen::Vector2d& two) {
  ShotOutcome o;
  o.cue_ball = "cue";
  o.cue_ball_final_m = cue;
  o.final_balls = {{"cue", cue, false}, {"1", one, false}, {"2", two, false}};
  o.first_hit = "1";
  return o;
}

const Scene& testScene() {
  static const Scene scene = suiteFromJson(oneCase(R"({"no_foul": true})"), "t").cases[0].scene;
  return scene;
}

ExpectationResult judge(const std::string& expect, const ShotOutcome& outcome) {
  const Suite suite = suiteFromJson(oneCase(expect), "t");
  return evaluateExpectation(suite.cases[0].expectations.at(0), outcome, testScene());
}

TEST(ExpectationEvaluation, PocketedAndNotPocketedReportWhatFellAndWhere) {
  ShotOutcome o = handMade({0, 0}, {1, 0}, {0.5, 0.3});
  o.final_balls[1].pocketed = true;
  o.pocketed = {{"1", 3}};
  ExpectationResult r = judge(R"({"pocketed": ["1"]})", o);
  EXPECT_TRUE(r.met);
  EXPECT_EQ(r.measured, "pocketed: 1 (top-right)");
  EXPECT_FALSE(judge(R"({"pocketed": ["1", "2"]})", o).met);
  EXPECT_TRUE(judge(R"({"not_pocketed": ["2"]})", o).met);
  r = judge(R"({"not_pocketed": ["1"]})", o);
  EXPECT_FALSE(r.met);
  EXPECT_EQ(r.measured, "pocketed: 1 (top-right)");
}

TEST(ExpectationEvaluation, FirstHitCushionsAndFouls) {
  ShotOutcome o = handMade({0, 0}, {1, 0}, {0.5, 0.3});
  o.first_hit = "2";
  o.cushions_before_first_hit = 2;
  ExpectationResult r = judge(R"({"first_hit": "1"})", o);
  EXPECT_FALSE(r.met);
  EXPECT_EQ(r.measured, "first hit 2");
  EXPECT_TRUE(judge(R"({"first_hit": "2"})", o).met);
  EXPECT_TRUE(judge(R"({"min_cushions_before_object_ball": 2})", o).met);
  r = judge(R"({"min_cushions_before_object_ball": 3})", o);
  EXPECT_FALSE(r.met);
  EXPECT_EQ(r.measured, "2 cushions before the first hit");
  o.first_hit.reset();  // cushions but no ball: not a kick that worked
  o.foul = Foul::NoBallHit;
  EXPECT_FALSE(judge(R"({"min_cushions_before_object_ball": 0})", o).met);
  r = judge(R"({"no_foul": true})", o);
  EXPECT_FALSE(r.met);
  EXPECT_EQ(r.measured, "foul: no ball hit");
}

TEST(ExpectationEvaluation, ACueBallInAPocketStopsInNoRegion) {
  ShotOutcome o = handMade({0, 0}, {1, 0}, {0.5, 0.3});
  o.cue_ball_pocketed = true;
  o.final_balls[0].pocketed = true;
  o.pocketed = {{"cue", 1}};
  o.foul = Foul::CueBallPocketed;
  ExpectationResult r = judge(R"({"cue_ball_not_pocketed": true})", o);
  EXPECT_FALSE(r.met);
  EXPECT_EQ(r.measured, "cue ball pocketed (bottom-middle)");
  EXPECT_FALSE(judge(R"({"cue_ball_stops_in": {"circle": [0, 0, 1]}})", o).met);
  EXPECT_FALSE(judge(R"({"cue_ball_stops_in": {"rectangle": [-1, -1, 1, 1]}})", o).met);
}

TEST(ExpectationEvaluation, CirclesAndRectanglesIncludeTheirEdges) {
  const ShotOutcome o = handMade({0.3, 0.4}, {1, 0}, {0.5, 0.3});
  EXPECT_TRUE(judge(R"({"cue_ball_stops_in": {"circle": [0, 0, 0.5]}})", o).met);  // 3-4-5
  const ExpectationResult r = judge(R"({"cue_ball_stops_in": {"circle": [0, 0, 0.49]}})", o);
  EXPECT_FALSE(r.met);
  EXPECT_EQ(r.measured, "cue ball at [0.300, 0.400], 0.500 m from the centre");
  EXPECT_TRUE(judge(R"({"cue_ball_stops_in": {"rectangle": [0.3, 0, 1, 0.4]}})", o).met);
  EXPECT_FALSE(judge(R"({"cue_ball_stops_in": {"rectangle": [0.31, 0, 1, 0.4]}})", o).met);
}

TEST(StraightShot, AClearLineIntoTheCornerAndTheBallsThatBlockIt) {
  const Table& table = testScene().table;
  const double R = kPoolRadius_m;
  const Eigen::Vector2d mouth = table.pockets[3].mouth_centre_m;
  // Ball 1 half a metre from the top-right pocket's mouth on its axis (45 deg), the cue ball
  // straight behind it: a cut of 0.
  const Eigen::Vector2d axis = Eigen::Vector2d(1, 1).normalized();
  const Eigen::Vector2d one = mouth - 0.5 * axis;
  const Eigen::Vector2d cue = one - 0.6 * axis;
  ShotOutcome o = handMade(cue, one, {-1, -0.5});
  StraightShotCheck check = straightShot(table, R, o, "1", 3);
  EXPECT_TRUE(check.clear) << check.reason;
  EXPECT_NEAR(check.cut_deg, 0, 1e-6);

  // Ball 2 on the object ball's path, then beside it just inside and just outside the clearance.
  const Eigen::Vector2d side = Eigen::Vector2d(-1, 1).normalized();
  o.final_balls[2].position_m = one + 0.25 * axis;
  check = straightShot(table, R, o, "1", 3);
  EXPECT_FALSE(check.clear);
  EXPECT_EQ(check.reason, "ball 2 blocks ball 1's path to the pocket");
  o.final_balls[2].position_m = one + 0.25 * axis + (2 * R + kStraightShotClearance_m * 0.9) * side;
  EXPECT_FALSE(straightShot(table, R, o, "1", 3).clear);
  o.final_balls[2].position_m = one + 0.25 * axis + (2 * R + kStraightShotClearance_m * 1.1) * side;
  EXPECT_TRUE(straightShot(table, R, o, "1", 3).clear);
  // On the cue ball's path.
  o.final_balls[2].position_m = cue + 0.3 * axis;
  EXPECT_EQ(straightShot(table, R, o, "1", 3).reason, "ball 2 blocks the cue ball's path");

  // The cue ball off to the side: a cut of 60 deg is playable, 85 deg is not.
  o.final_balls[2].position_m = {-1, -0.5};
  const Eigen::Vector2d ghost = one - 2 * R * axis;
  const auto from_cut = [&](double cut_deg) {
    const double a = cut_deg * M_PI / 180;
    const Eigen::Vector2d direction = std::cos(a) * axis + std::sin(a) * side;
    return Eigen::Vector2d(ghost - 0.4 * direction);
  };
  o.cue_ball_final_m = o.final_balls[0].position_m = from_cut(60);
  check = straightShot(table, R, o, "1", 3);
  EXPECT_TRUE(check.clear) << check.reason;
  EXPECT_NEAR(check.cut_deg, 60, 1e-9);
  o.cue_ball_final_m = o.final_balls[0].position_m = from_cut(85);
  EXPECT_FALSE(straightShot(table, R, o, "1", 3).clear);
  // The object ball pocketed: no shot at it.
  o.cue_ball_final_m = o.final_balls[0].position_m = cue;
  o.final_balls[1].pocketed = true;
  EXPECT_EQ(straightShot(table, R, o, "1", 3).reason, "ball 1 is pocketed");
}

TEST(Wilson, MatchesTheTextbookIntervals) {
  // Wilson (1927) score intervals at 95 %: 0/10 -> [0, 0.2775], 5/10 -> [0.2366, 0.7634],
  // 10/10 -> [0.7225, 1].
  constexpr double kTolerance = 5e-5;  // the reference values' last digit
  constexpr double kRounding = 1e-12;  // bounds that are exactly 0 or 1 in exact arithmetic
  ProbabilityEstimate p = wilsonEstimate(0, 10);
  EXPECT_NEAR(p.low, 0.0, kRounding);
  EXPECT_NEAR(p.high, 0.2775, kTolerance);
  p = wilsonEstimate(5, 10);
  EXPECT_NEAR(p.low, 0.2366, kTolerance);
  EXPECT_NEAR(p.high, 0.7634, kTolerance);
  p = wilsonEstimate(10, 10);
  EXPECT_NEAR(p.low, 0.7225, kTolerance);
  EXPECT_NEAR(p.high, 1.0, kRounding);
  EXPECT_THROW(wilsonEstimate(3, 2), std::invalid_argument);
  EXPECT_THROW(wilsonEstimate(0, 0), std::invalid_argument);
}

// A lone cue ball rolled about 0.48 m (0.3 m/s cue, natural roll), and a circle of 0.16 m around
// the noise-free stop: the speed error (0.075 m/s, a quarter of the speed, so about half the
// distance) leaves it inside about half the time.
SuiteCase loneRollCase() {
  const nlohmann::json scene = nlohmann::json::parse(R"({"table": "pool-9ft", "ball_set": "pool",
      "balls": {"cue": [-0.8, 0.0]},
      "shot": {"heading_deg": 0, "speed_mps": 0.3, "height": 0.4}})");
  const Scene s = sceneFromJson(scene, "t");
  const Eigen::Vector2d stop = shotOutcome(runScene(s), "cue").cue_ball_final_m;
  nlohmann::json suite = {
      {"cases",
       {{{"name", "roll"},
         {"scene", scene},
         {"expect", {{"cue_ball_stops_in", {{"circle", {stop.x(), stop.y(), 0.16}}}}}}}}}};
  return suiteFromJson(suite, "t").cases[0];
}

TEST(Noise, SamplingIsReproducibleAndDependsOnTheSeed) {
  const SuiteCase c = loneRollCase();
  const NoisyCaseResult a = sampleCase(c, ExecutionNoise{}, 50, 11, 0);
  const NoisyCaseResult b = sampleCase(c, ExecutionNoise{}, 50, 11, 0);
  EXPECT_EQ(a.whole_case.successes, b.whole_case.successes);
  EXPECT_EQ(a.expectations[0].successes, a.whole_case.successes);  // one expectation
  EXPECT_EQ(a.samples, 50);
  // Without noise every sample is the noise-free shot, which stops at the circle's centre.
  EXPECT_EQ(sampleCase(c, ExecutionNoise{0, 0, 0, 0}, 20, 11, 0).whole_case.successes, 20);
  EXPECT_TRUE(runCase(c).passed);
}

TEST(Noise, DoublingTheSamplesHalvesTheVarianceOfTheEstimate) {
  // kRepeats independent estimates (different case indices give independent seeds) with n and 2n
  // samples. Each estimate is a binomial proportion: variance p (1 - p) / n. The sample variance of
  // kRepeats estimates has relative standard error about sqrt(2 / (kRepeats - 1)) (4.5 %), so the
  // ratio of the two has about 6.3 %; 4 of those are allowed.
  constexpr int kRepeats = 1000;
  constexpr int kSamples = 8;
  constexpr double kRelativeTolerance = 4 * 0.063;
  const SuiteCase c = loneRollCase();
  double variance[2] = {0, 0}, pooled = 0;
  for (int doubled = 0; doubled < 2; ++doubled) {
    const int n = kSamples << doubled;
    std::vector<double> estimates;
    for (int r = 0; r < kRepeats; ++r) {
      estimates.push_back(
          sampleCase(c, ExecutionNoise{}, n, 5, static_cast<std::uint64_t>(r + doubled * kRepeats))
              .whole_case.probability);
    }
    double mean = 0;
    for (double e : estimates) mean += e;
    mean /= kRepeats;
    for (double e : estimates) variance[doubled] += (e - mean) * (e - mean);
    variance[doubled] /= kRepeats - 1;
    pooled += mean / 2;
  }
  ASSERT_GT(pooled, 0.2);  // the test means something only away from 0 and 1
  ASSERT_LT(pooled, 0.8);
  EXPECT_NEAR(variance[0] / variance[1], 2, 2 * kRelativeTolerance);
  const double binomial = pooled * (1 - pooled) / kSamples;
  EXPECT_NEAR(variance[0] / binomial, 1, kRelativeTolerance);
  EXPECT_NEAR(variance[1] / (binomial / 2), 1, kRelativeTolerance);
}

}  // namespace
}  // namespace baize::engine
