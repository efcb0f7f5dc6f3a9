#include "tools/baize/plan_command.h"

#include <CLI/CLI.hpp>
#include <cmath>
#include <cstdint>
#include <iomanip>
#include <iostream>
#include <memory>
#include <sstream>

#include "engine/play/shot_planner.h"
#include "engine/play/shot_suite.h"
#include "tools/baize/atomic_file.h"
#include "tools/baize/cli_errors.h"
#include "tools/baize/drawing.h"
#include "tools/baize/progress.h"

namespace baize::tools {
namespace {

constexpr double kDegToRad = M_PI / 180;
// Fresh samples per reported shot allowed: a bound that keeps a typo from running for hours.
constexpr int kMaxNoiseSamples = 1000000;
constexpr long kMaxBudget = 100000000;  // shots; likewise
// The re-estimates use streams apart from the search's (engine/play/shot_planner.cpp uses up to
// 2^33).
constexpr std::uint64_t kFreshStreamBase = 1ull << 40;

struct PlanFlags {
  std::string scene;
  std::string ball;
  std::string pocket;
  std::string region;
  long budget = 4000;
  int noise_samples = 1000;
  std::uint64_t seed = 1;
  int report = 3;
  std::string png_path;
  bool compare_grid = false;
  int grid_samples = 10;
  const Drawing* drawing = nullptr;  // draws --png; none in a build without rendering
};

int pocketIndex(const std::string& text, const engine::Scene& scene) {
  const std::vector<std::string>& names = engine::pocketNames();
  for (std::size_t i = 0; i < names.size() && i < scene.table.pockets.size(); ++i) {
    if (text == names[i] || text == std::to_string(i)) return static_cast<int>(i);
  }
  throw UsageError("--pocket " + text + " is not allowed: give a pocket index 0 to " +
                   std::to_string(scene.table.pockets.size() - 1) +
                   " or a name (bottom-left, bottom-middle, bottom-right, top-right, top-middle, "
                   "top-left)");
}

std::vector<double> numbers(const std::string& text) {
  std::vector<double> values;
  std::istringstream in(text);
  std::string item;
  while (std::getline(in, item, ',')) {
    std::size_t used = 0;
    double v = 0;
    try {
      v = std::stod(item, &used);
    } catch (const std::exception&) {
      used = 0;
    }
    if (used != item.size() || item.empty() || !std::isfinite(v)) return {};
    values.push_back(v);
  }
  return values;
}

engine::CueBallRegion parseRegion(const std::string& spec) {
  const auto reject = [&]() -> engine::CueBallRegion {
    throw UsageError("--region " + spec +
                     " is not allowed: it must be circle:X,Y,R (m, R > 0) or "
                     "rectangle:X0,Y0,X1,Y1 (m, X0 < X1, Y0 < Y1)");
  };
  const std::size_t colon = spec.find(':');
  if (colon == std::string::npos) return reject();
  const std::string kind = spec.substr(0, colon);
  const std::vector<double> v = numbers(spec.substr(colon + 1));
  engine::CueBallRegion region;
  if (kind == "circle" && v.size() == 3 && v[2] > 0) {
    region.kind = engine::CueBallRegion::Kind::Circle;
    region.centre_m = {v[0], v[1]};
    region.radius_m = v[2];
    return region;
  }
  if (kind == "rectangle" && v.size() == 4 && v[0] < v[2] && v[1] < v[3]) {
    region.kind = engine::CueBallRegion::Kind::Rectangle;
    region.min_m = {v[0], v[1]};
    region.max_m = {v[2], v[3]};
    return region;
  }
  return reject();
}

// Refuses a region in which the cue ball cannot stop: one that lies wholly outside the rectangle
// its centre can reach on the scene's table (the cushion noses moved in by a ball radius).
void requireRegionOnTable(const engine::CueBallRegion& region, const std::string& spec,
                          const engine::Scene& scene) {
  const double R = scene.ball_set.radius_m;
  const Eigen::Vector2d reach(scene.table.length_m / 2 - R, scene.table.width_m / 2 - R);
  bool meets = false;
  if (region.kind == engine::CueBallRegion::Kind::Circle) {
    const Eigen::Vector2d nearest = region.centre_m.cwiseMax(-reach).cwiseMin(reach);
    meets = (nearest - region.centre_m).norm() < region.radius_m;
  } else {
    meets = (region.min_m.array() < reach.array()).all() &&
            (region.max_m.array() > -reach.array()).all();
  }
  if (meets) return;
  std::ostringstream area;
  area << "[" << -reach.x() << ", " << reach.x() << "] x [" << -reach.y() << ", " << reach.y()
       << "] m";
  throw UsageError("--region " + spec +
                   " is not allowed: it lies wholly off the table, where the cue ball cannot "
                   "stop; its centre stops within " +
                   area.str() + " on " + scene.table.name);
}

std::string shotText(const physics::CueShot& s) {
  std::ostringstream out;
  out << std::fixed << std::setprecision(3) << "speed " << s.speed_mps << " m/s, heading "
      << s.heading_rad / kDegToRad << " deg, tip height " << s.height_offset << " R, side "
      << s.side_offset << " R, elevation " << std::setprecision(1) << s.elevation_rad / kDegToRad
      << " deg";
  return out.str();
}

std::string estimateText(const engine::ProbabilityEstimate& p) {
  std::ostringstream out;
  out << std::fixed << std::setprecision(3) << p.probability << " [" << p.low << ", " << p.high
      << "] (" << p.successes << "/" << p.samples << ")";
  return out.str();
}

// Prints the result's shots, each re-estimated from fresh samples (the search's own counts are
// biased upwards: the best was picked by them). Returns the first fresh estimate.
engine::ProbabilityEstimate report(const std::string& method, const engine::PlanResult& result,
                                   const engine::Scene& scene, const engine::PlanGoal& goal,
                                   const engine::PlanOptions& options, int fresh_samples,
                                   std::uint64_t stream_base) {
  std::cout << method << ": " << result.candidates << " candidates, " << result.shots_simulated
            << " shots simulated\n";
  engine::ProbabilityEstimate first;
  for (std::size_t k = 0; k < result.best.size(); ++k) {
    const engine::PlannedShot& p = result.best[k];
    const engine::ProbabilityEstimate fresh = engine::estimateGoal(
        scene, goal, p.shot, options.noise, fresh_samples, options.seed, stream_base + k);
    if (k == 0) first = fresh;
    std::cout << "  " << k + 1 << ". " << shotText(p.shot) << "\n     p = " << estimateText(fresh)
              << " from fresh samples; in the search " << estimateText(p.success) << "\n";
  }
  return first;
}

void runPlan(const PlanFlags& flags) {
  if (flags.budget < engine::kMinPlanBudget || flags.budget > kMaxBudget) {
    rejectFlag("--budget", static_cast<double>(flags.budget),
               "a number of simulated shots in [" + std::to_string(engine::kMinPlanBudget) + ", " +
                   std::to_string(kMaxBudget) + "]");
  }
  if (flags.noise_samples < 1 || flags.noise_samples > kMaxNoiseSamples) {
    rejectFlag("--noise-samples", flags.noise_samples,
               "a number of fresh samples per reported shot in [1, " +
                   std::to_string(kMaxNoiseSamples) + "]");
  }
  if (flags.report < 1 || flags.report > engine::kRaced) {
    rejectFlag("--report", flags.report,
               "a number of shots in [1, " + std::to_string(engine::kRaced) + "]");
  }
  if (flags.grid_samples < 1 || flags.grid_samples > flags.budget) {
    rejectFlag("--grid-samples", flags.grid_samples, "a number of samples in [1, --budget]");
  }
  std::optional<engine::CueBallRegion> region;
  if (!flags.region.empty()) region = parseRegion(flags.region);
  if (!flags.png_path.empty()) checkOutputPath("--png", flags.png_path);
  engine::Scene scene = engine::loadScene(flags.scene);
  if (region) requireRegionOnTable(*region, flags.region, scene);
  engine::PlanGoal goal{flags.ball, pocketIndex(flags.pocket, scene), region};
  try {
    engine::validatePlanGoal(scene, goal);
  } catch (const std::invalid_argument& e) {
    throw UsageError(std::string("--ball: ") + e.what());
  }
  engine::PlanOptions options;
  options.budget_shots = flags.budget;
  options.seed = flags.seed;
  options.report = flags.report;

  std::cout << "plan: pot " << goal.ball << " in " << engine::pocketNames()[goal.pocket]
            << ", cue ball on the table"
            << (region ? ", stopping in " + flags.region : std::string()) << "; budget "
            << flags.budget << " shots, " << flags.noise_samples
            << " fresh samples per reported shot, seed " << flags.seed << "\n";
  engine::PlanResult planned;
  {
    Progress progress("shots of the search", flags.budget);
    options.on_shot = [&progress] { progress.advance(); };
    planned = engine::planShot(scene, goal, options);
  }
  options.on_shot = nullptr;
  const engine::ProbabilityEstimate best =
      report("planner", planned, scene, goal, options, flags.noise_samples, kFreshStreamBase);
  if (flags.compare_grid) {
    const engine::PlanResult grid = engine::gridSearch(scene, goal, options, flags.grid_samples);
    const engine::ProbabilityEstimate grid_best =
        report("grid (" + std::to_string(flags.grid_samples) + " samples per point)", grid, scene,
               goal, options, flags.noise_samples, kFreshStreamBase + engine::kRaced);
    std::cout << std::fixed << std::setprecision(3) << "comparison: best p planner "
              << best.probability << ", grid " << grid_best.probability << " (fresh samples)\n";
  }
  if (!flags.png_path.empty() && !planned.best.empty()) {
    scene.shot = planned.best.front().shot;
    const engine::SceneRun run = engine::runScene(scene, true);
    std::vector<engine::CueBallRegion> regions;
    if (region) regions.push_back(*region);
    flags.drawing->shotPainter()->write(scene, run, regions, flags.png_path);
    note(std::cout) << "picture: " << flags.png_path << "\n";
  }
}

}  // namespace

void addPlanCommand(CLI::App& parent, const Drawing* drawing) {
  auto flags = std::make_shared<PlanFlags>();
  flags->drawing = drawing;
  CLI::App* command = parent.add_subcommand(
      "plan",
      "Search the shot most likely to pot a ball and leave the cue ball in a region, under "
      "execution error (docs/positional.md)");
  command->add_option("scene", flags->scene, "the scene file (JSON, docs/scenes.md)")->required();
  command->add_option("--ball", flags->ball, "the ball to pot")->required();
  command->add_option("--pocket", flags->pocket, "the pocket: index 0-5 or name")->required();
  command
      ->add_option("--region", flags->region,
                   "where the cue ball must stop: circle:X,Y,R or rectangle:X0,Y0,X1,Y1 (m)")
      ->check(notEmpty());
  command->add_option("--budget", flags->budget,
                      "simulated shots for the search, noise-free and noisy (default 4000)");
  command->add_option("--noise-samples", flags->noise_samples,
                      "fresh noisy samples to re-estimate each reported shot (default 1000)");
  command->add_option("--seed", flags->seed, "seed of the execution error (default 1)")
      ->check(unsigned64());
  command->add_option("--report", flags->report, "shots reported (default 3)");
  needsDrawing(*command,
               command
                   ->add_option("--png", flags->png_path,
                                "draw the best shot with its region here (PNG)"),
               drawing)
      ->check(notEmpty());
  CLI::Option* compare_grid = command->add_flag(
      "--compare-grid", flags->compare_grid,
      "also run a blind grid of the same budget and compare the best probabilities");
  command
      ->add_option("--grid-samples", flags->grid_samples,
                   "noisy samples per grid point with --compare-grid (default 10)")
      ->needs(compare_grid);
  command->callback([flags] {
    if (const int status = runReportingErrors("plan", [&] { runPlan(*flags); })) {
      throw CLI::RuntimeError(status);
    }
  });
}

}  // namespace baize::tools
