// Shot suites (docs/positional.md): cases of a scene and its shot with expectations about the
// outcome (balls pocketed or not, the first ball hit, the cue ball not pocketed, where it stops,
// cushions before the object ball, no foul), read strictly from JSON, run through the event loop
// and judged; optionally under execution error, with the probability of each expectation.
#pragma once

#include <Eigen/Core>
#include <cstdint>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "engine/io/scene.h"
#include "engine/play/execution_noise.h"
#include "engine/play/shot_outcome.h"

namespace baize::engine {

// Where the cue ball should stop.
struct CueBallRegion {
  enum class Kind { Circle, Rectangle, StraightShot };
  Kind kind = Kind::Circle;
  Eigen::Vector2d centre_m = Eigen::Vector2d::Zero();  // Circle
  double radius_m = 0;                                 // Circle
  Eigen::Vector2d min_m = Eigen::Vector2d::Zero();     // Rectangle: lower-left corner
  Eigen::Vector2d max_m = Eigen::Vector2d::Zero();     // Rectangle: upper-right corner
  std::string ball;                                    // StraightShot: the object ball
  int pocket = 0;                                      // StraightShot: index into Table::pockets
};

// A straight shot at `ball` into `pocket` from the cue ball's final position (docs/positional.md):
// the ghost-ball position G lies 2R behind the object ball on the line from the pocket's mouth
// centre through the ball; the cut (angle between the cue ball's path to G and the object ball's
// path to the mouth) is at most kMaxStraightShotCut_deg; and no other ball's centre comes within
// 2R + kStraightShotClearance_m of either path (cue ball C -> G, object ball -> mouth centre).
// Jaws and cushions are not checked.
constexpr double kMaxStraightShotCut_deg = 80;  // thinner cuts are not a playable position
// A path that clears another ball by less than this (m) is a kiss under the execution noise
// (0.125 deg of aim over a metre is about 2 mm).
constexpr double kStraightShotClearance_m = 0.001;

struct StraightShotCheck {
  bool clear = false;
  double cut_deg = 0;
  std::string reason;  // when not clear: what is in the way, or the cut
};

StraightShotCheck straightShot(const Table& table, double ball_radius_m, const ShotOutcome& outcome,
                               const std::string& ball, int pocket);

struct Expectation {
  enum class Kind {
    Pocketed,                     // every ball of `balls` pocketed
    NotPocketed,                  // no ball of `balls` pocketed
    FirstHit,                     // the cue ball first touches `ball`
    CueBallNotPocketed,           //
    CueBallStopsIn,               // the cue ball stops (on the table) in `region`
    MinCushionsBeforeObjectBall,  // at least `count` cushion or jaw contacts before the first hit
    NoFoul,                       // engine::Foul::None
  };
  Kind kind = Kind::NoFoul;
  std::vector<std::string> balls;
  std::string ball;
  int count = 0;  // MinCushionsBeforeObjectBall: 0 to kMaxCushionsExpected
  CueBallRegion region;
};
// The most cushions a suite may expect before the object ball: more is no position a player would
// ask for.
constexpr int kMaxCushionsExpected = 100;

// The suite-file key of an expectation ("pocketed", "cue_ball_stops_in", ...).
const char* expectationKey(Expectation::Kind kind);

struct SuiteCase {
  std::string name;
  Scene scene;
  std::vector<Expectation> expectations;  // in the order of their keys
};

struct Suite {
  std::string source;
  std::vector<SuiteCase> cases;
};

// Reads a suite (docs/positional.md). Throws std::invalid_argument naming the suite file, the case
// (by name, or by index before its name is known) and the key for an unknown key, a missing one, a
// wrong type, a duplicate case name, a ball or pocket the scene does not have, or a scene that does
// not load (the scene's own message follows). Scene paths are relative to the suite's folder.
Suite loadSuite(const std::string& path);
Suite suiteFromJson(const nlohmann::json& document, const std::string& source);

struct ExpectationResult {
  std::string key;       // expectationKey
  std::string expected;  // what was asked, as text
  std::string measured;  // what the shot did, as text
  bool met = false;
};

ExpectationResult evaluateExpectation(const Expectation& expectation, const ShotOutcome& outcome,
                                      const Scene& scene);

struct CaseResult {
  std::string name;
  bool passed = false;
  std::string error;  // the run failed (an impossible strike, too many events): the case fails
  std::vector<ExpectationResult> expectations;
};

// Runs the case's shot as written and judges every expectation.
CaseResult runCase(const SuiteCase& suite_case);

// A probability estimated from `successes` of `samples` with its 95 % Wilson score interval.
struct ProbabilityEstimate {
  int successes = 0;
  int samples = 0;
  double probability = 0;
  double low = 0, high = 0;
};
constexpr double kWilsonZ95 = 1.959963984540054;  // two-sided 95 % standard normal quantile
ProbabilityEstimate wilsonEstimate(int successes, int samples, double z = kWilsonZ95);

struct NoisyCaseResult {
  int samples = 0;
  int miscues = 0;      // samples whose tip offset passed the miscue limit: every expectation unmet
  int failed_runs = 0;  // samples whose simulation failed (event budget): every expectation unmet
  std::vector<ProbabilityEstimate> expectations;  // in the case's order
  ProbabilityEstimate whole_case;                 // every expectation met in the same sample
};

// Runs `samples` shots of the case, each with its own execution error drawn from
// sampleSeed(seed, case_index, sample), and counts how often each expectation and all of them
// together were met. The result depends only on the arguments.
NoisyCaseResult sampleCase(const SuiteCase& suite_case, const ExecutionNoise& noise, int samples,
                           std::uint64_t seed, std::uint64_t case_index);

}  // namespace baize::engine
