// Speed and accuracy of the cushion solvers over one fixed, seeded set of impacts, measured against
// a converged reference (the exact solver at kReferenceTolerance). Used by `baize bench cushion`.
//
// Error of one impact: max(|v - v_ref|_inf, R |w - w_ref|_inf) / V0, the largest error of any
// velocity component or of any spin component expressed as a surface speed, relative to the
// incoming speed. A setting's max_error is the largest over the set.
#pragma once

#include <cstdint>
#include <functional>
#include <optional>
#include <vector>

#include "physics/cushion_model.h"
#include "tools/baize/cushion_run.h"

namespace baize::tools {

constexpr std::uint64_t kBenchSeed = 20100521;  // fixed: every run measures the same impacts
constexpr int kDefaultBenchImpacts = 1000;
constexpr double kReferenceTolerance = 1e-14;       // the exact solver's, for the reference outputs
constexpr double kReferenceCheckTolerance = 1e-13;  // a second reference 10x looser, to check it

// The wide set: V0 uniform in [0.1, 2.5] m/s, alpha in [1, 179] deg, topspin k in [-2, 3] and
// sidespin k in [-3, 3] (units V0/R), drawn from std::mt19937_64 seeded with kBenchSeed through
// a fixed mapping of its 64-bit output (the same on every standard library).
std::vector<CushionShot> benchShots(int count);

// The rolling set, balls as they reach cushions in play (the shipped scenes' impacts are nearly
// all of this kind): V0 uniform in [0.1, 2.5] m/s, alpha in [1, 179] deg, topspin k exactly 1
// (natural roll: the cloth slip is zero when the impact starts) for every other shot and in
// [0.8, 1.05] for the rest, sidespin k in [-1.5, 1.5]; drawn as above from kRollingBenchSeed.
constexpr std::uint64_t kRollingBenchSeed = 20100522;
std::vector<CushionShot> rollingBenchShots(int count);

// The bench scores `count` shots of the wide set followed by rollingBenchCount(count) of the
// rolling set (max_error is over both) and times the wide set (median_ns is over it alone, so that
// it stays comparable with earlier runs and with the speed target).
int rollingBenchCount(int count);

// paper N = 100, 1000, 5000, 50000; exact at its default and at tolerances 1e-6 ... 1e-12.
std::vector<SolverSetting> benchSettings();

// The share of the promise whose count the bench reports besides the promise's own: how close to it
// the impacts come.
constexpr double kHalfPromiseShare = 0.5;

struct BenchRow {
  SolverSetting setting;
  double median_ns = 0;   // median over the wide set's impacts of the time per impact, ns
  double max_error = 0;   // as defined above, dimensionless
  double p999_error = 0;  // the 99.9th percentile of the impacts' errors
  int table_answers = 0;  // the tabulated path: impacts answered from the table
  // The impacts whose solution has a contact stick at some point, and their rate evaluations
  // (summed): the stretches around a stick cost the exact solver most.
  int stick_impacts = 0;
  double stick_evaluations = 0;
  // Over every impact scored: the rate evaluations (exact solver) or steps (paper scheme) per
  // impact, and how many impacts lie above half the promise and above it.
  double evaluations_per_impact = 0;
  int above_half_promise = 0;
  int above_promise = 0;
};

struct BenchReport {
  std::vector<BenchRow> rows;  // in the order of benchSettings()
  // Largest error (as above) of the reference against the kReferenceCheckTolerance solution.
  double reference_check_error = 0;
};

// An impact to score: the incoming ball (local cushion frame), its speed V0 (the scale of its
// error) and whether its time counts in median_ns.
struct BenchInput {
  physics::BallVelocity incoming;
  double speed_mps = 0;
  bool timed = true;
  std::optional<physics::CushionParams> params;  // its own cushion and cloth, else the bench's
  std::optional<CushionShot> shot;  // the shot it was made from, where `baize cushion` can run it
};

// The seeded sets: benchShots(count), timed, then rollingBenchShots(rollingBenchCount(count)).
std::vector<BenchInput> seededBenchInputs(double radius_m, int count);

// The spinning set, to check the exact solver's promise on spins the other sets never draw: V0
// uniform in [0.1, 2.5] m/s, alpha in [1, 179] deg, and the spin about each of the three axes
// uniform in [-kSpinningSpin_k, kSpinningSpin_k] V0/R on its own (so also spin about the line of
// travel), drawn as the sets above from std::mt19937_64 seeded with `seed`. None is timed.
constexpr double kSpinningSpin_k = 3;
std::vector<BenchInput> spinningBenchInputs(double radius_m, int count, std::uint64_t seed);

// The grippy set, contacts much grippier than real cushions and cloth: each impact has its own
// mu_s uniform in [kGrippyClothFrictionLow, kGrippyClothFrictionHigh) and mu_w in
// [0, kGrippyCushionFrictionHigh) (the rest is `params`), and a near-rolling ball: V0 in
// [0.1, 2.5] m/s, alpha in [1, 179] deg, topspin k in [0.8, 1.05], sidespin k in
// [-kGrippySidespin_k, kGrippySidespin_k]; drawn as above from `seed`. None is timed.
constexpr double kGrippyClothFrictionLow = 0.35, kGrippyClothFrictionHigh = 0.425;
constexpr double kGrippyCushionFrictionHigh = 0.4;
constexpr double kGrippyTopspinLow_k = 0.8, kGrippyTopspinHigh_k = 1.05;
constexpr double kGrippySidespin_k = 1.5;
std::vector<BenchInput> grippyBenchInputs(const physics::CushionParams& params, int count,
                                          std::uint64_t seed);
// Whether `params` allows every friction the grippy set draws: the cushion model's limits on mu_w
// and mu_s (physics::validateCushionParams) only tighten as either grows, so the largest pair
// stands for all. Throws std::invalid_argument with the model's refusal otherwise.
void validateGrippyCushion(const physics::CushionParams& params);

// The exact solver at its default tolerance, and the default path, over the inputs, scored against
// the reference (each input with its own cushion where it has one): what their promises are
// checked on.
struct PromiseReport {
  BenchRow row;                      // median_ns unset
  std::size_t worst = 0;             // the input with the largest error
  double reference_check_error = 0;  // as in BenchReport
  BenchRow tabulated;                // the default path on the same inputs (median_ns unset)
};
PromiseReport scorePromise(const physics::CushionParams& params,
                           const std::vector<BenchInput>& inputs);

// Times every setting over the inputs (none with its own cushion) (each impact's time is the least
// over `passes` timed batches) and scores it against the reference. Calls on_row after each setting
// (for progress output).
BenchReport runCushionBench(const physics::CushionParams& params,
                            const std::vector<BenchInput>& inputs, int passes,
                            const std::function<void(const BenchRow&)>& on_row = {});

}  // namespace baize::tools
