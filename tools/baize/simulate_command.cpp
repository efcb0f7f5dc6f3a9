#include "tools/baize/simulate_command.h"

#include <CLI/CLI.hpp>
#include <chrono>
#include <cmath>
#include <filesystem>
#include <iomanip>
#include <iostream>
#include <memory>
#include <nlohmann/json.hpp>
#include <sstream>

#include "engine/io/scene.h"
#include "engine/play/shot_outcome.h"
#include "engine/io/table.h"
#include "render/shot_record.h"
#include "tools/baize/atomic_file.h"
#include "tools/baize/cli_errors.h"
#include "tools/baize/shot_pictures.h"

namespace baize::tools {
namespace {

struct SimulateFlags {
  std::string scene;
  std::string json_path;
  std::vector<std::string> samples;  // "BALL@TIME_S"
  std::string cushion_model;          // empty: the scene's
  std::string ball_ball_model;        // empty: the scene's
  PictureFlags pictures;
};

// The scene with the models the flags name, each at its defaults in place of the scene's group,
// checked as the scene's own physics is.
engine::Scene withFlaggedModels(engine::Scene scene, const SimulateFlags& flags) {
  if (flags.cushion_model.empty() && flags.ball_ball_model.empty()) return scene;
  if (!flags.cushion_model.empty())
    scene.overrides.cushion = nlohmann::json{{"model", flags.cushion_model}};
  if (!flags.ball_ball_model.empty())
    scene.overrides.ball_ball = nlohmann::json{{"model", flags.ball_ball_model}};
  engine::validateScenePhysics(engine::simulationParamsFor(scene), engine::cueStrikeParamsFor(scene),
                               scene.source, [] {
                                 return std::string("the scene with --cushion-model or "
                                                    "--ball-ball-model");
                               });
  return scene;
}

nlohmann::json stateJson(const physics::BallState& s) {
  return {{"position_m", {s.position.x(), s.position.y()}},
          {"velocity_mps", {s.velocity.x(), s.velocity.y(), s.velocity.z()}},
          {"angular_velocity_radps",
           {s.angular_velocity.x(), s.angular_velocity.y(), s.angular_velocity.z()}}};
}

// A --sample request: a ball of the scene and a time from the strike on.
struct SampleRequest {
  std::string text;  // as given, for messages
  int ball = 0;
  double time_s = 0;
};

SampleRequest parseSample(const std::string& text, const std::vector<std::string>& ball_ids) {
  const auto refuse = [&](const std::string& why) {
    throw UsageError("--sample '" + text + "' is not allowed: " + why);
  };
  const std::size_t at = text.rfind('@');
  if (at == std::string::npos) refuse("it must be BALL@TIME_S, for example cue@1.5");
  SampleRequest request{text, -1, 0};
  const std::string id = text.substr(0, at), time = text.substr(at + 1);
  for (std::size_t i = 0; i < ball_ids.size(); ++i) {
    if (ball_ids[i] == id) request.ball = static_cast<int>(i);
  }
  if (request.ball < 0) refuse("'" + id + "' is not a ball of the scene");
  std::size_t used = 0;
  try {
    request.time_s = std::stod(time, &used);
  } catch (const std::exception&) {
    used = 0;
  }
  if (used == 0 || used != time.size() || !std::isfinite(request.time_s) || request.time_s < 0) {
    refuse("the time must be a finite number of seconds >= 0 after the strike");
  }
  return request;
}

std::string vectorText(const Eigen::Vector3d& v) {
  std::ostringstream out;
  out << std::setprecision(4) << std::fixed << '[' << v.x() << ", " << v.y() << ", " << v.z()
      << ']';
  return out.str();
}

void runSimulate(const SimulateFlags& flags) {
  std::unique_ptr<AtomicFile> json_file;
  if (!flags.json_path.empty()) json_file = std::make_unique<AtomicFile>(flags.json_path, "--json");
  checkPictureFlags(flags.pictures);  // also without --png or --frames: a bad value is an error
  const engine::Scene scene = withFlaggedModels(engine::loadScene(flags.scene), flags);
  std::vector<std::string> scene_ids;
  for (const engine::PlacedBall& b : scene.balls) scene_ids.push_back(b.id);
  std::vector<SampleRequest> samples;
  for (const std::string& text : flags.samples) samples.push_back(parseSample(text, scene_ids));
  const auto start = std::chrono::steady_clock::now();
  const engine::SceneRun run =
      engine::runScene(scene, /*record_trajectories=*/json_file != nullptr ||
                                  flags.pictures.wanted() || !samples.empty());
  const double wall_ms =
      std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
  const engine::SimulationResult& r = run.result;
  const auto id = [&](int i) { return run.ball_ids.at(i); };
  const engine::ShotOutcome outcome = engine::shotOutcome(run, scene.cue_ball);
  const std::vector<std::string>& pocket_names = engine::pocketNames();
  const engine::SimulationParams params = engine::simulationParamsFor(scene);
  const engine::FinalBall& cue = *outcome.ball(scene.cue_ball);

  std::cout << std::setprecision(4) << std::fixed;
  std::cout << "scene: " << flags.scene << " (" << scene.table.name << ", " << run.ball_ids.size()
            << " balls)\n";
  std::cout << "strike: cue ball '" << scene.cue_ball << "' at " << run.strike.ball.v.norm()
            << " m/s\n";
  const nlohmann::json physics = engine::physicsJson(params, engine::cueStrikeParamsFor(scene));
  std::cout << "models: cushion " << physics["cushion"]["model"].get<std::string>()
            << ", ball-ball " << physics["ball_ball"]["model"].get<std::string>()
            << (physics["cue"].contains("squirt_end_mass_kg") ? ", squirt\n" : "\n");
  std::cout << "first ball hit: " << outcome.first_hit.value_or("none");
  if (outcome.first_hit && outcome.cushions_before_first_hit > 0) {
    std::cout << " (after " << outcome.cushions_before_first_hit << " cushion or jaw contacts)";
  }
  std::cout << "\npocketed:";
  for (std::size_t k = 0; k < outcome.pocketed.size(); ++k) {
    std::cout << (k ? ", " : " ") << outcome.pocketed[k].ball << " ("
              << pocket_names.at(outcome.pocketed[k].pocket) << ")";
  }
  std::cout << (outcome.pocketed.empty() ? " none\n" : "\n");
  std::cout << "cushion and jaw contacts: " << outcome.cushion_contacts << " (cue ball "
            << cue.cushion_contacts << ")\n";
  if (cue.pocketed) {
    std::cout << "cue ball: pocketed\n";
  } else {
    std::cout << "cue ball stopped at: [" << cue.position_m.x() << ", " << cue.position_m.y()
              << "] m\n";
  }
  std::cout << "foul: " << engine::foulName(outcome.foul) << "\n";
  std::cout << "events: " << r.events.size() << ", at rest after " << r.end_time_s << " s\n";
  std::cout << "predictions: " << r.predictions << " solved, " << r.skipped_predictions
            << " skipped\n";
  nlohmann::json sampled = nlohmann::json::array();
  for (const SampleRequest& request : samples) {
    const engine::Trajectory& path = r.trajectories.at(request.ball);
    const physics::BallState s = engine::sampleTrajectory(params.cloth, path, request.time_s);
    nlohmann::json entry = {{"ball", id(request.ball)}, {"time_s", request.time_s}};
    // A pocketed ball is in its pocket from the piece that says so on; its state is where it fell.
    const engine::TrajectoryPiece* fell = nullptr;
    for (const engine::TrajectoryPiece& piece : path) {
      if (piece.pocketed && piece.start_time_s <= request.time_s) fell = &piece;
    }
    std::cout << "sample " << request.text << ": ";
    if (fell) {
      const std::string& pocket = pocket_names.at(r.final_balls.at(request.ball).pocket);
      std::cout << "in the " << pocket << " pocket since " << fell->start_time_s << " s\n";
      entry["pocketed"] = true;
      entry["pocket_name"] = pocket;
      entry["fell_at_s"] = fell->start_time_s;
    } else {
      std::cout << "position [" << s.position.x() << ", " << s.position.y() << "] m, velocity "
                << vectorText(s.velocity) << " m/s, angular velocity "
                << vectorText(s.angular_velocity) << " rad/s\n";
      entry.update(stateJson(s));
      entry["pocketed"] = false;
    }
    sampled.push_back(entry);
  }
  std::cout << "wall time: " << std::setprecision(3) << wall_ms << " ms\n";

  if (json_file) {
    nlohmann::json out;
    out["scene"] = flags.scene;
    // Where `baize render` finds the table, balls and cloth again, whatever its working directory.
    out["scene_path"] = std::filesystem::absolute(flags.scene).lexically_normal().string();
    out["table"] = scene.table.name;
    out["end_time_s"] = r.end_time_s;
    out["first_ball_hit"] = outcome.first_hit.value_or("none");
    out["pocketed"] = nlohmann::json::array();
    for (const engine::PocketedBall& p : outcome.pocketed) out["pocketed"].push_back(p.ball);
    out["foul"] = engine::foulName(outcome.foul);
    out["predictions"] = {{"solved", r.predictions}, {"skipped", r.skipped_predictions}};
    if (!samples.empty()) out["samples"] = sampled;
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
      if (r.final_balls[i].pocketed) {
        ball["pocket"] = r.final_balls[i].pocket;
        ball["pocket_name"] = pocket_names.at(r.final_balls[i].pocket);
      }
      ball["cushion_contacts"] = outcome.final_balls[i].cushion_contacts;
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
  command->add_option("--json", flags->json_path, "also write the events and final states here")
      ->check(notEmpty());
  command->add_option("--sample", flags->samples,
                      "print (and with --json write) BALL's state at TIME_S seconds after the "
                      "strike, as BALL@TIME_S; repeatable");
  command
      ->add_option("--cushion-model", flags->cushion_model,
                   "resolve cushion and jaw hits by this model at its defaults instead of the "
                   "scene's (docs/scenes.md, physics.cushion.model)")
      ->check(CLI::IsMember(engine::cushionModels().names()));
  command
      ->add_option("--ball-ball-model", flags->ball_ball_model,
                   "resolve ball-ball collisions by this model at its defaults instead of the "
                   "scene's (physics.ball_ball.model)")
      ->check(CLI::IsMember(engine::ballBallModels().names()));
  addPictureFlags(*command, flags->pictures);
  command->callback([flags] {
    if (const int status = runReportingErrors("simulate", [&] { runSimulate(*flags); })) {
      throw CLI::RuntimeError(status);
    }
  });
}

}  // namespace baize::tools
