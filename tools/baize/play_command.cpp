#include "tools/baize/play_command.h"

#include <CLI/CLI.hpp>
#include <filesystem>
#include <iomanip>
#include <iostream>
#include <memory>
#include <sstream>

#include "engine/play/games/frame_summary.h"
#include "engine/play/games/game_log.h"
#include "tools/baize/atomic_file.h"
#include "tools/baize/cli_errors.h"
#include "tools/baize/drawing.h"
#include "tools/baize/output_folder.h"
#include "tools/baize/progress.h"
#include "tools/baize/shot_file.h"

namespace baize::tools {
namespace {

// The pictures --png-dir gets, one per shot: shot_NNN.png.
const OutputFileNames kShotPictureNames{"shot_", ".png"};

// The most shots one frame may take: far beyond any real frame, a bound on a typo.
constexpr int kMaxShotsAllowed = 10000;

struct PlayFlags {
  std::string game;
  std::uint64_t seed = 1;
  double noise = 1;
  std::string log_path;
  std::string shots_path;
  std::string png_dir;
  int max_shots = 400;
  const Drawing* drawing = nullptr;  // draws --png-dir; none in a build without rendering
};

engine::Game gameFlag(const std::string& name) {
  if (const std::optional<engine::Game> game = engine::gameNamed(name)) return *game;
  std::string known;
  for (const std::string& n : engine::gameNames()) known += (known.empty() ? "" : ", ") + n;
  throw UsageError("GAME = " + name + " is not allowed: the games are " + known);
}

void checkFlags(const PlayFlags& flags) {
  if (!(std::isfinite(flags.noise) && flags.noise >= 0)) {
    rejectFlag("--noise", flags.noise, "a multiple of the default execution-noise sigmas, >= 0");
  }
  if (flags.max_shots < 1 || flags.max_shots > kMaxShotsAllowed) {
    rejectFlag("--max-shots", flags.max_shots,
               "a number of shots in [1, " + std::to_string(kMaxShotsAllowed) + "]");
  }
  if (!flags.log_path.empty() && flags.log_path != "-") checkOutputPath("--log", flags.log_path);
  if (!flags.png_dir.empty()) {
    prepareOutputFolder("--png-dir", flags.png_dir, kShotPictureNames);
  }
}

// Player A's shots from the file, line after line; the game player takes over after the last.
engine::ShotSource fileSource(const std::string& path, const engine::GameSetup& setup) {
  auto lines = std::make_shared<std::vector<ShotLine>>(readShotFile(path));
  auto next = std::make_shared<std::size_t>(0);
  return [lines, next, path, setup](const engine::GameState& state)
             -> std::optional<engine::GameShot> {
    if (*next >= lines->size()) return std::nullopt;
    return shotFromLine((*lines)[(*next)++], path, state, setup);
  };
}

void writeLog(const engine::PlayedFrame& frame, const std::string& path) {
  std::ostringstream text;
  for (std::size_t i = 0; i < frame.shots.size(); ++i) {
    text << engine::playedShotJson(frame.shots[i], static_cast<int>(i)).dump() << "\n";
  }
  AtomicFile file(path, "--log");
  file.stream() << text.str();
  file.commit();
}

void writePictures(const engine::GameSetup& setup, const engine::PlayedFrame& frame,
                   const std::string& dir, const Drawing& drawing) {
  const std::unique_ptr<ShotPainter> painter = drawing.shotPainter();
  for (std::size_t i = 0; i < frame.shots.size(); ++i) {
    const engine::PlayedShot& shot = frame.shots[i];
    engine::GameShot stroke = shot.intended;
    stroke.shot = shot.executed;
    const engine::Scene scene = engine::shotScene(setup, shot.state, stroke);
    if (!shot.ran) continue;  // a miscue: nothing moved
    const engine::SceneRun run = engine::runScene(scene, true);
    std::ostringstream name;
    name << kShotPictureNames.prefix << std::setw(3) << std::setfill('0') << i << kShotPictureNames.suffix;
    painter->write(scene, run, {}, (std::filesystem::path(dir) / name.str()).string());
  }
}

void printSummary(const engine::PlayedFrame& frame, const engine::Game game) {
  const engine::FrameSummary s = engine::summarizeFrame(frame);
  const char* names[] = {"A", "B"};
  std::cout << engine::gameName(game) << ": " << frame.shots.size() << " shots, ";
  if (s.finished) {
    std::cout << "player " << names[s.winner] << " won" << (s.run_out ? " (break and run)" : "");
  } else {
    std::cout << "unfinished (shot limit)";
  }
  if (game == engine::Game::Snooker) {
    std::cout << ", score " << frame.final_state.score[0] << "-" << frame.final_state.score[1];
  }
  std::cout << "\n";
  for (int p = 0; p < 2; ++p) {
    const engine::PlayerSummary& ps = s.players[p];
    std::cout << "  player " << names[p] << ": " << ps.shots << " shots, " << ps.visits
              << " visits, " << ps.potted << " potted, " << ps.fouls << " fouls, best visit "
              << ps.best_visit << (game == engine::Game::Snooker ? " points" : " balls") << "\n";
  }
}

void runPlay(const PlayFlags& flags) {
  const engine::Game game = gameFlag(flags.game);
  checkFlags(flags);
  const engine::GameSetup setup = engine::gameSetup(game);
  engine::ShotSource source;
  if (!flags.shots_path.empty()) source = fileSource(flags.shots_path, setup);
  engine::PlayOptions options;
  options.noise_scale = flags.noise;
  options.seed = flags.seed;
  options.max_shots = flags.max_shots;
  const engine::PlayedFrame frame = engine::playFrame(setup, options, source);
  if (!flags.png_dir.empty()) writePictures(setup, frame, flags.png_dir, *flags.drawing);
  if (!flags.log_path.empty()) writeLog(frame, flags.log_path);
  printSummary(frame, game);  // the result: --quiet drops only notes and progress
}

}  // namespace

void addPlayCommand(CLI::App& parent, const Drawing* drawing) {
  auto flags = std::make_shared<PlayFlags>();
  flags->drawing = drawing;
  CLI::App* command = parent.add_subcommand(
      "play",
      "Play a frame of 9-ball, 10-ball, 8-ball or snooker from the break: two players driven by "
      "the planner, under execution noise (docs/games.md)");
  command->add_option("game", flags->game, "the game: 9-ball, 10-ball, 8-ball or snooker")
      ->required();
  command->add_option("--seed", flags->seed, "seed of the execution noise (default 1)")
      ->check(unsigned64());
  command->add_option("--noise", flags->noise,
                      "execution noise as a multiple of the default sigmas; 0 none (default 1)");
  command->add_option("--log", flags->log_path,
                      "write the frame log here as JSON lines (state, shot, outcome, decision); "
                      "- for standard output")
      ->check(notEmpty());
  command->add_option("--shots", flags->shots_path,
                      "player A's shots, one JSON object per line (the planner plays after the "
                      "last)")
      ->check(notEmpty());
  needsDrawing(*command,
               command->add_option("--png-dir", flags->png_dir, "draw every shot to DIR/shot_NNN.png"),
               drawing)
      ->check(notEmpty());
  command->add_option("--max-shots", flags->max_shots,
                      "stop a frame not over after this many shots (default 400)");
  command->callback([flags] {
    if (const int status = runReportingErrors("play", [&] { runPlay(*flags); })) {
      throw CLI::RuntimeError(status);
    }
  });
}

}  // namespace baize::tools
