#include "tools/baize/bench_accuracy_command.h"

#include <CLI/CLI.hpp>
#include <algorithm>
#include <chrono>
#include <cmath>
#include <filesystem>
#include <functional>
#include <iomanip>
#include <iostream>
#include <memory>
#include <optional>
#include <random>
#include <set>
#include <sstream>

#include "engine/baselines/box2d_pool.h"
#include "engine/baselines/fixed_step_simulator.h"
#include "engine/io/scene.h"
#include "engine/play/random_shots.h"
#include "tools/baize/atomic_file.h"
#include "tools/baize/cli_errors.h"
#include "tools/baize/progress.h"
#include "tools/baize/median.h"

namespace baize::tools {
namespace {

// Timed runs of one shot in one configuration stop early once they have used this much wall time,
// s, so the slowest configurations (10 us steps) take one run per shot and the bench stays within
// a few minutes; the fast ones get the full --repeat.
constexpr double kRepeatBudget_s = 0.2;
// How many of the cue ball's first contacts (collapsed where the same contact repeats) make up the
// "event order" compared between engines: the first ball hit and what follows it.
constexpr std::size_t kComparedCueContacts = 3;
// Seeded random positional shots in the set.
constexpr int kRandomShots = 5;
constexpr std::uint64_t kRandomSeed = 20261121;
// The exact cushion solver's tolerances tried besides its default (3e-11), as in `baize bench
// cushion`: per impact they allow errors up to about 1e-9, 5e-7 and 1.5e-5 V0.
constexpr double kLooserCushionTolerances[] = {1e-10, 1e-8, 1e-6};

struct BenchAccuracyFlags {
  std::string csv_path;
  int shots = 0;          // 0: the whole set
  int repeats = 3;        // timed runs per shot and configuration, at most (median)
  bool per_shot = false;  // also print each shot's time, error and outcome per configuration
};

struct Shot {
  std::string name;
  engine::SimulationParams params;
  engine::TableGeometry table;
  std::vector<physics::BallState> balls;
  int cue = 0;               // index of the cue ball in balls
  bool frozen_rack = false;  // a break: racked balls touching up to engine::kFrozenGap_m
};

// The default tolerance of the exact solver in cushion model "exact" or "tabulated", as the
// model's registration sets it.
double defaultCushionTolerance(const std::string& model) {
  return engine::cushionModels().make(model, engine::ModelDefaults{})->parametersJson().value(
      "tolerance", 0.0);
}

// `cushion` ("exact" or "tabulated") as model `to`: a tolerance at its own model's default becomes
// the other's default, one the scene set is kept.
std::shared_ptr<const engine::CushionContactModel> cushionModelAs(
    const engine::CushionContactModel& cushion, const std::string& to) {
  nlohmann::json changes = {{"model", to}};
  if (cushion.parametersJson().value("tolerance", 0.0) == defaultCushionTolerance(cushion.name()))
    changes["tolerance"] = defaultCushionTolerance(to);
  return engine::cushionModels().changed(cushion, changes, "bench accuracy");
}

// The balls of a scene just after the cue strike, as engine::runScene sets them up.
Shot shotFromScene(const engine::Scene& scene, const std::string& name) {
  Shot shot;
  shot.name = name;
  shot.params = engine::simulationParamsFor(scene);
  // The reference and the tolerance rows solve every impact exactly; the "tabulated" row puts the
  // table back.
  if (std::string(shot.params.cushion->name()) == "tabulated")
    shot.params.cushion = cushionModelAs(*shot.params.cushion, "exact");
  shot.table = engine::geometryOf(scene.table);
  physics::CueStrikeParams cue;
  cue.ball_mass_kg = scene.ball_set.mass_kg;
  cue.ball_radius_m = scene.ball_set.radius_m;
  const physics::CueStrikeResult strike = physics::strikeCueBall(cue, scene.shot);
  for (const engine::PlacedBall& b : scene.balls) {
    physics::BallState state;
    state.position = b.position_m;
    if (b.id == scene.cue_ball) {
      shot.cue = static_cast<int>(shot.balls.size());
      state.velocity = strike.ball.v;
      state.angular_velocity = strike.ball.w;
    }
    shot.balls.push_back(state);
  }
  return shot;
}

// The set, cheapest first so that --shots N keeps the cheap ones: the shipped single-ball and
// positional scenes, the seeded random positional shots (cue ball and two object balls on the 9 ft
// table, 0.5-3 m/s, any tip offset up to 0.4 R), a long multi-cushion shot, then the breaks.
std::vector<Shot> shotSet() {
  std::vector<std::filesystem::path> files;
  for (const auto& f : std::filesystem::directory_iterator(engine::assetsDirectory() + "/scenes"))
    files.push_back(f.path());
  std::sort(files.begin(), files.end());
  std::vector<Shot> plain, breaks;
  for (const auto& f : files) {
    const std::string name = f.stem().string();
    Shot shot = shotFromScene(engine::loadScene(f.string()), name);
    shot.frozen_rack = name.find("break") != std::string::npos;
    (shot.frozen_rack ? breaks : plain).push_back(shot);
  }
  std::mt19937_64 random(kRandomSeed);
  auto uniform = [&](double lo, double hi) {
    return lo + (hi - lo) * static_cast<double>(random() >> 11) * 0x1.0p-53;
  };
  const engine::Scene base = engine::nineFootPoolScene();
  const double R = base.ball_set.radius_m;
  const double x = base.table.length_m / 2 - R, y = base.table.width_m / 2 - R;
  for (int made = 0; made < kRandomShots;) {
    engine::Scene s = base;
    s.balls = {{"cue", {uniform(-x, x), uniform(-y, y)}},
               {"1", {uniform(-x, x), uniform(-y, y)}},
               {"2", {uniform(-x, x), uniform(-y, y)}}};
    bool apart = true;
    for (std::size_t i = 0; i < s.balls.size(); ++i)
      for (std::size_t j = 0; j < i; ++j)
        apart = apart && (s.balls[i].position_m - s.balls[j].position_m).norm() > 2 * R;
    // Aim at the first object ball with a random cut, so that most shots hit something.
    const Eigen::Vector2d to_ball = s.balls[1].position_m - s.balls[0].position_m;
    s.shot.heading_rad = std::atan2(to_ball.y(), to_ball.x()) + uniform(-0.3, 0.3);
    s.shot.speed_mps = uniform(0.5, 3);
    const double offset = uniform(0, 0.4), angle = uniform(-M_PI, M_PI);
    s.shot.side_offset = offset * std::cos(angle);
    s.shot.height_offset = offset * std::sin(angle);
    if (!apart) continue;
    Shot shot = shotFromScene(s, "random-" + std::to_string(made + 1));
    try {  // the set keeps shots the reference runs (it fails on a few per cent of random shots)
      engine::simulate(shot.params, shot.table, shot.balls);
    } catch (const std::exception&) {
      continue;
    }
    plain.push_back(shot);
    ++made;
  }
  engine::Scene long_shot = base;  // fast, with follow and running side: many cushions
  long_shot.balls = {{"cue", {-0.9, -0.3}}};
  long_shot.shot.speed_mps = 4.5;
  long_shot.shot.heading_rad = 0.47;
  long_shot.shot.height_offset = 0.3;
  long_shot.shot.side_offset = -0.3;
  plain.push_back(shotFromScene(long_shot, "long-multi-cushion"));
  plain.insert(plain.end(), breaks.begin(), breaks.end());
  return plain;
}

// What a ball met, in order: each contact (another ball, a cushion, a jaw, a pocket) and when.
// State changes are left out: the baselines do not record them.
struct Contact {
  engine::EventKind kind;
  int with;  // the other ball, or the cushion, jaw or pocket
  double time_s;
};
std::vector<std::vector<Contact>> contactsByBall(const engine::SimulationResult& r) {
  std::vector<std::vector<Contact>> by_ball(r.final_balls.size());
  for (const engine::Event& e : r.events) {
    if (e.kind == engine::EventKind::StateChange) continue;
    const bool pair = e.kind == engine::EventKind::BallBall;
    by_ball[e.ball].push_back({e.kind, pair ? e.other : e.index, e.time_s});
    if (pair) by_ball[e.other].push_back({e.kind, e.ball, e.time_s});
  }
  return by_ball;
}

// What is compared between engines: the pocketed balls and the cue ball's first contacts.
struct Outcome {
  std::set<int> pocketed;
  std::vector<std::string> cue_contacts;
  bool operator==(const Outcome& o) const {
    return pocketed == o.pocketed && cue_contacts == o.cue_contacts;
  }
};

// What a run is compared by: every ball's contacts and the outcome, listed once per run.
struct RunSummary {
  std::vector<std::vector<Contact>> contacts;  // contactsByBall
  Outcome outcome;
};

RunSummary summarize(const engine::SimulationResult& r, int cue) {
  RunSummary summary{contactsByBall(r), {}};
  Outcome& o = summary.outcome;
  for (std::size_t i = 0; i < r.final_balls.size(); ++i)
    if (r.final_balls[i].pocketed) o.pocketed.insert(static_cast<int>(i));
  for (const Contact& c : summary.contacts[cue]) {
    if (o.cue_contacts.size() == kComparedCueContacts) break;
    const std::string token = c.kind == engine::EventKind::BallBall
                                  ? "ball " + std::to_string(c.with)
                                  : std::string(engine::eventKindName(c.kind)) + " " +
                                        std::to_string(c.with);
    if (o.cue_contacts.empty() || o.cue_contacts.back() != token) o.cue_contacts.push_back(token);
  }
  return summary;
}

using Simulator = std::function<engine::SimulationResult(const Shot&)>;

// An engine and its setting. The setting's model change is made once per shot, before the timed
// runs (`prepare`; none leaves the shot as it is): building a model from its parameters costs
// about as much as a short shot, and it is not part of simulating one.
struct Configuration {
  std::string engine, setting;
  Simulator run;
  std::function<engine::SimulationParams(const Shot&)> prepare = nullptr;
};

// Whether every ball meets the same things in the same order in both runs (the order between
// balls may differ: two balls' contacts a moment apart swap with a small shift), and if so the
// largest difference between the times of a contact, s; NaN when they differ.
double largestContactShift(const std::vector<std::vector<Contact>>& in_a,
                           const std::vector<std::vector<Contact>>& in_b) {
  if (in_a.size() != in_b.size()) return NAN;
  double shift = 0;
  for (std::size_t ball = 0; ball < in_a.size(); ++ball) {
    if (in_a[ball].size() != in_b[ball].size()) return NAN;
    for (std::size_t i = 0; i < in_a[ball].size(); ++i) {
      const Contact &x = in_a[ball][i], &y = in_b[ball][i];
      if (x.kind != y.kind || x.with != y.with) return NAN;
      shift = std::max(shift, std::abs(x.time_s - y.time_s));
    }
  }
  return shift;
}

// One configuration on one shot.
struct ShotScore {
  bool failed = false;  // the run threw: counted as a mismatch, left out of time and error
  double median_us = 0;
  double position_error_m = 0;  // largest final-position distance over balls on the table in both
  bool mismatch = false;
  double contact_shift_s = NAN;  // largestContactShift from the reference
};

struct Row {
  std::string engine, setting;
  double median_us = 0, position_error_m = 0, outcome_mismatch = 0;
  // The largest final-position error over the shots; the share of shots in which some ball's
  // contacts differ from the reference's (largestContactShift); over the others, the largest
  // shift of a contact's time (NaN when no shot keeps the reference's contacts).
  double largest_position_error_m = 0, contact_mismatch = 0, largest_contact_shift_s = NAN;
  int failures = 0;
};

// The row of one configuration over the shots that `include` accepts.
Row aggregate(const Configuration& config, const std::vector<ShotScore>& scores,
              const std::vector<Shot>& shots, const std::function<bool(const Shot&)>& include) {
  Row row{config.engine, config.setting};
  std::vector<double> times_us;
  double error_sum_m = 0;
  int counted = 0, mismatches = 0, contact_mismatches = 0;
  for (std::size_t k = 0; k < shots.size(); ++k) {
    if (!include(shots[k])) continue;
    ++counted;
    if (scores[k].failed) {
      ++row.failures;
      ++mismatches;
      ++contact_mismatches;
      continue;
    }
    times_us.push_back(scores[k].median_us);
    error_sum_m += scores[k].position_error_m;
    row.largest_position_error_m =
        std::max(row.largest_position_error_m, scores[k].position_error_m);
    if (scores[k].mismatch) ++mismatches;
    const double shift = scores[k].contact_shift_s;
    if (std::isnan(shift)) ++contact_mismatches;
    row.largest_contact_shift_s = std::fmax(row.largest_contact_shift_s, shift);  // NaN: the other
  }
  row.median_us = times_us.empty() ? NAN : median(times_us);
  row.position_error_m = times_us.empty() ? NAN : error_sum_m / times_us.size();
  if (times_us.empty()) row.largest_position_error_m = NAN;
  row.outcome_mismatch = counted > 0 ? static_cast<double>(mismatches) / counted : NAN;
  row.contact_mismatch = counted > 0 ? static_cast<double>(contact_mismatches) / counted : NAN;
  return row;
}

void printTable(const std::vector<Row>& rows) {
  std::cout << std::left << std::setw(12) << "engine" << std::setw(12) << "setting" << std::right
            << std::setw(12) << "median us" << std::setw(18) << "position error m"
            << std::setw(18) << "largest error m" << std::setw(18) << "outcome mismatch"
            << std::setw(18) << "contact mismatch" << std::setw(18) << "largest shift s"
            << std::setw(8) << "failed" << '\n';
  for (const Row& r : rows) {
    std::cout << std::left << std::setw(12) << r.engine << std::setw(12) << r.setting << std::right
              << std::setw(12) << std::setprecision(4) << r.median_us << std::setprecision(3)
              << std::setw(18) << r.position_error_m << std::setw(18)
              << r.largest_position_error_m << std::setw(18) << r.outcome_mismatch
              << std::setw(18) << r.contact_mismatch << std::setw(18) << r.largest_contact_shift_s
              << std::setw(8) << r.failures << '\n';
  }
}

std::vector<Configuration> configurations() {
  std::vector<Configuration> list;
  const Simulator simulateEvents = [](const Shot& s) {
    return engine::simulate(s.params, s.table, s.balls);
  };
  list.push_back({"event", "exact", simulateEvents});
  // The event loop with the Mathavan 2010 cushion model solved to looser tolerances (the setting
  // names them as `baize bench cushion` does): what accuracy of each impact buys in whole shots.
  for (const double tolerance : kLooserCushionTolerances) {
    std::ostringstream setting;
    setting << "tol=" << tolerance;
    list.push_back({"event", setting.str(), simulateEvents, [tolerance](const Shot& s) {
                      engine::SimulationParams params = s.params;
                      params.cushion = engine::cushionModels().changed(
                          *params.cushion, {{"tolerance", tolerance}}, "bench accuracy");
                      return params;
                    }});
  }
  // The default model: rolling balls' impacts from the table of exact solutions.
  list.push_back({"event", "tabulated", simulateEvents, [](const Shot& s) {
                    engine::SimulationParams params = s.params;
                    if (std::string(params.cushion->name()) == "exact")
                      params.cushion = cushionModelAs(*params.cushion, "tabulated");
                    return params;
                  }});
  const std::pair<double, const char*> fixed[] = {
      {1e-2, "dt=10ms"}, {1e-3, "dt=1ms"}, {1e-4, "dt=100us"}, {1e-5, "dt=10us"}};
  for (const auto& [dt, name] : fixed) {
    list.push_back({"fixed-step", name, [dt = dt](const Shot& s) {
                      return engine::simulateFixedStep(s.params, s.table, s.balls, dt);
                    }});
  }
  const std::pair<double, const char*> box2d[] = {
      {1.0 / 60, "dt=1/60s"}, {1.0 / 240, "dt=1/240s"}, {1e-3, "dt=1ms"}, {1e-4, "dt=100us"}};
  for (const auto& [dt, name] : box2d) {
    list.push_back({"box2d", name, [dt = dt](const Shot& s) {
                      engine::Box2dPoolSettings settings;
                      settings.time_step_s = dt;
                      return simulateBox2d(s.params, s.table, s.balls, settings);
                    }});
  }
  return list;
}

// The event loop's run of a shot, which every configuration is compared with.
struct Reference {
  engine::SimulationResult result;
  RunSummary summary;
};

// One configuration on one shot against the reference run: timed runs after an untimed one (the
// default path's table builds the cells a shot needs on its first impacts there).
ShotScore scoreShot(const Configuration& config, const Shot& original, const Reference& ref,
                    const BenchAccuracyFlags& flags) {
  const engine::SimulationResult& reference = ref.result;
  ShotScore score;
  std::vector<double> runs_us;
  std::optional<engine::SimulationResult> result;
  try {
    Shot shot = original;
    if (config.prepare) shot.params = config.prepare(shot);
    result = config.run(shot);
    double spent_s = 0;
    while (static_cast<int>(runs_us.size()) < flags.repeats && spent_s < kRepeatBudget_s) {
      const auto start = std::chrono::steady_clock::now();
      result = config.run(shot);
      const double s =
          std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
      runs_us.push_back(s * 1e6);
      spent_s += s;
    }
  } catch (const std::exception& failure) {
    std::cerr << "bench accuracy: " << config.engine << ' ' << config.setting << " on "
              << original.name << " failed: " << failure.what() << '\n';
    score.failed = true;
    return score;
  }
  score.median_us = median(runs_us);
  const RunSummary run = summarize(*result, original.cue);
  const Outcome &got = run.outcome, &want = ref.summary.outcome;
  score.mismatch = !(got == want);
  score.contact_shift_s = largestContactShift(run.contacts, ref.summary.contacts);
  for (std::size_t i = 0; i < reference.final_balls.size(); ++i) {
    if (reference.final_balls[i].pocketed || result->final_balls[i].pocketed) continue;
    score.position_error_m = std::max(
        score.position_error_m,
        (result->final_balls[i].state.position - reference.final_balls[i].state.position).norm());
  }
  if (flags.per_shot) {
    std::cout << config.engine << ' ' << config.setting << ' ' << original.name << ": "
              << std::setprecision(4) << score.median_us << " us, error " << score.position_error_m
              << " m, events " << result->events.size() << ", cue contacts";
    for (const std::string& token : got.cue_contacts) std::cout << " [" << token << ']';
    if (score.mismatch) {
      std::cout << " MISMATCH, reference";
      for (const std::string& token : want.cue_contacts) std::cout << " [" << token << ']';
    }
    std::cout << '\n';
  }
  return score;
}

void runBenchAccuracy(const BenchAccuracyFlags& flags) {
  if (flags.repeats < 1 || flags.repeats > kMaxBenchCount) {
    rejectFlag("--repeat", flags.repeats, kBenchCountAllowed);
  }
  if (flags.shots < 0) rejectFlag("--shots", flags.shots, "it must be >= 0 (0: all)");
  std::optional<AtomicFile> csv;
  if (!flags.csv_path.empty()) csv.emplace(flags.csv_path, "--csv");
  std::vector<Shot> shots = shotSet();
  if (flags.shots > 0 && flags.shots < static_cast<int>(shots.size())) shots.resize(flags.shots);

  std::vector<Reference> reference;
  for (const Shot& s : shots) {
    engine::SimulationResult result = engine::simulate(s.params, s.table, s.balls);
    RunSummary summary = summarize(result, s.cue);
    reference.push_back({std::move(result), std::move(summary)});
  }

  const std::vector<Configuration> configs = configurations();
  std::vector<std::vector<ShotScore>> scores(configs.size(), std::vector<ShotScore>(shots.size()));
  Progress progress("runs (configuration x shot)", static_cast<long>(configs.size() * shots.size()));
  // Shot by shot, every configuration in turn: the times of one shot are taken a few seconds
  // apart rather than the whole bench apart, so a change in the machine's speed during the bench
  // does not favour one configuration.
  for (std::size_t k = 0; k < shots.size(); ++k) {
    for (std::size_t c = 0; c < configs.size(); ++c, progress.advance())
      scores[c][k] = scoreShot(configs[c], shots[k], reference[k], flags);
  }
  std::vector<Row> rows, without_breaks;
  for (std::size_t c = 0; c < configs.size(); ++c) {
    rows.push_back(aggregate(configs[c], scores[c], shots, [](const Shot&) { return true; }));
    without_breaks.push_back(
        aggregate(configs[c], scores[c], shots, [](const Shot& s) { return !s.frozen_rack; }));
  }

  const auto racks =
      std::count_if(shots.begin(), shots.end(), [](const Shot& s) { return s.frozen_rack; });
  const bool both_sets = racks > 0 && racks < static_cast<long>(shots.size());
  // The column "shots" names the subset a row scores: "all", or "no-breaks" (the same without the
  // breaks, written when the set has breaks and other shots).
  std::ostringstream out;
  out << "engine,setting,median_us,position_error_m,outcome_mismatch,shots,"
         "largest_position_error_m,contact_mismatch,largest_contact_shift_s,failed\n";
  const auto write_rows = [&](const std::vector<Row>& subset, const char* name) {
    for (const Row& r : subset) {
      out << r.engine << ',' << r.setting << ',' << std::setprecision(6) << r.median_us << ','
          << r.position_error_m << ',' << r.outcome_mismatch << ',' << name << ','
          << r.largest_position_error_m << ',' << r.contact_mismatch << ','
          << r.largest_contact_shift_s << ',' << r.failures << '\n';
    }
  };
  write_rows(rows, "all");
  if (both_sets) write_rows(without_breaks, "no-breaks");
  std::cout << shots.size() << " shots (";
  for (std::size_t k = 0; k < shots.size(); ++k) std::cout << (k ? ", " : "") << shots[k].name;
  std::cout << ")\n\n";
  printTable(rows);
  std::cout << "\nmedian us: median over shots of each shot's median wall time; position error: "
               "mean over shots of the largest final-position distance from the event loop's "
               "(balls on the table in both), largest error: the largest over shots; outcome "
               "mismatch: share of shots whose pocketed balls or first "
            << kComparedCueContacts
            << " cue-ball contacts differ from the event loop's; contact mismatch: share of shots "
               "in which a ball meets other balls, cushions, jaws or pockets in another order "
               "than in the event loop; largest shift: over the others, the largest difference "
               "of a contact's time.\n";
  if (both_sets) {
    std::cout << "\nThe same without the " << racks
              << " breaks (frozen racks: their outcome hangs on 100 nm gaps between the racked "
                 "balls, which no fixed step resolves):\n\n";
    printTable(without_breaks);
  }
  if (csv) {
    csv->stream() << out.str();
    csv->commit();
    note(std::cout) << "wrote " << flags.csv_path << '\n';
  }
}

}  // namespace

void addBenchAccuracyCommand(CLI::App& parent) {
  auto flags = std::make_shared<BenchAccuracyFlags>();
  CLI::App* command = parent.add_subcommand(
      "accuracy",
      "Run time against error for whole shots: the event loop (its cushion impacts solved to the "
      "default and looser tolerances), a fixed-step integrator of the same physics and a Box2D "
      "baseline");
  command->add_option("--csv", flags->csv_path, "also write the table to this CSV file")
      ->check(notEmpty());
  command->add_option("--shots", flags->shots, "use only the first N shots of the set (0: all)")
      ->capture_default_str();
  command->add_option("--repeat", flags->repeats, "timed runs per shot and configuration, at most")
      ->capture_default_str();
  command->add_flag("--per-shot", flags->per_shot,
                    "also print each shot's time, error and cue-ball contacts per configuration");
  command->callback([flags] {
    if (const int status = runReportingErrors("bench accuracy", [&] { runBenchAccuracy(*flags); }))
      throw CLI::RuntimeError(status);
  });
}

}  // namespace baize::tools
