// Shot planning for positional play (docs/positional.md, "baize plan"): the cue speed, aim and tip
// offsets most likely, under execution error (engine/play/execution_noise.h), to pot one ball in
// one pocket and leave the cue ball on the table, in a region when one is given. The search counts
// every simulated shot against a budget; a blind grid of the same budget is here too, as the
// baseline the planner is compared with.
#pragma once

#include <cstdint>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "engine/io/scene.h"
#include "engine/play/execution_noise.h"
#include "engine/play/shot_outcome.h"
#include "engine/play/shot_suite.h"
#include "physics/cue_strike.h"

namespace baize::engine {

struct PlanGoal {
  std::string ball;  // the object ball to pot
  int pocket = 0;    // index into Table::pockets
  std::optional<CueBallRegion>
      region;  // where the cue ball must stop (none: anywhere on the table)
};

// The ranges searched (the elevation stays the scene's). Tip offsets in units of R, kept inside
// the miscue limit (0.5 R) with room for the execution error.
struct PlanRanges {
  double min_speed_mps = 0.5;  // slower cue balls barely reach a ball a table length away
  double max_speed_mps = 4.0;  // a hard break shot; positional play is slower
  double max_height = 0.4;     // |tip height|
  double max_side = 0.25;      // |tip side| (0.47 R with max_height at the corner)
};

struct PlanOptions {
  long budget_shots = 4000;  // simulated shots in all, noise-free and noisy
  ExecutionNoise noise;
  std::uint64_t seed = 1;
  int report = 3;  // shots reported
  PlanRanges ranges;
  std::function<void()> on_shot;  // called as each shot of the search starts (progress), if set
};

// Search constants (docs/positional.md states the method).
constexpr int kCoarseSpeeds = 8;   // coarse grid: cue speeds, evenly over the range
constexpr int kCoarseHeights = 9;  // tip heights, evenly over [-max, max]
constexpr int kCoarseSides = 3;    // tip sides: -max, 0, +max
// The refinement halves the coarse steps this many times around the best candidates so far.
constexpr int kRefinements = 3;
constexpr int kRefinedCentres = 4;  // candidates refined around in each refinement
constexpr int kRaced = 16;          // candidates that enter the noisy race
// Throw correction: the aim is corrected until the simulated object ball leaves within this angle
// of the line to the pocket's mouth centre (rad): 0.01 deg is 0.2 mm over a metre.
constexpr double kThrowTolerance_rad = 1.7e-4;
constexpr double kThrowProbe_rad = 1.7e-3;  // first secant step: 0.1 deg
constexpr int kMaxThrowIterations = 5;      // simulations per candidate for the aim at most
// The smallest budget: the noise-free stages stop at half the budget, and the coarse grid alone
// (kCoarseSpeeds x kCoarseHeights x kCoarseSides candidates at up to kMaxThrowIterations shots
// each: 1080) must fit in that half, or it would be cut off at the slow speeds it tries first.
constexpr long kMinPlanBudget = 2500;
static_assert(kMinPlanBudget / 2 >=
                  kCoarseSpeeds * kCoarseHeights * kCoarseSides * kMaxThrowIterations,
              "the coarse grid must fit in the noise-free half of the smallest budget");

struct PlannedShot {
  physics::CueShot shot;
  ProbabilityEstimate success;  // pot in the pocket, cue ball on the table (and in the region)
  double noise_free_score = 0;  // <= 1: the noise-free shot succeeds (0: the region's centre)
};

struct PlanResult {
  std::vector<PlannedShot> best;  // best first
  long shots_simulated = 0;
  int candidates = 0;  // noise-free candidates tried (the grid: points)
};

// The object ball's direction just after the cue ball first hits it, minus the direction wanted
// (rad, wrapped to [-pi, pi]); nothing when the cue ball hits another ball first or none.
std::optional<double> objectDirectionError(const SceneRun& run, const std::string& cue,
                                           const std::string& object, double wanted_rad);

// Whether a run's outcome meets the goal.
bool goalMet(const Scene& scene, const PlanGoal& goal, const ShotOutcome& outcome);

// Validates the goal against the scene: the ball exists and is not the cue ball, the pocket exists.
// Throws std::invalid_argument naming the value otherwise.
void validatePlanGoal(const Scene& scene, const PlanGoal& goal);

// The planner: ghost-ball aim at the pocket's mouth centre with the throw corrected by a secant
// search on the simulated object ball's direction; a noise-free coarse grid over speed x tip height
// x tip side, refined around the best candidates (half steps, kRefinements times); then successive
// halving of the noisy samples among the kRaced best. Deterministic for a seed. Throws
// std::invalid_argument for a bad goal, ranges or a budget below kMinPlanBudget.
PlanResult planShot(const Scene& scene, const PlanGoal& goal, const PlanOptions& options);

// The baseline: a blind grid over the same ranges and the aims that touch the object ball (every
// heading within asin(2R / d) of the line to its centre), each point sampled `samples_per_point`
// times with noise, the budget split evenly; the best points by their estimated probability.
PlanResult gridSearch(const Scene& scene, const PlanGoal& goal, const PlanOptions& options,
                      int samples_per_point);

// The probability of the goal for one shot from `samples` noisy samples, sample s seeded by
// sampleSeed(seed, stream, s).
ProbabilityEstimate estimateGoal(const Scene& scene, const PlanGoal& goal,
                                 const physics::CueShot& shot, const ExecutionNoise& noise,
                                 int samples, std::uint64_t seed, std::uint64_t stream);

}  // namespace baize::engine
