#include "tools/baize/bench_play_command.h"

#include <CLI/CLI.hpp>
#include <chrono>
#include <cmath>
#include <iomanip>
#include <iostream>
#include <memory>
#include <sstream>

#include "engine/play/games/frame_summary.h"
#include "engine/play/shot_suite.h"
#include "tools/baize/atomic_file.h"
#include "tools/baize/cli_errors.h"
#include "tools/baize/median.h"

namespace baize::tools {
namespace {

struct BenchPlayFlags {
  std::string game = "9-ball";
  int racks = 100;
  std::string noise = "0.5,1,2";
  std::uint64_t seed = 1;
  std::string csv_path;
};

struct LevelResult {
  double noise = 0;
  int racks = 0, finished = 0, run_outs = 0, first_visit_run_outs = 0, shots = 0;
  std::vector<int> breaks;
  std::vector<double> shot_ms;
};

std::vector<double> noiseLevels(const std::string& text) {
  std::vector<double> levels;
  std::istringstream in(text);
  std::string item;
  while (std::getline(in, item, ',')) {
    std::size_t used = 0;
    double v = -1;
    try {
      v = std::stod(item, &used);
    } catch (const std::exception&) {
      used = 0;
    }
    if (used != item.size() || !std::isfinite(v) || v < 0) {
      throw UsageError("--noise " + text + " is not allowed: give noise scales >= 0 separated by "
                       "commas, e.g. 0.5,1,2");
    }
    levels.push_back(v);
  }
  if (levels.empty()) throw UsageError("--noise is empty: give at least one noise scale");
  return levels;
}

// Frames shot by shot, each shot (the decision and its stroke) timed on this thread.
LevelResult playLevel(const engine::GameSetup& setup, double noise, const BenchPlayFlags& flags) {
  LevelResult level;
  level.noise = noise;
  level.racks = flags.racks;
  for (int rack = 0; rack < flags.racks; ++rack) {
    engine::PlayOptions options;
    options.noise_scale = noise;
    options.seed = flags.seed + static_cast<std::uint64_t>(rack);
    engine::PlayedFrame frame;
    engine::GameState state = engine::frameStart(setup, options);
    while (!state.frame_over && static_cast<int>(frame.shots.size()) < options.max_shots) {
      const auto start = std::chrono::steady_clock::now();
      frame.shots.push_back(engine::playShot(setup, state, options,
                                             static_cast<int>(frame.shots.size()), {}));
      level.shot_ms.push_back(
          std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start)
              .count());
      state = frame.shots.back().next;
    }
    frame.final_state = state;
    frame.finished = state.frame_over;
    const engine::FrameSummary summary = engine::summarizeFrame(frame);
    level.finished += summary.finished;
    level.run_outs += summary.run_out;
    level.first_visit_run_outs += summary.first_visit_run_out;
    level.shots += static_cast<int>(frame.shots.size());
    level.breaks.insert(level.breaks.end(), summary.breaks.begin(), summary.breaks.end());
  }
  return level;
}

// Mean and its 95 % interval (normal approximation with the sample standard deviation).
void meanInterval(const std::vector<int>& values, double* mean, double* low, double* high) {
  const double n = static_cast<double>(values.size());
  double sum = 0, squares = 0;
  for (int v : values) sum += v;
  *mean = n > 0 ? sum / n : NAN;
  for (int v : values) squares += (v - *mean) * (v - *mean);
  const double half = n > 1 ? engine::kWilsonZ95 * std::sqrt(squares / (n - 1) / n) : NAN;
  *low = *mean - half;
  *high = *mean + half;
}

std::string fixed(double v, int digits) {
  std::ostringstream out;
  out << std::fixed << std::setprecision(digits) << v;
  return out.str();
}

std::string estimateText(const engine::ProbabilityEstimate& e) {
  return fixed(e.probability, 3) + " [" + fixed(e.low, 3) + ", " + fixed(e.high, 3) + "] (" +
         std::to_string(e.successes) + "/" + std::to_string(e.samples) + ")";
}

std::string estimateCells(const engine::ProbabilityEstimate& e) {
  return fixed(e.probability, 3) + "," + fixed(e.low, 3) + "," + fixed(e.high, 3);
}

// One CSV row and one line of text per level.
std::string levelRow(const std::string& game, const LevelResult& r, std::string* line) {
  const engine::ProbabilityEstimate run_out = engine::wilsonEstimate(r.run_outs, r.racks);
  const engine::ProbabilityEstimate first =
      engine::wilsonEstimate(r.first_visit_run_outs, r.racks);
  double mean = NAN, low = NAN, high = NAN;
  meanInterval(r.breaks, &mean, &low, &high);
  int highest = 0;
  for (int b : r.breaks) highest = std::max(highest, b);
  const double ms = median(r.shot_ms);
  const bool snooker = game == "snooker";
  *line = game + " noise " + fixed(r.noise, 2) + ": " + std::to_string(r.racks) + " frames, " +
          std::to_string(r.finished) + " finished, " +
          (snooker ? "mean break " + fixed(mean, 2) + " [" + fixed(low, 2) + ", " + fixed(high, 2) +
                         "] over " + std::to_string(r.breaks.size()) + " breaks, highest " +
                         std::to_string(highest)
                   : "break and run " + estimateText(run_out) +
                         ", first visit after the break clears the table " +
                         estimateText(first)) +
          ", " + fixed(static_cast<double>(r.shots) / r.racks, 1) + " shots per frame, " +
          fixed(ms, 2) + " ms per shot (median)";
  const std::string na = "-";
  return game + "," + fixed(r.noise, 2) + "," + std::to_string(r.racks) + "," +
         std::to_string(r.finished) + "," +
         (snooker ? na + "," + na + "," + na + "," + na + "," + na + "," + na
                  : estimateCells(run_out) + "," + estimateCells(first)) +
         "," +
         (snooker ? fixed(mean, 2) + "," + fixed(low, 2) + "," + fixed(high, 2) + "," +
                        std::to_string(highest)
                  : na + "," + na + "," + na + "," + na) +
         "," + fixed(static_cast<double>(r.shots) / r.racks, 1) + "," + fixed(ms, 2) + "\n";
}

void runBenchPlay(const BenchPlayFlags& flags) {
  const std::optional<engine::Game> game = engine::gameNamed(flags.game);
  if (!game) {
    throw UsageError("--game " + flags.game +
                     " is not allowed: the games are 9-ball, 10-ball, 8-ball, snooker");
  }
  if (flags.racks < 1 || flags.racks > kMaxBenchCount) {
    rejectFlag("--racks", flags.racks, kBenchCountAllowed);
  }
  const std::vector<double> levels = noiseLevels(flags.noise);
  std::unique_ptr<AtomicFile> csv;
  if (!flags.csv_path.empty()) csv = std::make_unique<AtomicFile>(flags.csv_path, "--csv");
  const engine::GameSetup setup = engine::gameSetup(*game);
  std::string rows =
      "game,noise,frames,finished,break_and_run,bar_low,bar_high,first_visit_run_out,fvr_low,"
      "fvr_high,mean_break,break_low,break_high,highest_break,shots_per_frame,ms_per_shot\n";
  for (double noise : levels) {
    std::string line;
    rows += levelRow(flags.game, playLevel(setup, noise, flags), &line);
    std::cout << line << std::endl;
  }
  if (csv) {
    csv->stream() << rows;
    csv->commit();
  }
}

}  // namespace

void addBenchPlayCommand(CLI::App& bench) {
  auto flags = std::make_shared<BenchPlayFlags>();
  CLI::App* command = bench.add_subcommand(
      "play",
      "Play seeded frames at a few noise levels: run-out rate from the break (pool) or mean "
      "break (snooker) with 95 % intervals, and the time per shot decision (docs/games.md)");
  command->add_option("--game", flags->game, "9-ball, 10-ball, 8-ball or snooker (default 9-ball)");
  command->add_option("--racks", flags->racks, "frames per noise level (default 100)");
  command->add_option("--noise", flags->noise,
                      "noise scales, multiples of the default sigmas (default 0.5,1,2)");
  command->add_option("--seed", flags->seed, "frame r plays seed S + r (default 1)")
      ->check(unsigned64());
  command->add_option("--csv", flags->csv_path, "also write the table as CSV here")
      ->check(notEmpty());
  command->callback([flags] {
    if (const int status = runReportingErrors("bench play", [&] { runBenchPlay(*flags); })) {
      throw CLI::RuntimeError(status);
    }
  });
}

}  // namespace baize::tools
