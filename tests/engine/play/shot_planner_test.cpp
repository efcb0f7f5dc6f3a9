#include "engine/play/shot_planner.h"

#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "tests/engine/error_test_support.h"

namespace baize::engine {
namespace {

constexpr double kPoolRadius_m = 0.028575;
constexpr int kTopRight = 3;  // Table::pockets index
// The stop-shot drill's layout (assets/suites/positional-drills.json, "follow"): the cue ball and
// ball 1 on the top-right corner's 45 deg axis, 0.557 m apart.
const Eigen::Vector2d kCue_m(0.1689, -0.4661);
const Eigen::Vector2d kObject_m(0.5629, -0.0721);
// A stop shot leaves the cue ball where it met the object ball (physics-notes 3: it keeps
// (1 - e)/2 = 2.5 % of its speed, a few mm of roll): the ghost-ball position, 2R short of ball 1.
// The region is a 5 cm circle there.
constexpr double kStopRegionRadius_m = 0.05;
// The shipped stop-shot drill (a hand-made stun, 3 cm circle) meets its case with p = 0.925 under
// the default noise (docs/positional.md); a planner must find a stun at least this good in a 5 cm
// circle.
constexpr double kMinStopProbability = 0.8;
constexpr int kFreshSamples = 400;  // re-estimates: a Wilson half-width of about 0.04 at p = 0.8
// The planner's aim is the ghost ball's with the throw corrected to 0.01 deg; on a straight-in shot
// with little side the throw is tiny, so the aim stays this close to the line, deg.
constexpr double kStraightAimTolerance_deg = 0.2;
constexpr long kBudget_shots = 4000;  // the CLI's default

Scene straightInScene() {
  return sceneFromJson(nlohmann::json::parse(R"({"table": "pool-9ft", "ball_set": "pool",
      "balls": {"cue": [0.1689, -0.4661], "1": [0.5629, -0.0721], "2": [-0.8, 0.3]},
      "shot": {"aim_at": "1", "speed_mps": 1.0}})"),
                       "straight-in.json");
}

PlanGoal stopGoal() {
  CueBallRegion region;
  region.kind = CueBallRegion::Kind::Circle;
  const Eigen::Vector2d u = Eigen::Vector2d(1, 1).normalized();  // towards the top-right corner
  region.centre_m = kObject_m - 2 * kPoolRadius_m * u;
  region.radius_m = kStopRegionRadius_m;
  return PlanGoal{"1", kTopRight, region};
}

TEST(ShotPlanner, FindsAStunShotThatStopsTheCueBallWhereItMetTheObjectBall) {
  const Scene scene = straightInScene();
  PlanOptions options;
  options.budget_shots = kBudget_shots;
  const PlanResult result = planShot(scene, stopGoal(), options);
  ASSERT_FALSE(result.best.empty());
  EXPECT_LE(result.shots_simulated, kBudget_shots);
  const PlannedShot& best = result.best.front();
  // A stop shot is struck below the centre (draw that wears off just as the balls meet).
  EXPECT_LT(best.shot.height_offset, 0);
  // Aimed at the ghost ball: on the straight line, so within a small fraction of a degree of it.
  EXPECT_NEAR(best.shot.heading_rad, M_PI / 4, kStraightAimTolerance_deg * M_PI / 180);
  const ProbabilityEstimate fresh = estimateGoal(scene, stopGoal(), best.shot, options.noise,
                                                 kFreshSamples, options.seed, 1ull << 41);
  EXPECT_GT(fresh.probability, kMinStopProbability)
      << "p " << fresh.probability << " [" << fresh.low << ", " << fresh.high << "]";
}

TEST(ShotPlanner, BeatsABlindGridOfTheSameBudget) {
  const Scene scene = straightInScene();
  PlanOptions options;
  options.budget_shots = kBudget_shots;
  const PlanResult planned = planShot(scene, stopGoal(), options);
  ASSERT_FALSE(planned.best.empty());
  const ProbabilityEstimate p = estimateGoal(scene, stopGoal(), planned.best[0].shot, options.noise,
                                             kFreshSamples, options.seed, 1ull << 41);
  // One sample per point (the densest grid: 7 speeds, heights and sides x 11 aims, the straight
  // aim among them) and ten (4 x 4 x 4 x 6).
  for (int samples_per_point : {1, 10}) {
    const PlanResult grid = gridSearch(scene, stopGoal(), options, samples_per_point);
    EXPECT_LE(grid.shots_simulated, kBudget_shots);
    ASSERT_FALSE(grid.best.empty());
    const ProbabilityEstimate g = estimateGoal(scene, stopGoal(), grid.best[0].shot, options.noise,
                                               kFreshSamples, options.seed, 1ull << 41);
    // Clearly better: the intervals do not overlap.
    EXPECT_GT(p.low, g.high) << samples_per_point << " per point: planner " << p.probability
                             << ", grid " << g.probability;
  }
}

TEST(ShotPlanner, SameSeedSameShots) {
  const Scene scene = straightInScene();
  PlanOptions options;
  options.budget_shots = kMinPlanBudget;
  options.seed = 7;
  const PlanResult a = planShot(scene, stopGoal(), options);
  const PlanResult b = planShot(scene, stopGoal(), options);
  ASSERT_EQ(a.best.size(), b.best.size());
  for (std::size_t i = 0; i < a.best.size(); ++i) {
    EXPECT_EQ(a.best[i].shot.speed_mps, b.best[i].shot.speed_mps);
    EXPECT_EQ(a.best[i].shot.heading_rad, b.best[i].shot.heading_rad);
    EXPECT_EQ(a.best[i].shot.height_offset, b.best[i].shot.height_offset);
    EXPECT_EQ(a.best[i].success.successes, b.best[i].success.successes);
  }
}

TEST(ShotPlanner, GoalNeedsThePotInThatPocketAndTheCueBallInTheRegion) {
  const Scene scene = straightInScene();
  ShotOutcome o;
  o.cue_ball = "cue";
  o.pocketed = {{"1", kTopRight}};
  o.cue_ball_final_m = stopGoal().region->centre_m;
  o.final_balls = {{"cue", o.cue_ball_final_m, false}, {"1", kObject_m, true}};
  EXPECT_TRUE(goalMet(scene, stopGoal(), o));
  ShotOutcome elsewhere = o;
  elsewhere.cue_ball_final_m += Eigen::Vector2d(kStopRegionRadius_m * 1.01, 0);
  elsewhere.final_balls[0].position_m = elsewhere.cue_ball_final_m;
  EXPECT_FALSE(goalMet(scene, stopGoal(), elsewhere));
  ShotOutcome other_pocket = o;
  other_pocket.pocketed = {{"1", 0}};
  EXPECT_FALSE(goalMet(scene, stopGoal(), other_pocket));
  ShotOutcome scratch = o;
  scratch.pocketed.push_back({"cue", kTopRight});
  scratch.cue_ball_pocketed = true;
  EXPECT_FALSE(goalMet(scene, stopGoal(), scratch));
}

TEST(ShotPlanner, RefusesBadGoalsAndBudgets) {
  const Scene scene = straightInScene();
  PlanGoal goal = stopGoal();
  goal.ball = "cue";
  EXPECT_NE(invalidArgumentMessage([&] { planShot(scene, goal, {}); }).find("ball cue"),
            std::string::npos);
  goal = stopGoal();
  goal.pocket = 6;
  EXPECT_NE(invalidArgumentMessage([&] { planShot(scene, goal, {}); }).find("pocket 6"),
            std::string::npos);
  PlanOptions options;
  options.budget_shots = kMinPlanBudget - 1;
  EXPECT_NE(invalidArgumentMessage([&] { planShot(scene, stopGoal(), options); }).find("budget"),
            std::string::npos);
}

}  // namespace
}  // namespace baize::engine
