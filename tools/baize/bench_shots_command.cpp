#include "tools/baize/bench_shots_command.h"

#include <CLI/CLI.hpp>
#include <algorithm>
#include <chrono>
#include <cmath>
#include <filesystem>
#include <iomanip>
#include <iostream>
#include <memory>
#include <optional>
#include <sstream>

#include "engine/io/scene.h"
#include "engine/models/cushion_mathavan2010.h"
#include "engine/play/random_shots.h"
#include "engine/sim/cushion_impact_worker.h"
#include "physics/cushion_exact_solver.h"
#include "physics/cushion_rolling_surface.h"
#include "tools/baize/atomic_file.h"
#include "tools/baize/cli_errors.h"
#include "tools/baize/median.h"
#include "tools/baize/progress.h"

namespace baize::tools {
namespace {

struct BenchShotsFlags {
  std::string csv_path;
  int repeat = 21;          // timed runs per scene; the median is reported
  int random_shots = 1000;  // random single shots
  // Given: every shot's exact cushion solver at this tolerance instead of its scene's (run time
  // against the accuracy of each impact; `baize bench accuracy` gives the error it makes).
  std::optional<double> cushion_tolerance;
};

// Random shots run untimed before the timed pass (as each scene runs once untimed first).
constexpr std::size_t kWarmUpShots = 50;

// Cushion and jaw impacts in the runs with the worker, and how many it answered.
struct WorkerTally {
  long impacts = 0;
  long taken_ahead = 0;
};

// One run of `scene` (wall time in microseconds): on this thread alone (`worker` null), or with a
// worker solving cushion impacts ahead on a second core (engine/sim/cushion_impact_worker.h).
double timedRun(const engine::Scene& scene, engine::CushionImpactWorker* worker,
                std::size_t* events, WorkerTally* tally) {
  const long taken_before = worker ? worker->impactsTakenAhead() : 0;
  const auto start = std::chrono::steady_clock::now();
  const engine::SceneRun run = engine::runScene(scene, false, worker);
  const double us =
      std::chrono::duration<double, std::micro>(std::chrono::steady_clock::now() - start).count();
  *events = run.result.events.size();
  if (worker) {
    tally->taken_ahead += worker->impactsTakenAhead() - taken_before;
    for (const engine::Event& e : run.result.events)
      tally->impacts += e.kind == engine::EventKind::Cushion || e.kind == engine::EventKind::Jaw;
  }
  return us;
}

struct Timing {
  double one_core_us = 0;       // the shot on this thread alone
  double two_core_wall_us = 0;  // with the worker on a second core (NaN without one)
  std::size_t events = 0;
};

// Median wall times of simulating `scene` on one core and, given a worker, on two, run alternately
// (in alternating order, so that both see the same machine), and its event count.
Timing timeScene(const engine::Scene& scene, int repeat, engine::CushionImpactWorker* worker,
                 WorkerTally* tally) {
  std::vector<double> one, two;
  std::size_t events = 0;
  engine::runScene(scene);  // untimed warm-up: caches and the clock frequency settle first
  for (int i = 0; i < repeat; ++i) {
    for (const bool with_worker : {i % 2 != 0, i % 2 == 0}) {
      if (with_worker && !worker) continue;
      (with_worker ? two : one)
          .push_back(timedRun(scene, with_worker ? worker : nullptr, &events, tally));
    }
  }
  return {median(one), two.empty() ? NAN : median(two), events};
}

// The build so far of the rolling balls' table of the shots' cushion (random shots share one).
physics::RollingSurfaceStats rollingTableStats(const std::vector<engine::Scene>& shots) {
  if (shots.empty()) return {};
  return physics::rollingSurfaceFor(
             engine::impactParams(
                 engine::readMathavan2010(engine::modelDefaultsFor(shots[0]), nullptr),
                 engine::simulationParamsFor(shots[0])))
      .stats();
}

struct RandomShotsTiming {
  double one_core_us = 0;       // median per shot
  double two_core_wall_us = 0;  // median per shot with the worker (NaN without one)
  double events = 0;            // median per shot
  double one_core_total_s = 0;  // all the shots on one core
};

struct ShotPairTiming {
  RandomShotsTiming full, simple;
};

// Each shot once per pass, with the full model and with the simple rule side by side (in
// alternating order, so that both see the same machine: timed as two passes one after the other,
// their ratio moved by a quarter from run to run), one core first, then with the worker if there
// is one.
ShotPairTiming timeShotPairs(const std::vector<engine::Scene>& full_shots,
                             const std::vector<engine::Scene>& simple_shots,
                             engine::CushionImpactWorker* worker, WorkerTally* tally) {
  std::vector<double> one[2], two[2], events[2];
  RandomShotsTiming* timing[2];
  ShotPairTiming result;
  timing[0] = &result.full;
  timing[1] = &result.simple;
  const std::vector<engine::Scene>* shots[2] = {&full_shots, &simple_shots};
  const long passes = worker ? 2 : 1;
  Progress progress("random shots timed, full model and simple rule",
                    static_cast<long>(full_shots.size()) * passes);
  for (long pass = 0; pass < passes; ++pass) {
    engine::CushionImpactWorker* const second = pass == 0 ? nullptr : worker;
    for (std::size_t i = 0; i < full_shots.size(); ++i) {
      progress.advance();
      for (const int m : {static_cast<int>(i % 2), static_cast<int>(1 - i % 2)}) {
        std::size_t count = 0;
        const double us = timedRun((*shots[m])[i], second, &count, tally);
        if (second) {
          two[m].push_back(us);
          continue;
        }
        one[m].push_back(us);
        timing[m]->one_core_total_s += us * 1e-6;
        events[m].push_back(static_cast<double>(count));
      }
    }
  }
  for (int m = 0; m < 2; ++m) {
    timing[m]->one_core_us = median(one[m]);
    timing[m]->two_core_wall_us = two[m].empty() ? NAN : median(two[m]);
    timing[m]->events = median(events[m]);
  }
  return result;
}

void runBenchShots(const BenchShotsFlags& flags) {
  if (flags.repeat < 1 || flags.repeat > kMaxBenchCount) {
    rejectFlag("--repeat", flags.repeat, kBenchCountAllowed);
  }
  if (flags.random_shots < 1 || flags.random_shots > kMaxBenchCount) {
    rejectFlag("--random-shots", flags.random_shots, kBenchCountAllowed);
  }
  if (flags.cushion_tolerance) {
    physics::ExactSolverOptions options;
    options.tolerance = *flags.cushion_tolerance;
    try {
      physics::validateExactSolverOptions(options);
    } catch (const std::invalid_argument& refused) {
      throw UsageError(
          namingTheFlag(refused.what(), "exact solver tolerance", "--cushion-tolerance"));
    }
  }
  // The scenes and random shots, with the tolerance asked for.
  const auto withTolerance = [&](engine::Scene scene) {
    // The tolerance is the exact solver's: a scene on the exact solver ("exact", or "tabulated",
    // which then gives every impact to it) gets it; one that chose another model keeps it.
    if (flags.cushion_tolerance) {
      nlohmann::json& cushion = scene.overrides.cushion
                                    ? *scene.overrides.cushion
                                    : scene.overrides.cushion.emplace(nlohmann::json::object());
      const std::string model = cushion.value("model", engine::cushionModels().defaultName());
      if (model == "exact" || model == "tabulated") {
        cushion["model"] = "exact";
        cushion["tolerance"] = *flags.cushion_tolerance;
      }
    }
    return scene;
  };
  std::optional<AtomicFile> csv;
  if (!flags.csv_path.empty()) csv.emplace(flags.csv_path, "--csv");
  std::ostringstream table;
  // With a tolerance asked for, each row names it (the file then tells its runs apart).
  std::ostringstream tolerance_column;
  if (flags.cushion_tolerance) tolerance_column << ',' << *flags.cushion_tolerance;
  const std::string row_end = tolerance_column.str() + '\n';
  table << "scene,one_core_us,two_core_wall_us,events"
        << (flags.cushion_tolerance ? ",cushion_tolerance" : "") << '\n';
  std::vector<std::filesystem::path> files;
  for (const auto& f : std::filesystem::directory_iterator(engine::assetsDirectory() + "/scenes")) {
    files.push_back(f.path());
  }
  std::sort(files.begin(), files.end());
  // The second core is handed over only where one is there to take.
  std::optional<engine::CushionImpactWorker> worker;
  if (engine::CushionImpactWorker::secondCoreAvailable()) worker.emplace();
  engine::CushionImpactWorker* const second = worker ? &*worker : nullptr;
  WorkerTally tally;
  for (const auto& f : files) {
    const Timing t =
        timeScene(withTolerance(engine::loadScene(f.string())), flags.repeat, second, &tally);
    table << f.stem().string() << ',' << std::setprecision(4) << t.one_core_us << ','
          << t.two_core_wall_us << ',' << t.events << row_end;
  }
  std::vector<engine::Scene> shots = engine::randomSingleShots(flags.random_shots);
  std::transform(shots.begin(), shots.end(), shots.begin(), withTolerance);
  // Both sets name their cushion model, so that both read an override of the same form: reading
  // it is part of neither model's cost.
  for (engine::Scene& s : shots) {
    if (!s.overrides.cushion)
      s.overrides.cushion = nlohmann::json{{"model", engine::cushionModels().defaultName()}};
  }
  // The same shots with the simple restitution rule at every cushion: what the event loop costs
  // without the impact model, the yardstick of the full model's cost.
  std::vector<engine::Scene> simple_shots = shots;
  for (engine::Scene& s : simple_shots) s.overrides.cushion = nlohmann::json{{"model", "simple"}};
  for (std::size_t i = 0; i < std::min<std::size_t>(shots.size(), kWarmUpShots); ++i)
    engine::runScene(simple_shots[i]);  // untimed warm-up, as for the scenes
  // The full model's untimed pass runs every shot: it builds the cells of the rolling balls' table
  // (physics/cushion_rolling_surface.h) that the shots touch, a cost paid once per parameter set
  // and process, reported here beside the per-shot times it leaves out.
  const auto build_start = std::chrono::steady_clock::now();
  for (const engine::Scene& s : shots) engine::runScene(s);
  const double warm_up_s =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - build_start).count();
  const ShotPairTiming timed = timeShotPairs(shots, simple_shots, second, &tally);
  const RandomShotsTiming &full = timed.full, &simple = timed.simple;
  table << "random-single-shots," << std::setprecision(4) << full.one_core_us << ','
        << full.two_core_wall_us << ',' << full.events << row_end;
  table << "random-single-shots-simple," << std::setprecision(4) << simple.one_core_us << ','
        << simple.two_core_wall_us << ',' << simple.events << row_end;
  std::cout << table.str();
  std::cout << "random single shots: " << std::setprecision(4)
            << shots.size() / full.one_core_total_s << " shots/s on one core (" << shots.size()
            << " shots; median events as above)\n";
  std::cout
      << "random single shots with the full cushion model / with the simple rule at every cushion: "
      << std::setprecision(3) << full.one_core_us / simple.one_core_us
      << "x (one_core_us medians of the same shots in one run); of their total times: "
      << full.one_core_total_s / simple.one_core_total_s
      << "x (the shots whose impacts the table leaves to the exact solver weigh in)\n";
  const physics::RollingSurfaceStats built = rollingTableStats(shots);
  std::cout << "rolling balls' cushion table: " << built.cells_kept << " cells kept of "
            << built.cells_built << " built from " << built.exact_solves << " exact solutions in "
            << std::setprecision(3) << built.build_seconds
            << " s, once per process and parameter set (the untimed pass over the shots: "
            << warm_up_s << " s)\n";
  if (flags.cushion_tolerance) {
    std::cout << "cushion impacts solved to tolerance " << *flags.cushion_tolerance
              << " (the exact solver's default: " << physics::ExactSolverOptions{}.tolerance
              << ")\n";
  }
  if (second) {
    std::cout << "two cores: " << tally.taken_ahead << " of the " << tally.impacts
              << " cushion and jaw impacts of the runs with the worker were solved ahead\n";
  } else {
    std::cout << "two cores: not here (one core, or a CPU limit below two cores): "
                 "two_core_wall_us is nan\n";
  }
  if (csv) {
    csv->stream() << table.str();
    csv->commit();
    note(std::cout) << "wrote " << flags.csv_path << '\n';
  }
}

}  // namespace

void addBenchShotsCommand(CLI::App& parent) {
  auto flags = std::make_shared<BenchShotsFlags>();
  CLI::App* command = parent.add_subcommand(
      "shots", "Time whole shots: the shipped scenes and a seeded set of random single shots");
  command->add_option("--csv", flags->csv_path, "also write the table to this CSV file")
      ->check(notEmpty());
  command->add_option("--repeat", flags->repeat, "timed runs per scene (median)")
      ->capture_default_str();
  command->add_option("--random-shots", flags->random_shots, "random single shots")
      ->capture_default_str();
  command
      ->add_option("--cushion-tolerance", flags->cushion_tolerance,
                   "solve every cushion impact with the exact solver at this tolerance, in "
                   "[1e-14, 1e-6] (default: each scene's own)")
      ->check(notEmpty());
  command->callback([flags] {
    if (const int status = runReportingErrors("bench shots", [&] { runBenchShots(*flags); })) {
      throw CLI::RuntimeError(status);
    }
  });
}

}  // namespace baize::tools
