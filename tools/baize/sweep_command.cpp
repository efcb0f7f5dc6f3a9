#include "tools/baize/sweep_command.h"

#include <CLI/CLI.hpp>
#include <Eigen/Core>
#include <cmath>
#include <cstdint>
#include <iomanip>
#include <iostream>
#include <memory>
#include <optional>
#include <sstream>

#include "engine/io/scene.h"
#include "engine/play/execution_noise.h"
#include "engine/play/shot_outcome.h"
#include "engine/play/shot_suite.h"
#include "physics/cue_strike.h"
#include "physics/value_text.h"
#include "tools/baize/atomic_file.h"
#include "tools/baize/cli_errors.h"
#include "tools/baize/drawing.h"
#include "tools/baize/progress.h"

namespace baize::tools {
namespace {

constexpr double kDegToRad = M_PI / 180;
// A grid end within this many steps of a grid point counts as on it: "0.5:4:0.25" reaches 4
// although 3.5 / 0.25 may round below 14.
constexpr double kGridEndSlack_steps = 1e-9;
// Points per sweep: a million shots is minutes of work; more is a typo in a step.
constexpr long kMaxPoints = 1000000;

struct Axis {
  std::string name;  // speed, aim, tip-height, tip-side, elevation
  double start = 0, stop = 0, step = 0;
  long count = 0;
  double at(long i) const { return start + static_cast<double>(i) * step; }
};

struct SweepFlags {
  std::string scene;
  std::vector<std::string> vary;
  std::string csv_path;
  std::string png_path;   // the position map, when set
  std::string object;     // empty: any ball but the cue ball
  int noise_samples = 0;  // 0: no execution error columns
  std::uint64_t seed = 1;
  const Drawing* drawing = nullptr;  // draws --png; none in a build without rendering
};

// Samples per grid point allowed with --noise: a bound that keeps a typo from running for days.
constexpr int kMaxNoiseSamples = 100000;

std::string number(double value) {
  std::ostringstream out;
  out << std::setprecision(10) << value;
  return out.str();
}

bool objectPocketed(const engine::ShotOutcome& o, const std::string& object) {
  for (const engine::PocketedBall& p : o.pocketed) {
    if (p.ball != o.cue_ball && (object.empty() || p.ball == object)) return true;
  }
  return false;
}

// The point's shot under execution error: how often the object ball and the cue ball fell, how
// often the tip offset miscued, and the spread of the cue ball's finishing positions (mean and the
// standard deviations along the principal axes of their covariance: the 1-sigma ellipse).
struct NoiseSummary {
  double p_object = 0, p_cue = 0, p_miscue = 0;
  std::optional<FinishSpread> spread;  // fewer than 2 samples on the table: none
};

NoiseSummary noiseSummary(const engine::Scene& scene, const SweepFlags& flags, long point) {
  const engine::ExecutionNoise noise;  // the defaults (physics-notes section 4)
  engine::Scene sample = scene;
  int object = 0, cue = 0, miscues = 0, on_table = 0;
  Eigen::Vector2d sum = Eigen::Vector2d::Zero();
  Eigen::Matrix2d products = Eigen::Matrix2d::Zero();
  for (int s = 0; s < flags.noise_samples; ++s) {
    engine::NormalGenerator normal(engine::sampleSeed(flags.seed, static_cast<std::uint64_t>(point),
                                                      static_cast<std::uint64_t>(s)));
    sample.shot = engine::perturbedShot(
        scene.shot, engine::drawExecutionError(noise, scene.ball_set.radius_m, &normal));
    engine::ShotOutcome o;
    try {
      o = engine::shotOutcome(engine::runScene(sample), sample.cue_ball);
    } catch (const std::exception&) {  // a miscue (or a run over the event budget)
      ++miscues;
      continue;
    }
    object += objectPocketed(o, flags.object);
    cue += o.cue_ball_pocketed;
    if (!o.cue_ball_pocketed) {
      ++on_table;
      sum += o.cue_ball_final_m;
      products += o.cue_ball_final_m * o.cue_ball_final_m.transpose();
    }
  }
  const double n = flags.noise_samples;
  NoiseSummary summary{object / n, cue / n, miscues / n, std::nullopt};
  if (on_table < 2) return summary;
  const Eigen::Vector2d mean = sum / on_table;
  const Eigen::Matrix2d covariance =
      (products - on_table * mean * mean.transpose()) / (on_table - 1);
  // Principal axes of a symmetric 2x2 matrix in closed form.
  const double half_trace = (covariance(0, 0) + covariance(1, 1)) / 2;
  const double half_gap = std::hypot((covariance(0, 0) - covariance(1, 1)) / 2, covariance(0, 1));
  FinishSpread e;
  e.mean_m = mean;
  e.sd_major_m = std::sqrt(std::max(0.0, half_trace + half_gap));
  e.sd_minor_m = std::sqrt(std::max(0.0, half_trace - half_gap));
  e.major_axis_rad = 0.5 * std::atan2(2 * covariance(0, 1), covariance(0, 0) - covariance(1, 1));
  summary.spread = e;
  return summary;
}

std::string noiseColumns(const NoiseSummary& s) {
  std::string columns = number(s.p_object) + ',' + number(s.p_cue) + ',' + number(s.p_miscue);
  if (!s.spread) return columns + ",,,,,";
  return columns + ',' + number(s.spread->mean_m.x()) + ',' + number(s.spread->mean_m.y()) + ',' +
         number(s.spread->sd_major_m) + ',' + number(s.spread->sd_minor_m) + ',' +
         number(s.spread->major_axis_rad / kDegToRad);
}

// The largest aim offset, deg: a scene's largest heading (beyond it one ulp of the heading exceeds
// 1e-10 deg).
constexpr double kMaxAimOffset_deg = 1e6;

const char* kParameterHelp =
    "speed (cue speed, m/s), aim (degrees added to the scene's heading), tip-height and tip-side "
    "(units of R), elevation (deg)";

Axis parseAxis(const std::string& spec) {
  const auto reject = [&](const std::string& why) -> Axis {
    throw UsageError("--vary " + spec + " is not allowed: " + why);
  };
  const std::size_t equals = spec.find('=');
  if (equals == std::string::npos) return reject("it must be NAME=START:STOP:STEP");
  Axis axis;
  axis.name = spec.substr(0, equals);
  if (axis.name != "speed" && axis.name != "aim" && axis.name != "tip-height" &&
      axis.name != "tip-side" && axis.name != "elevation") {
    return reject(std::string("NAME must be one of ") + kParameterHelp);
  }
  std::istringstream range(spec.substr(equals + 1));
  char colon1 = 0, colon2 = 0;
  if (!(range >> axis.start >> colon1 >> axis.stop >> colon2 >> axis.step) || colon1 != ':' ||
      colon2 != ':' || !range.eof()) {
    return reject("the range must be START:STOP:STEP, three numbers");
  }
  if (!std::isfinite(axis.start) || !std::isfinite(axis.stop) || !(axis.step > 0) ||
      !std::isfinite(axis.step) || axis.stop < axis.start) {
    return reject("it needs finite numbers with START <= STOP and STEP > 0");
  }
  // The bounds a scene's shot has (engine/io/scene.cpp), which the grid's shots bypass otherwise.
  if (axis.name == "speed" && !(axis.start > 0 && axis.stop <= physics::kMaxCueSpeed_mps)) {
    return reject("speeds must lie in (0, " + physics::valueText(physics::kMaxCueSpeed_mps) +
                  "] m/s, as a scene's");
  }
  if (axis.name == "aim" &&
      !(std::abs(axis.start) <= kMaxAimOffset_deg && std::abs(axis.stop) <= kMaxAimOffset_deg)) {
    return reject("aim offsets must lie in [-1e6, 1e6] deg, as a scene's heading");
  }
  axis.count =
      static_cast<long>(std::floor((axis.stop - axis.start) / axis.step + kGridEndSlack_steps)) + 1;
  if (axis.count > kMaxPoints) return reject("too many points");
  return axis;
}

void setParameter(const Axis& axis, double value, const physics::CueShot& base,
                  physics::CueShot* shot) {
  if (axis.name == "speed") shot->speed_mps = value;
  if (axis.name == "aim") shot->heading_rad = base.heading_rad + value * kDegToRad;
  if (axis.name == "tip-height") shot->height_offset = value;
  if (axis.name == "tip-side") shot->side_offset = value;
  if (axis.name == "elevation") shot->elevation_rad = value * kDegToRad;
}

void runSweep(const SweepFlags& flags) {
  if (flags.vary.empty() || flags.vary.size() > 2) {
    throw UsageError("--vary is needed once or twice (one or two parameters), got " +
                     std::to_string(flags.vary.size()));
  }
  if (flags.noise_samples < 0 || flags.noise_samples > kMaxNoiseSamples) {
    rejectFlag(
        "--noise", flags.noise_samples,
        "a number of samples per grid point in [0, " + std::to_string(kMaxNoiseSamples) + "]");
  }
  std::vector<Axis> axes;
  for (const std::string& spec : flags.vary) axes.push_back(parseAxis(spec));
  if (axes.size() == 2 && axes[0].name == axes[1].name) {
    throw UsageError("--vary " + axes[1].name + " is given twice: vary two different parameters");
  }
  const long rows = axes.size() == 1 ? axes[0].count : axes[0].count * axes[1].count;
  if (rows > kMaxPoints) {
    throw UsageError("the grid has " + std::to_string(rows) + " points: at most " +
                     std::to_string(kMaxPoints) + " are allowed");
  }
  std::unique_ptr<AtomicFile> csv;
  if (!flags.csv_path.empty()) csv = std::make_unique<AtomicFile>(flags.csv_path, "--csv");
  if (!flags.png_path.empty()) checkOutputPath("--png", flags.png_path);
  engine::Scene scene = engine::loadScene(flags.scene);
  if (!flags.object.empty()) {
    bool found = false;
    for (const engine::PlacedBall& b : scene.balls) found = found || b.id == flags.object;
    if (!found || flags.object == scene.cue_ball) {
      throw UsageError("--object " + flags.object +
                       " is not allowed: it must be a ball of the scene other than the cue ball");
    }
  }
  std::ostream& out = csv ? csv->stream() : std::cout;
  for (const Axis& a : axes) out << a.name << ',';
  out << "cue_x_m,cue_y_m,cue_pocketed,object_pocketed,first_hit,foul,pocketed,events,error";
  if (flags.noise_samples > 0) {
    out << ",p_object_pocketed,p_cue_pocketed,p_miscue,cue_mean_x_m,cue_mean_y_m,cue_sd_major_m,"
           "cue_sd_minor_m,cue_major_axis_deg";
  }
  out << '\n';
  const physics::CueShot base = scene.shot;
  const long inner = axes.size() == 2 ? axes[1].count : 1;
  SweepMap map;
  for (const Axis& a : axes) map.axes.push_back({a.name, a.at(0), a.at(a.count - 1), a.count});
  map.noise_samples = flags.noise_samples;
  Progress progress("points", rows);
  for (long row = 0; row < rows; ++row, progress.advance()) {
    const long i = row / inner, j = row % inner;
    scene.shot = base;
    bool marked = false;  // this row's noise-free shot ran and has its marker
    setParameter(axes[0], axes[0].at(i), base, &scene.shot);
    out << number(axes[0].at(i)) << ',';
    if (axes.size() == 2) {
      setParameter(axes[1], axes[1].at(j), base, &scene.shot);
      out << number(axes[1].at(j)) << ',';
    }
    try {
      const engine::ShotOutcome o = engine::shotOutcome(engine::runScene(scene), scene.cue_ball);
      std::string pocketed;
      for (const engine::PocketedBall& p : o.pocketed) {
        pocketed += (pocketed.empty() ? "" : " ") + p.ball;
      }
      out << number(o.cue_ball_final_m.x()) << ',' << number(o.cue_ball_final_m.y()) << ','
          << o.cue_ball_pocketed << ',' << objectPocketed(o, flags.object) << ','
          << o.first_hit.value_or("") << ',' << engine::foulName(o.foul) << ',' << pocketed << ','
          << o.events << ',';
      map.finishes.push_back({i, j, o.cue_ball_final_m, o.cue_ball_pocketed,
                              objectPocketed(o, flags.object), std::nullopt});
      marked = true;
    } catch (const std::exception& e) {
      // A grid point the strike refuses (a miscue) or that fails: a row saying why, no values.
      std::string why = e.what();
      for (char& c : why) {
        if (c == ',' || c == '\n' || c == '"') c = ' ';
      }
      out << ",,,,,,,," << why;
    }
    if (flags.noise_samples > 0) {
      const NoiseSummary summary = noiseSummary(scene, flags, row);
      out << ',' << noiseColumns(summary);
      // The spread belongs to the marker just made (none when the noise-free shot failed).
      if (marked) map.finishes.back().spread = summary.spread;
    }
    out << '\n';
  }
  if (!flags.png_path.empty()) {
    flags.drawing->writePositionMap(scene.table, map, flags.png_path);
    note(std::cerr) << "picture: " << flags.png_path << " (" << map.finishes.size()
                    << " finishing positions)\n";
  }
  if (csv) csv->commit();
}

}  // namespace

void addSweepCommand(CLI::App& parent, const Drawing* drawing) {
  auto flags = std::make_shared<SweepFlags>();
  flags->drawing = drawing;
  CLI::App* command = parent.add_subcommand(
      "sweep", "Simulate a scene's shot over a grid of one or two shot parameters (CSV)");
  command->add_option("scene", flags->scene, "the scene file (JSON, docs/scenes.md)")->required();
  command
      ->add_option("--vary", flags->vary,
                   std::string("NAME=START:STOP:STEP, once or twice; NAME: ") + kParameterHelp)
      ->allow_extra_args(false);
  command->add_option("--csv", flags->csv_path, "write the CSV here (default: standard output)")
      ->check(notEmpty());
  command
      ->add_option("--object", flags->object,
                   "the ball whose pocketing object_pocketed reports (default: any ball but "
                   "the cue ball)")
      ->check(notEmpty());
  CLI::Option* noise =
      command->add_option("--noise", flags->noise_samples,
                          "also run N samples per point with the default execution error and "
                          "write pocketing probabilities and the spread of the cue ball's "
                          "finishing positions");
  command->add_option("--seed", flags->seed, "seed of the execution error (default 1)")
      ->check(unsigned64())
      ->needs(noise);
  needsDrawing(*command,
               command
                   ->add_option("--png", flags->png_path,
                                "also draw the position map here: finishing positions coloured by "
                                "the first parameter, sized by the second, shaped by the outcome, "
                                "with the 1-sigma ellipses under --noise (PNG, 1600 x 800)"),
               drawing)
      ->check(notEmpty());
  command->callback([flags] {
    if (const int status = runReportingErrors("sweep", [&] { runSweep(*flags); })) {
      throw CLI::RuntimeError(status);
    }
  });
}

}  // namespace baize::tools
