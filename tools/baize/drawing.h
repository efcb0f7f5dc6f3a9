// What the commands draw, behind one interface, so that baize builds without the renderer. A build
// with rendering hands the commands the renderer's Drawing (tools/baize/pictures/), a core build
// (BAIZE_WITH_RENDER=OFF) none (picture_commands.h says which). Every flag that draws is marked by
// needsDrawing: without a Drawing it is refused by name as the command line is read, before any
// work, so a command never reaches a picture it cannot make.
#pragma once

#include <Eigen/Core>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "engine/fit/cushion_calibration.h"
#include "engine/io/scene.h"
#include "engine/play/shot_suite.h"
#include "tools/baize/picture_flags.h"

namespace CLI {
class App;
class Option;
}

namespace baize::tools {

// Top views of shots as PNG files, one renderer for many (check, plan and play draw shot after shot).
class ShotPainter {
 public:
  virtual ~ShotPainter() = default;
  // The shot of `run` (trajectories recorded), each region drawn over it, written to `path`.
  virtual void write(const engine::Scene& scene, const engine::SceneRun& run,
                     const std::vector<engine::CueBallRegion>& regions,
                     const std::string& path) = 0;
};

// `baize sweep --png`: the parameters varied, and per grid point whose noise-free shot ran, where
// the cue ball finished and, under --noise, the spread of its noisy finishes.
struct SweepAxisRange {
  std::string name;  // speed, aim, tip-height, tip-side, elevation
  double first = 0, last = 0;
  long count = 1;  // grid points along it
};
struct FinishSpread {  // the 1-sigma ellipse: mean and standard deviations along the principal axes
  Eigen::Vector2d mean_m = Eigen::Vector2d::Zero();
  double sd_major_m = 0, sd_minor_m = 0;
  double major_axis_rad = 0;  // from +x
};
struct SweepFinish {
  long first_index = 0, second_index = 0;  // along the first and second axis (0 with one)
  Eigen::Vector2d cue_final_m = Eigen::Vector2d::Zero();
  bool cue_pocketed = false, object_pocketed = false;
  std::optional<FinishSpread> spread;
};
struct SweepMap {
  std::vector<SweepAxisRange> axes;  // one or two
  std::vector<SweepFinish> finishes;
  int noise_samples = 0;
};

class Drawing {
 public:
  virtual ~Drawing() = default;
  // `baize simulate`'s picture flags: checked before any work (UsageError naming the flag), then
  // the pictures they ask for of a run with trajectories recorded.
  virtual void checkShotPictures(const PictureFlags& flags) const = 0;
  virtual void writeShotPictures(const engine::Scene& scene, const engine::SceneRun& run,
                                 const PictureFlags& flags) const = 0;
  virtual std::unique_ptr<ShotPainter> shotPainter() const = 0;
  // `baize sweep --png`: the position map of the finishes on the scene's table.
  virtual void writePositionMap(const engine::Table& table, const SweepMap& map,
                                const std::string& path) const = 0;
  // `baize calibrate --png`: the measured against the fitted rebound speeds.
  virtual void writeCalibrationChart(const engine::CushionCalibration& fit,
                                     const std::string& path) const = 0;
};

// The reason a build without rendering gives for refusing what draws.
constexpr const char* kNoRendering =
    "this baize was built without rendering (BAIZE_WITH_RENDER=OFF), which pictures and charts "
    "need";

// `option` of `command` draws: without a Drawing it is refused when given (a UsageError naming
// the command and the flag) and its help says so; with one it is left as it is. Returns `option`.
CLI::Option* needsDrawing(const CLI::App& command, CLI::Option* option, const Drawing* drawing);

}  // namespace baize::tools
