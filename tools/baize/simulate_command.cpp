#include "tools/baize/simulate_command.h"

#include <CLI/CLI.hpp>
#include <chrono>
#include <filesystem>
#include <iomanip>
#include <iostream>
#include <memory>
#include <nlohmann/json.hpp>
#include <set>

#include "engine/scene.h"
#include "render/shot_record.h"
#include "tools/baize/atomic_file.h"
#include "tools/baize/cli_errors.h"
#include "tools/baize/shot_pictures.h"

namespace baize::tools {
namespace {

struct SimulateFlags {
  std::string scene;
  std::string json_path;
  PictureFlags pictures;
};

nlohmann::json stateJson(const physics::BallState& s) {
  return {{"position_m", {s.position.x(), s.position.y()}},
          {"velocity_mps", {s.velocity.x(), s.velocity.y(), s.velocity.z()}},
          {"angular_velocity_radps",
           {s.angular_velocity.x(), s.angular_velocity.y(), s.angular_velocity.z()}}};
}

void runSimulate(const SimulateFlags& flags) {
  std::unique_ptr<AtomicFile> json_file;
  if (!flags.json_path.empty()) json_file = std::make_unique<AtomicFile>(flags.json_path, "--json");
  if (flags.pictures.wanted()) checkPictureFlags(flags.pictures);
  const engine::Scene scene = engine::loadScene(flags.scene);
  const auto start = std::chrono::steady_clock::now();
  const engine::SceneRun run = engine::runScene(
      scene, /*record_trajectories=*/json_file != nullptr || flags.pictures.wanted());
  const double wall_ms =
      std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
  const engine::SimulationResult& r = run.result;
  const auto id = [&](int i) { return run.ball_ids.at(i); };

  std::string first_hit = "none";
  std::vector<std::string> pocketed;
  std::set<int> cushions;
  int cue_index = 0;
  for (std::size_t i = 0; i < run.ball_ids.size(); ++i) {
    if (run.ball_ids[i] == scene.cue_ball) cue_index = static_cast<int>(i);
  }
  for (const engine::Event& e : r.events) {
    if (e.kind == engine::EventKind::BallBall && first_hit == "none" &&
        (e.ball == cue_index || e.other == cue_index)) {
      first_hit = id(e.ball == cue_index ? e.other : e.ball);
    }
    if (e.kind == engine::EventKind::Pocket) pocketed.push_back(id(e.ball));
    if (e.kind == engine::EventKind::Cushion || e.kind == engine::EventKind::Jaw) {
      cushions.insert(e.kind == engine::EventKind::Cushion ? e.index : 1000 + e.index);
    }
  }
  const engine::BallRecord& cue = r.final_balls.at(cue_index);
  std::cout << std::setprecision(4) << std::fixed;
  std::cout << "scene: " << flags.scene << " (" << scene.table.name << ", " << run.ball_ids.size()
            << " balls)\n";
  std::cout << "strike: cue ball '" << scene.cue_ball << "' at " << run.strike.ball.v.norm()
            << " m/s\n";
  const nlohmann::json physics =
      engine::physicsJson(engine::simulationParamsFor(scene), engine::cueStrikeParamsFor(scene));
  std::cout << "models: cushion " << physics["cushion"]["model"].get<std::string>()
            << ", ball-ball " << physics["ball_ball"]["model"].get<std::string>()
            << (physics["cue"].contains("squirt_end_mass_kg") ? ", squirt\n" : "\n");
  std::cout << "first ball hit: " << first_hit << "\n";
  std::cout << "pocketed:";
  for (const std::string& b : pocketed) std::cout << ' ' << b;
  std::cout << (pocketed.empty() ? " none\n" : "\n");
  std::cout << "cushions and jaws touched: " << cushions.size() << "\n";
  if (cue.pocketed) {
    std::cout << "cue ball: pocketed\n";
  } else {
    std::cout << "cue ball stopped at: [" << cue.state.position.x() << ", "
              << cue.state.position.y() << "] m\n";
  }
  std::cout << "events: " << r.events.size() << ", at rest after " << r.end_time_s << " s\n";
  std::cout << "predictions: " << r.predictions << " solved, " << r.skipped_predictions
            << " skipped\n";
  std::cout << "wall time: " << std::setprecision(3) << wall_ms << " ms\n";

  if (json_file) {
    nlohmann::json out;
    out["scene"] = flags.scene;
    // Where `baize render` finds the table, balls and cloth again, whatever its working directory.
    out["scene_path"] = std::filesystem::absolute(flags.scene).lexically_normal().string();
    out["table"] = scene.table.name;
    out["end_time_s"] = r.end_time_s;
    out["first_ball_hit"] = first_hit;
    out["pocketed"] = pocketed;
    out["physics"] = physics;  // the parameters the shot ran with, in the scene format's keys
    for (const engine::Event& e : r.events) {
      nlohmann::json event = {
          {"time_s", e.time_s}, {"type", engine::eventKindName(e.kind)}, {"ball", id(e.ball)}};
      if (e.other >= 0) event["other"] = id(e.other);
      if (e.index >= 0) event["index"] = e.index;
      for (const auto& s : e.before) event["before"].push_back(stateJson(s));
      for (const auto& s : e.after) event["after"].push_back(stateJson(s));
      out["events"].push_back(event);
    }
    for (std::size_t i = 0; i < r.final_balls.size(); ++i) {
      nlohmann::json ball = stateJson(r.final_balls[i].state);
      ball["id"] = id(static_cast<int>(i));
      ball["pocketed"] = r.final_balls[i].pocketed;
      if (r.final_balls[i].pocketed) ball["pocket"] = r.final_balls[i].pocket;
      out["final"].push_back(ball);
      // The exact path: from each piece's start the ball moves in closed form
      // (physics/cloth_motion.h `advance`) from that state until the next piece.
      nlohmann::json pieces = nlohmann::json::array();
      for (const engine::TrajectoryPiece& piece : r.trajectories[i]) {
        nlohmann::json q = stateJson(piece.state);
        q["start_time_s"] = piece.start_time_s;
        q["pocketed"] = piece.pocketed;
        pieces.push_back(q);
      }
      out["trajectories"][id(static_cast<int>(i))] = pieces;
    }
    json_file->stream() << std::setprecision(17) << out.dump(2) << '\n';
    json_file->commit();
  }
  if (flags.pictures.wanted()) writePictures(render::shotRecordOf(scene, run), flags.pictures);
}

}  // namespace

void addSimulateCommand(CLI::App& parent) {
  auto flags = std::make_shared<SimulateFlags>();
  CLI::App* command = parent.add_subcommand(
      "simulate", "Strike a scene's cue ball and simulate the shot until every ball is at rest");
  command->add_option("scene", flags->scene, "the scene file (JSON, see docs/scenes.md)")
      ->required();
  command->add_option("--json", flags->json_path, "also write the events and final states here");
  addPictureFlags(*command, flags->pictures);
  command->callback([flags] {
    if (const int status = runReportingErrors("simulate", [&] { runSimulate(*flags); })) {
      throw CLI::RuntimeError(status);
    }
  });
}

}  // namespace baize::tools
