#include "tools/baize/cushion_bench.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstring>
#include <limits>
#include <random>
#include <stdexcept>

#include "tools/baize/median.h"

namespace baize::tools {
namespace {

using Clock = std::chrono::steady_clock;

// A timed batch lasts at least this long, ns: steady_clock ticks in 1 ns and a pair of reads costs
// a few tens of ns here, so the clock adds well under 1 % to a batch's time.
constexpr double kMinBatchNs = 20'000;
constexpr long kMaxBatch = 1'000'000;  // runs per batch, whatever the first run measured

constexpr double kRadiansPerDegree = M_PI / 180;

// Uniform in [lo, hi) from the top 53 bits of one draw: defined here rather than by
// std::uniform_real_distribution, whose algorithm differs between standard libraries.
double uniform(std::mt19937_64& generator, double lo, double hi) {
  const double unit = static_cast<double>(generator() >> 11) * 0x1.0p-53;  // [0, 1)
  return lo + (hi - lo) * unit;
}

double impactError(const physics::BallVelocity& ball, const physics::BallVelocity& reference,
                   double radius_m, double speed_mps) {
  const double velocity_error = (ball.v - reference.v).cwiseAbs().maxCoeff();
  const double spin_error = radius_m * (ball.w - reference.w).cwiseAbs().maxCoeff();
  return std::max(velocity_error, spin_error) / speed_mps;
}

bool sameBits(double a, double b) { return std::memcmp(&a, &b, sizeof a) == 0; }

double elapsedNs(Clock::time_point start, Clock::time_point end) {
  return std::chrono::duration<double, std::nano>(end - start).count();
}

// The percentile of the impacts' errors each row reports besides the largest.
constexpr double kReportedPercentile = 99.9;

// The p-th percentile of `values` (nearest rank; NaN sorts last); 0 for none.
double percentile(std::vector<double> values, double p) {
  if (values.empty()) return 0;
  std::sort(values.begin(), values.end(), [](double a, double b) {
    return std::isnan(b) ? !std::isnan(a) : (!std::isnan(a) && a < b);
  });
  const std::size_t rank = static_cast<std::size_t>(std::ceil(p / 100 * values.size()));
  return values[std::min(values.size(), std::max<std::size_t>(rank, 1)) - 1];
}

// Outgoing states are summed into this, so that no solver call could be dropped as unused.
volatile double g_checksum = 0;

struct BenchImpact {
  double speed_mps;
  physics::BallVelocity incoming;
  physics::BallVelocity reference;  // outgoing state at kReferenceTolerance
  bool timed;                       // of the wide set: median_ns is taken over these
};

// Adds one scored impact to the row's error, evaluation, stick and promise tallies (evaluations:
// the exact solver's rate evaluations, the paper scheme's steps).
// A NaN error counts as above the promise and becomes the largest (and stays so).
void tally(const physics::CushionImpactResult& result, double error, BenchRow* row) {
  if (!std::isnan(row->max_error) && !(error <= row->max_error)) row->max_error = error;
  row->evaluations_per_impact += static_cast<double>(result.rhs_evaluations);
  const bool sticks = std::any_of(
      result.contact_changes.begin(), result.contact_changes.end(),
      [](const physics::ContactChange& c) { return c.mode == physics::ContactMode::Stick; });
  if (sticks) {
    ++row->stick_impacts;
    row->stick_evaluations += static_cast<double>(result.rhs_evaluations);
  }
  row->above_half_promise += !(error <= kHalfPromiseShare * physics::kExactPromise);
  row->above_promise += !(error <= physics::kExactPromise);
}

// The reference outgoing state of an input, and how far the looser check solution lies from it.
physics::BallVelocity referenceOf(const physics::CushionParams& params, const BenchInput& input,
                                  double* check_error) {
  SolverSetting reference_setting;
  reference_setting.exact_tolerance = kReferenceTolerance;
  SolverSetting check_setting;
  check_setting.exact_tolerance = kReferenceCheckTolerance;
  const physics::BallVelocity reference =
      solveCushionShot(params, input.incoming, reference_setting).after;
  const physics::BallVelocity check = solveCushionShot(params, input.incoming, check_setting).after;
  *check_error =
      std::max(*check_error, impactError(check, reference, params.radius_m, input.speed_mps));
  return reference;
}

BenchRow measure(const physics::CushionParams& params, const std::vector<BenchImpact>& impacts,
                 const SolverSetting& setting, int passes) {
  BenchRow row;
  row.setting = setting;
  std::vector<long> batch(impacts.size());
  std::vector<double> best_ns(impacts.size(), std::numeric_limits<double>::infinity());
  // A first, untimed-for-the-table run gives the output to score and the batch size.
  std::vector<double> errors;
  for (std::size_t i = 0; i < impacts.size(); ++i) {
    const Clock::time_point start = Clock::now();
    const physics::CushionImpactResult result =
        solveCushionShot(params, impacts[i].incoming, setting);
    const double once_ns = std::max(1.0, elapsedNs(start, Clock::now()));
    errors.push_back(
        impactError(result.after, impacts[i].reference, params.radius_m, impacts[i].speed_mps));
    tally(result, errors.back(), &row);
    // The table's answers carry no impulses (the exact solver's always do: P_f > 0).
    row.table_answers += setting.kind == SolverKind::Tabulated && result.final_impulse_Ns == 0;
    batch[i] = std::min(kMaxBatch, static_cast<long>(std::ceil(kMinBatchNs / once_ns)));
  }
  row.p999_error = percentile(errors, kReportedPercentile);
  row.evaluations_per_impact /= static_cast<double>(std::max<std::size_t>(1, impacts.size()));
  for (int pass = 0; pass < passes; ++pass) {
    for (std::size_t i = 0; i < impacts.size(); ++i) {
      if (!impacts[i].timed) continue;
      double checksum = 0;
      const Clock::time_point start = Clock::now();
      for (long run = 0; run < batch[i]; ++run) {
        checksum += solveCushionShot(params, impacts[i].incoming, setting).after.v.x();
      }
      best_ns[i] = std::min(best_ns[i], elapsedNs(start, Clock::now()) / batch[i]);
      g_checksum = g_checksum + checksum;
    }
  }
  std::vector<double> timed_ns;
  for (std::size_t i = 0; i < impacts.size(); ++i) {
    if (impacts[i].timed) timed_ns.push_back(best_ns[i]);
  }
  row.median_ns = median(timed_ns);
  return row;
}

}  // namespace

std::vector<CushionShot> benchShots(int count) {
  std::mt19937_64 generator(kBenchSeed);
  std::vector<CushionShot> shots(count);
  for (CushionShot& shot : shots) {
    shot.speed_mps = uniform(generator, 0.1, 2.5);
    shot.angle_deg = uniform(generator, 1, 179);
    shot.topspin_k = uniform(generator, -2, 3);
    shot.sidespin_k = uniform(generator, -3, 3);
  }
  return shots;
}

std::vector<CushionShot> rollingBenchShots(int count) {
  std::mt19937_64 generator(kRollingBenchSeed);
  std::vector<CushionShot> shots(count);
  for (int i = 0; i < count; ++i) {
    CushionShot& shot = shots[i];
    shot.speed_mps = uniform(generator, 0.1, 2.5);
    shot.angle_deg = uniform(generator, 1, 179);
    const double near_roll = uniform(generator, 0.8, 1.05);  // drawn always: same stream for all
    shot.topspin_k = i % 2 == 0 ? 1.0 : near_roll;
    shot.sidespin_k = uniform(generator, -1.5, 1.5);
  }
  return shots;
}

int rollingBenchCount(int count) { return (count + 1) / 2; }

std::vector<SolverSetting> benchSettings() {
  std::vector<SolverSetting> settings;
  for (int steps : {100, 1000, 5000, 50000}) {
    SolverSetting paper;
    paper.kind = SolverKind::Paper;
    paper.paper_steps = steps;
    settings.push_back(paper);
  }
  settings.push_back(SolverSetting{});     // the exact solver at its default tolerance
  settings.push_back(tabulatedDefault());  // the default path: rolling balls from the table
  for (double tolerance : {1e-6, 1e-8, 1e-10, 1e-12}) {
    SolverSetting exact;
    exact.exact_tolerance = tolerance;
    settings.push_back(exact);
  }
  return settings;
}

std::vector<BenchInput> seededBenchInputs(double radius_m, int count) {
  std::vector<CushionShot> shots = benchShots(count);
  const std::vector<CushionShot> rolling = rollingBenchShots(rollingBenchCount(count));
  shots.insert(shots.end(), rolling.begin(), rolling.end());
  std::vector<BenchInput> inputs;
  for (std::size_t i = 0; i < shots.size(); ++i) {
    const bool timed = i < static_cast<std::size_t>(count);
    inputs.push_back(
        {incomingBallOf(shots[i], radius_m), shots[i].speed_mps, timed, std::nullopt, shots[i]});
  }
  return inputs;
}

std::vector<BenchInput> spinningBenchInputs(double radius_m, int count, std::uint64_t seed) {
  std::mt19937_64 generator(seed);
  std::vector<BenchInput> inputs;
  for (int i = 0; i < count; ++i) {
    BenchInput input;
    input.speed_mps = uniform(generator, 0.1, 2.5);
    const double alpha_rad = uniform(generator, 1, 179) * kRadiansPerDegree;
    input.incoming = physics::incomingBall(input.speed_mps, alpha_rad, 0, 0);
    const double spin_unit = input.speed_mps / radius_m;  // V0 / R, rad/s
    for (int axis = 0; axis < 3; ++axis) {
      input.incoming.w[axis] = uniform(generator, -kSpinningSpin_k, kSpinningSpin_k) * spin_unit;
    }
    input.timed = false;
    inputs.push_back(input);
  }
  return inputs;
}

std::vector<BenchInput> grippyBenchInputs(const physics::CushionParams& params, int count,
                                          std::uint64_t seed) {
  std::mt19937_64 generator(seed);
  std::vector<BenchInput> inputs;
  for (int i = 0; i < count; ++i) {
    physics::CushionParams grippy = params;
    grippy.cloth_friction = uniform(generator, kGrippyClothFrictionLow, kGrippyClothFrictionHigh);
    grippy.cushion_friction = uniform(generator, 0, kGrippyCushionFrictionHigh);
    CushionShot shot;
    shot.speed_mps = uniform(generator, 0.1, 2.5);
    shot.angle_deg = uniform(generator, 1, 179);
    shot.topspin_k = uniform(generator, kGrippyTopspinLow_k, kGrippyTopspinHigh_k);
    shot.sidespin_k = uniform(generator, -kGrippySidespin_k, kGrippySidespin_k);
    BenchInput input;
    input.incoming = incomingBallOf(shot, params.radius_m);
    input.speed_mps = shot.speed_mps;
    input.timed = false;
    input.params = grippy;
    input.shot = shot;
    inputs.push_back(input);
  }
  return inputs;
}

void validateGrippyCushion(const physics::CushionParams& params) {
  physics::CushionParams grippiest = params;
  grippiest.cloth_friction = kGrippyClothFrictionHigh;
  grippiest.cushion_friction = kGrippyCushionFrictionHigh;
  physics::validateCushionParams(grippiest);
}

PromiseReport scorePromise(const physics::CushionParams& params,
                           const std::vector<BenchInput>& inputs) {
  PromiseReport report;
  const SolverSetting exact_default;
  const SolverSetting tabulated = tabulatedDefault();
  report.tabulated.setting = tabulated;
  std::vector<double> tabulated_errors;
  for (std::size_t i = 0; i < inputs.size(); ++i) {
    const physics::CushionParams& own = inputs[i].params ? *inputs[i].params : params;
    const physics::BallVelocity reference =
        referenceOf(own, inputs[i], &report.reference_check_error);
    const physics::CushionImpactResult result =
        solveCushionShot(own, inputs[i].incoming, exact_default);
    const double error = impactError(result.after, reference, own.radius_m, inputs[i].speed_mps);
    const double largest_before = report.row.max_error;
    tally(result, error, &report.row);
    if (!sameBits(report.row.max_error, largest_before)) report.worst = i;
    const physics::CushionImpactResult path = solveCushionShot(own, inputs[i].incoming, tabulated);
    tabulated_errors.push_back(
        impactError(path.after, reference, own.radius_m, inputs[i].speed_mps));
    tally(path, tabulated_errors.back(), &report.tabulated);
    report.tabulated.table_answers += path.final_impulse_Ns == 0;
  }
  report.tabulated.p999_error = percentile(tabulated_errors, kReportedPercentile);
  for (BenchRow* row : {&report.row, &report.tabulated})
    row->evaluations_per_impact /= static_cast<double>(std::max<std::size_t>(1, inputs.size()));
  return report;
}

BenchReport runCushionBench(const physics::CushionParams& params,
                            const std::vector<BenchInput>& inputs, int passes,
                            const std::function<void(const BenchRow&)>& on_row) {
  BenchReport report;
  std::vector<BenchImpact> impacts;
  for (const BenchInput& input : inputs) {
    if (input.params) throw std::logic_error("runCushionBench: an input with its own cushion");
    const physics::BallVelocity reference =
        referenceOf(params, input, &report.reference_check_error);
    impacts.push_back({input.speed_mps, input.incoming, reference, input.timed});
  }
  for (const SolverSetting& setting : benchSettings()) {
    report.rows.push_back(measure(params, impacts, setting, passes));
    if (on_row) on_row(report.rows.back());
  }
  return report;
}

}  // namespace baize::tools
