#include "tools/baize/stress_command.h"

#include <CLI/CLI.hpp>
#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <filesystem>
#include <iostream>
#include <map>
#include <memory>
#include <mutex>
#include <nlohmann/json.hpp>
#include <sstream>
#include <stdexcept>
#include <string>
#include <thread>
#include <vector>

#include "engine/io/json_reader.h"
#include "engine/io/scene.h"
#include "engine/play/stress_checks.h"
#include "engine/play/stress_shots.h"
#include "physics/cue_strike.h"
#include "tools/baize/atomic_file.h"
#include "tools/baize/cli_errors.h"
#include "tools/baize/output_folder.h"
#include "tools/baize/progress.h"
#include "tools/baize/thread_flag.h"

namespace baize::tools {
namespace {

using physics::BallState;

// How many failing shots are printed in full (all of them are written with --failures).
constexpr int kMaxReportedShots = 10;
// The "format" of a state file (a failing shot that no scene can express).
constexpr const char* kStateFormat = "baize stress state";

struct StressFlags {
  long shots = 100000;
  std::uint64_t seed = 1;
  int max_balls = 6;
  int threads = 0;         // --threads: 0 for the hardware concurrency
  double max_seconds = 0;  // 0: no budget
  long max_events = engine::SimulationParams{}.max_events;
  std::string failures_dir;
  std::string replay_path;
};

struct FailedShot {
  long shot = 0;
  engine::StressShot made;
  engine::ShotCheck check;
};

// What a run of shots adds up to; sums and maxima, so the same whatever the threads did when.
struct Tally {
  long shots = 0;
  long events = 0;
  long pocketed = 0;
  double worst_energy_growth = 0;
  std::map<std::string, long> failures_by_kind;  // kind -> shots failing that way
  std::map<std::string, long> shots_by_kind;     // shot kind -> shots
  std::vector<FailedShot> failed;
  std::string error;  // what a thread's shot threw outside the checks, if anything

