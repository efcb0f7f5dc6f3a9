#include "tools/baize/simulate_command.h"

#include <CLI/CLI.hpp>
#include <chrono>
#include <cmath>
#include <iomanip>
#include <iostream>
#include <memory>
#include <nlohmann/json.hpp>
#include <sstream>

#include "engine/io/result_file.h"
#include "engine/io/scene.h"
#include "engine/io/table.h"
#include "engine/play/model_range.h"
#include "engine/play/shot_outcome.h"
#include "physics/value_text.h"
#include "tools/baize/atomic_file.h"
#include "tools/baize/cli_errors.h"
#include "tools/baize/drawing.h"
#include "tools/baize/picture_flags.h"

namespace baize::tools {
namespace {

struct SimulateFlags {
  std::string scene;
  std::string json_path;
  std::vector<std::string> samples;  // "BALL@TIME_S"
  std::string cushion_model;         // empty: the scene's
  std::string ball_ball_model;       // empty: the scene's
  PictureFlags pictures;
  const Drawing* drawing = nullptr;  // draws the pictures; none in a build without rendering
};

// The scene with the models the flags name, each at its defaults in place of the scene's group,
// checked as the scene's own physics is.
engine::Scene withFlaggedModels(engine::Scene scene, const SimulateFlags& flags) {
  if (flags.cushion_model.empty() && flags.ball_ball_model.empty()) return scene;
  if (!flags.cushion_model.empty())
    scene.overrides.cushion = nlohmann::json{{"model", flags.cushion_model}};
  if (!flags.ball_ball_model.empty())
    scene.overrides.ball_ball = nlohmann::json{{"model", flags.ball_ball_model}};
  engine::validateScenePhysics(engine::simulationParamsFor(scene),
                               engine::cueStrikeParamsFor(scene), scene.source, [] {
                                 return std::string(
                                     "the scene with --cushion-model or "
                                     "--ball-ball-model");
                               });
  return scene;
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
  // Also without a picture output: a bad value is an error. (Without a Drawing no picture flag
  // gets this far.)
  if (flags.drawing) flags.drawing->checkShotPictures(flags.pictures);
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
            << (physics["cushion"].contains("restitution_speed_dependence")
                    ? " with speed-dependent restitution"
                    : "")
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
  const std::size_t beyond = engine::impactsBeyondModelRange(scene, run).size();
  std::cout << "beyond the cushion model's range: " << beyond
            << (beyond == 1 ? " impact" : " impacts") << " (normal speed above "
            << physics::valueText(engine::validNormalSpeedFor(scene)) << " m/s)\n";
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
  std::vector<engine::ResultSample> sampled;
  for (const SampleRequest& request : samples) {
    const engine::Trajectory& path = r.trajectories.at(request.ball);
    engine::ResultSample sample;
    sample.ball = id(request.ball);
    sample.time_s = request.time_s;
    sample.state = engine::sampleTrajectory(params.cloth, path, request.time_s);
    // A pocketed ball is in its pocket from the piece that says so on; its state is where it fell.
    for (const engine::TrajectoryPiece& piece : path) {
      if (piece.pocketed && piece.start_time_s <= request.time_s) {
        sample.pocketed = true;
        sample.pocket = r.final_balls.at(request.ball).pocket;
        sample.fell_at_s = piece.start_time_s;
      }
    }
    const auto& s = sample.state;
    std::cout << "sample " << request.text << ": ";
    if (sample.pocketed) {
      std::cout << "in the " << pocket_names.at(sample.pocket) << " pocket since "
                << sample.fell_at_s << " s\n";
    } else {
      std::cout << "position [" << s.position.x() << ", " << s.position.y() << "] m, velocity "
                << vectorText(s.velocity) << " m/s, angular velocity "
                << vectorText(s.angular_velocity) << " rad/s\n";
    }
    sampled.push_back(sample);
  }
  std::cout << "wall time: " << std::setprecision(3) << wall_ms << " ms\n";

  if (json_file) {
    engine::ShotResult result = engine::shotResult(scene, run, /*with_recording=*/true);
    result.samples = sampled;
    json_file->stream() << engine::resultJson(result).dump(2) << '\n';
    json_file->commit();
  }
  if (flags.pictures.wanted()) flags.drawing->writeShotPictures(scene, run, flags.pictures);
}

}  // namespace

void addSimulateCommand(CLI::App& parent, const Drawing* drawing) {
  auto flags = std::make_shared<SimulateFlags>();
  flags->drawing = drawing;
  CLI::App* command = parent.add_subcommand(
      "simulate", "Strike a scene's cue ball and simulate the shot until every ball is at rest");
  command->add_option("scene", flags->scene, "the scene file (JSON, see docs/scenes.md)")
      ->required();
  command
      ->add_option("--json", flags->json_path, "also write the result file here (docs/results.md)")
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
  addPictureFlags(*command, flags->pictures, drawing);
  command->callback([flags] {
    if (const int status = runReportingErrors("simulate", [&] { runSimulate(*flags); })) {
      throw CLI::RuntimeError(status);
    }
  });
}

}  // namespace baize::tools
