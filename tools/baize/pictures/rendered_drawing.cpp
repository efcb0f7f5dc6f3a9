// The renderer's Drawing (tools/baize/drawing.h): what a build with rendering hands the commands.
#include <algorithm>
#include <memory>

#include "render/position_map.h"
#include "render/shot_picture.h"
#include "render/shot_record.h"
#include "tools/baize/drawing.h"
#include "tools/baize/picture_commands.h"
#include "tools/baize/pictures/calibration_chart.h"
#include "tools/baize/pictures/overlay_pictures.h"
#include "tools/baize/pictures/shot_pictures.h"

namespace baize::tools {
namespace {

class OverlayShotPainter : public ShotPainter {
 public:
  void write(const engine::Scene& scene, const engine::SceneRun& run,
             const std::vector<engine::CueBallRegion>& regions, const std::string& path) override {
    const double pixel_m =
        render::pixelSizeFor(scene.table, kOverlayWidth_px, kOverlayHeight_px);
    render::Picture picture = shotPicture(scene, run, pixel_m);
    if (!regions.empty()) {
      const engine::ShotOutcome outcome = engine::shotOutcome(run, scene.cue_ball);
      for (const engine::CueBallRegion& region : regions) {
        addRegion(picture, scene, outcome, region, pixel_m);
      }
    }
    painter_.write(picture, path);
  }

 private:
  PngPainter painter_;
};

// A grid index's place along its axis, [0, 1] (0.5 for an axis of one point).
double fraction(const SweepAxisRange& axis, long i) {
  return axis.count > 1 ? static_cast<double>(i) / static_cast<double>(axis.count - 1) : 0.5;
}

render::MapPoint mapPoint(const SweepMap& map, const SweepFinish& finish) {
  render::MapPoint p;
  p.position_m = finish.cue_final_m;
  p.outcome = finish.cue_pocketed      ? render::MapOutcome::CueBallPocketed
              : finish.object_pocketed ? render::MapOutcome::ObjectPocketed
                                       : render::MapOutcome::Missed;
  p.colour_fraction = fraction(map.axes[0], finish.first_index);
  if (map.axes.size() == 2) p.size_fraction = fraction(map.axes[1], finish.second_index);
  if (finish.spread) {
    const FinishSpread& s = *finish.spread;
    p.spread = render::SpreadEllipse{s.mean_m, s.sd_major_m, s.sd_minor_m, s.major_axis_rad};
  }
  return p;
}

class RenderedDrawing : public Drawing {
 public:
  void checkShotPictures(const PictureFlags& flags) const override { checkPictureFlags(flags); }

  void writeShotPictures(const engine::Scene& scene, const engine::SceneRun& run,
                         const PictureFlags& flags) const override {
    writePictures(render::shotRecordOf(scene, run), flags);
  }

  std::unique_ptr<ShotPainter> shotPainter() const override {
    return std::make_unique<OverlayShotPainter>();
  }

  void writePositionMap(const engine::Table& table, const SweepMap& map,
                        const std::string& path) const override {
    std::vector<render::MapPoint> points;
    for (const SweepFinish& finish : map.finishes) points.push_back(mapPoint(map, finish));
    std::vector<render::MapAxis> axes;
    for (const SweepAxisRange& a : map.axes) axes.push_back({a.name, a.first, a.last});
    const double pixel_m = render::pixelSizeFor(table, kOverlayWidth_px, kOverlayHeight_px);
    PngPainter().write(render::buildPositionMap(table, points, axes, pixel_m, map.noise_samples),
                       path);
  }

  void writeCalibrationChart(const engine::CushionCalibration& fit,
                             const std::string& path) const override {
    tools::writeCalibrationChart(fit, path);
  }
};

}  // namespace

const Drawing* renderedDrawing() {
  static const RenderedDrawing drawing;
  return &drawing;
}

}  // namespace baize::tools