  void add(const Tally& other) {
    shots += other.shots;
    events += other.events;
    pocketed += other.pocketed;
    worst_energy_growth = std::max(worst_energy_growth, other.worst_energy_growth);
    for (const auto& [kind, count] : other.failures_by_kind) failures_by_kind[kind] += count;
    for (const auto& [kind, count] : other.shots_by_kind) shots_by_kind[kind] += count;
    failed.insert(failed.end(), other.failed.begin(), other.failed.end());
  }
};

nlohmann::json ballsJson(const std::vector<BallState>& balls) {
  nlohmann::json list = nlohmann::json::array();
  for (const BallState& b : balls) {
    list.push_back({{"position", {b.position.x(), b.position.y()}},
                    {"velocity", {b.velocity.x(), b.velocity.y(), b.velocity.z()}},
                    {"angular_velocity",
                     {b.angular_velocity.x(), b.angular_velocity.y(), b.angular_velocity.z()}}});
  }
  return list;
}

// The file that makes a failing shot again: a scene for a cue shot (`baize simulate` runs it,
// `baize stress --replay` checks it), else the balls' states (`baize stress --replay`). Numbers
// are written with enough digits to read back bit for bit.
nlohmann::json reproductionJson(const FailedShot& f, const StressFlags& flags) {
  if (f.made.scene) return engine::sceneFileJson(f.made, flags.max_events);
  return {{"format", kStateFormat},
          {"seed", flags.seed},
          {"shot", f.shot},
          {"kind", engine::stressShotKindName(f.made.kind)},
          {"table", engine::makeStressTable(f.made.table).name},
          {"max_events", flags.max_events},
          {"first_failure", f.check.first_message},
          {"balls", ballsJson(f.made.balls)}};
}

// Every reproduction file's name: seed<S>-shot<N>.scene.json or .state.json.
const OutputFileNames kReproductionNames{"seed", ".json"};

std::string reproductionFileName(const FailedShot& f, const StressFlags& flags) {
  return "seed" + std::to_string(flags.seed) + "-shot" + std::to_string(f.shot) +
         (f.made.scene ? ".scene.json" : ".state.json");
}

// A replay: the shot a reproduction file holds, on its table with its physics.
struct Replay {
  engine::StressTable table;
  engine::SimulationParams params;
  std::vector<BallState> balls;
};

// Three finite numbers [x, y, z] under `key`.
Eigen::Vector3d vector3(const engine::JsonReader& object, const std::string& key) {
  const std::vector<double> numbers = object.finiteNumbers(key, 3);
  return {numbers[0], numbers[1], numbers[2]};
}

Replay loadReplay(const std::string& path) {
  const nlohmann::json document = engine::JsonReader::parseFile(path);
  Replay replay;
  if (document.is_object() && document.contains("shot") && !document.contains("format")) {
    const engine::Scene scene = engine::loadScene(path);
    replay.table = stressTableOfScene(scene);
    replay.params = replay.table.params;
    replay.balls = engine::sceneStart(scene).balls;
    return replay;
  }
  const engine::JsonReader state(document, path);
  state.requireKeys({"format", "table", "max_events", "balls"},
                    {"seed", "shot", "kind", "first_failure"});
  if (state.text("format") != kStateFormat) {
    state.reject("format", std::string("\"") + kStateFormat + "\" (or a scene file)");
  }
  try {
    replay.table = engine::makeStressTable(engine::stressTableIdByName(state.text("table")));
  } catch (const std::invalid_argument& e) {
    state.reject("table", e.what());
  }
  replay.params = replay.table.params;
  replay.params.max_events = state.integer("max_events", 1, 2147483647);
  // The keys written for information only must still be what the program writes.
  if (state.has("seed") && !(document["seed"].is_number_unsigned())) {
    state.reject("seed", "it must be a whole number >= 0");
  }
  if (state.has("shot") && !(document["shot"].is_number_unsigned())) {
    state.reject("shot", "it must be a whole number >= 0");
  }
  if (state.has("kind") && !engine::isStressShotKindName(state.text("kind"))) {
    state.reject("kind", "it must name a kind of stress shot, as the program writes it");
  }
  for (const engine::JsonReader& ball : state.objectArray("balls")) {
    ball.requireExactKeys({"position", "velocity", "angular_velocity"});
    BallState s;
    s.position = ball.point("position");
    s.velocity = vector3(ball, "velocity");
    s.angular_velocity = vector3(ball, "angular_velocity");
    replay.balls.push_back(s);
  }
  return replay;
}

// Shots [0, flags.shots) on flags.threads threads. Each thread takes the next shot number from a
// shared counter and finishes every shot it takes, so when the time budget stops the run the shots
// done are exactly a first run of numbers, and each shot's result depends on (seed, shot) alone:
// the summary is the same for any thread count.
Tally runShots(const StressFlags& flags, const engine::StressTables& tables,
               bool* stopped_by_budget) {
  std::atomic<long> next{0};
  std::atomic<bool> stop{false};
  Progress progress("shots", flags.shots);
  const auto started = std::chrono::steady_clock::now();
  std::vector<Tally> tallies(flags.threads);
  auto work = [&](Tally* tally) {
    for (;;) {
      if (flags.max_seconds > 0 &&
          std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count() >
              flags.max_seconds) {
        stop = true;
      }
      if (stop) return;
      const long shot = next.fetch_add(1);
      if (shot >= flags.shots) return;
      progress.advance();
      engine::StressShot made;
      engine::StressShotOutcome outcome;
      try {
        made = engine::makeStressShot(tables, flags.seed, shot, flags.max_balls);
        engine::SimulationParams params = tables.of(made.table).params;
        params.max_events = flags.max_events;
        outcome = engine::checkShot(tables.of(made.table), params, made.balls);
      } catch (const std::exception& e) {
        // Not a failure of the event loop (engine::checkShot records those) but of this program:
        // stop the run and say which shot, rather than let the thread end the process.
        tally->error = "shot " + std::to_string(shot) + ": " + e.what();
        stop = true;
        return;
      }
      ++tally->shots;
      ++tally->shots_by_kind[engine::stressShotKindName(made.kind)];
      tally->events += outcome.events;
      tally->pocketed += outcome.pocketed;
      tally->worst_energy_growth =
          std::max(tally->worst_energy_growth, outcome.worst_energy_growth);
      if (!outcome.check.failed()) continue;
      for (const auto& entry : outcome.check.failures) ++tally->failures_by_kind[entry.first];
      tally->failed.push_back({shot, std::move(made), outcome.check});
    }
  };
  std::vector<std::thread> threads;
  for (int t = 1; t < flags.threads; ++t) threads.emplace_back(work, &tallies[t]);
  work(&tallies[0]);
  for (std::thread& thread : threads) thread.join();
  for (const Tally& t : tallies) {
    if (!t.error.empty()) throw std::logic_error("stress: making or checking " + t.error);
  }
  Tally total;
  for (const Tally& t : tallies) total.add(t);
  std::sort(total.failed.begin(), total.failed.end(),
            [](const FailedShot& a, const FailedShot& b) { return a.shot < b.shot; });
  *stopped_by_budget = stop && total.shots < flags.shots;
  return total;
}

void runReplay(const StressFlags& flags) {
  Replay replay;
  try {
    replay = loadReplay(flags.replay_path);
  } catch (const std::invalid_argument& e) {
    throw UsageError(std::string("--replay: ") + e.what());
  }
  const engine::StressShotOutcome outcome =
      engine::checkShot(replay.table, replay.params, replay.balls);
  std::cout << "replay: " << flags.replay_path << ", table " << replay.table.name << ", balls "
            << replay.balls.size() << ", events " << outcome.events << ", ";
  if (!outcome.check.failed()) {
    std::cout << "passed every check\n";
    return;
  }
  std::cout << "FAILED " << outcome.check.first_message << '\n';
  throw std::runtime_error("the replayed shot failed its checks");
}

void runStress(StressFlags flags) {  // a copy: --threads is resolved in it
  if (!flags.replay_path.empty()) return runReplay(flags);
  if (flags.shots < 1) rejectFlag("--shots", static_cast<double>(flags.shots), "it must be >= 1");
  if (flags.max_balls < 2 || flags.max_balls > 16) {
    rejectFlag("--balls", flags.max_balls, "it must lie in [2, 16] (the most balls per shot)");
  }
  flags.threads = threadsOfFlag(flags.threads);
  if (!(flags.max_seconds >= 0) || !std::isfinite(flags.max_seconds)) {
    rejectFlag("--max-seconds", flags.max_seconds, "it must be >= 0 (0: no budget)");
  }
  if (flags.max_events < 1) {
    rejectFlag("--max-events", static_cast<double>(flags.max_events), "it must be >= 1");
  }
  if (!flags.failures_dir.empty()) {
    prepareOutputFolder("--failures", flags.failures_dir, kReproductionNames);
  }
  const engine::StressTables tables = engine::makeStressTables();
  const auto started = std::chrono::steady_clock::now();
  bool stopped_by_budget = false;
  const Tally tally = runShots(flags, tables, &stopped_by_budget);
  const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();

  long reported = 0, not_reproduced = 0;
  for (const FailedShot& f : tally.failed) {
    const nlohmann::json repro = reproductionJson(f, flags);
    std::string written;
    if (!flags.failures_dir.empty()) {
      written =
          (std::filesystem::path(flags.failures_dir) / reproductionFileName(f, flags)).string();
      AtomicFile file(written, "--failures");
      file.stream() << repro.dump(2) << '\n';
      file.commit();
      // The file must make the same failure again, read back as --replay reads it.
      const Replay replay = loadReplay(written);
      const engine::StressShotOutcome again =
          engine::checkShot(replay.table, replay.params, replay.balls);
      if (again.check.first_message != f.check.first_message) ++not_reproduced;
    }
    if (++reported > kMaxReportedShots) continue;
    std::cout << "FAILED SHOT " << f.shot << " (" << engine::stressShotKindName(f.made.kind) << ", "
              << tables.of(f.made.table).name << "): " << f.check.first_message << '\n';
    if (written.empty()) {
      std::cout << "  " << repro.dump() << '\n';
    } else if (f.made.scene) {
      std::cout << "  written to " << written << " (baize simulate runs it, baize stress --replay "
                << "checks it)\n";
    } else {
      std::cout << "  written to " << written << " (baize stress --replay checks it)\n";
    }
  }
  if (!flags.failures_dir.empty() && !tally.failed.empty()) {
    note(std::cout) << "reproductions: " << tally.failed.size() << " written to " << flags.failures_dir
              << ", " << tally.failed.size() - not_reproduced << " fail the same way on replay\n";
  }
  if (stopped_by_budget) {
    std::cout << "stopped by --max-seconds " << flags.max_seconds << " after shots 0 to "
              << tally.shots - 1 << " of " << flags.shots << '\n';
  }
  std::cout << "shots by kind:";
  for (const auto& [kind, count] : tally.shots_by_kind) std::cout << ' ' << kind << '=' << count;
  std::cout << "\nballs pocketed " << tally.pocketed << '\n';
  std::cout << "stress: shots " << tally.shots << ", events " << tally.events << ", failed shots "
            << tally.failed.size() << ", failed shots by kind";
  if (tally.failures_by_kind.empty()) std::cout << " none";
  for (const auto& [what, count] : tally.failures_by_kind) std::cout << ' ' << what << '=' << count;
  std::cout.precision(3);
  std::cout << ", largest energy growth " << tally.worst_energy_growth << " (relative), " << seconds
            << " s, " << tally.shots / seconds << " shots/s\n";
  if (not_reproduced > 0) {
    throw std::runtime_error(std::to_string(not_reproduced) +
                             " reproduction files do not make their failure again");
  }
  if (!tally.failed.empty()) {
    throw std::runtime_error(std::to_string(tally.failed.size()) + " shots failed their checks");
  }
}

}  // namespace

void addStressCommand(CLI::App& parent) {
  auto flags = std::make_shared<StressFlags>();
  CLI::App* command = parent.add_subcommand(
      "stress",
      "Run many seeded shots through the event loop and check every event (finite values, no "
      "overlap, no ball off the table, energy never growing, every shot coming to rest)");
  command->add_option("--shots", flags->shots, "number of shots")->capture_default_str();
  command
      ->add_option("--seed", flags->seed,
                   "random seed (shot k uses a generator seeded from it and k)")
      ->check(unsigned64())
      ->capture_default_str();
  command->add_option("--balls", flags->max_balls, "most balls in a shot (racks excepted)")
      ->capture_default_str();
  command->add_option("--threads", flags->threads, kThreadsHelp)->capture_default_str();
  command
      ->add_option("--max-seconds", flags->max_seconds,
                   "stop taking new shots after this many seconds (0: run all)")
      ->capture_default_str();
  command
      ->add_option("--max-events", flags->max_events, "a shot needing more events counts as a hang")
      ->capture_default_str();
  command
      ->add_option("--failures", flags->failures_dir,
                   "write a reproduction of every failing shot into this folder (made if missing; "
                   "earlier reproductions removed)")
      ->check(notEmpty());
  command
      ->add_option("--replay", flags->replay_path,
                   "check the one shot of a reproduction file (a scene or a state file) instead")
      ->check(notEmpty());
  command->callback([flags] {
    if (const int status = runReportingErrors("stress", [&] { runStress(*flags); })) {
      throw CLI::RuntimeError(status);
    }
  });
}

}  // namespace baize::tools
