#include "tools/baize/pictures/overlay_pictures.h"

#include <cstdio>
#include <filesystem>

#include "render/camera.h"
#include "render/gl_renderer.h"
#include "render/osmesa_context.h"
#include "render/overlay_items.h"
#include "render/png_writer.h"
#include "render/shot_picture.h"
#include "render/shot_record.h"
#include "tools/baize/cli_errors.h"

namespace baize::tools {

render::Rgba regionColour() { return {1.0f, 0.2f, 0.85f, 1}; }

void addRegion(render::Picture& picture, const engine::Scene& scene,
               const engine::ShotOutcome& outcome, const engine::CueBallRegion& region,
               double pixel_size_m) {
  const double width_m = kRegionLine_px * pixel_size_m;
  switch (region.kind) {
    case engine::CueBallRegion::Kind::Circle:
      picture.items.push_back(
          render::circleOutline(region.centre_m, region.radius_m, width_m, regionColour()));
      return;
    case engine::CueBallRegion::Kind::Rectangle:
      picture.items.push_back(
          render::rectangleOutline(region.min_m, region.max_m, width_m, regionColour()));
      return;
    case engine::CueBallRegion::Kind::StraightShot: {
      const engine::FinalBall* object = outcome.ball(region.ball);
      if (object == nullptr || object->pocketed) return;  // nothing left to aim at
      const double r = scene.ball_set.radius_m;
      const Eigen::Vector2d mouth = scene.table.pockets[region.pocket].mouth_centre_m;
      const Eigen::Vector2d ghost =
          object->position_m - 2 * r * (mouth - object->position_m).normalized();
      picture.items.push_back(render::circleOutline(ghost, r, width_m, regionColour()));
      picture.items.push_back(render::segment(object->position_m, mouth, width_m, regionColour()));
      if (!outcome.cue_ball_pocketed) {
        picture.items.push_back(
            render::segment(outcome.cue_ball_final_m, ghost, width_m, regionColour()));
      }
      return;
    }
  }
}

render::Picture shotPicture(const engine::Scene& scene, const engine::SceneRun& run,
                            double pixel_size_m) {
  render::PictureOptions options;
  options.pixel_size_m = pixel_size_m;
  return render::buildShotPicture(render::shotRecordOf(scene, run), options);
}

struct PngPainter::Gl {
  render::OsmesaContext context;
  render::GlRenderer renderer{context};
};

PngPainter::PngPainter() : gl_(std::make_unique<Gl>()) {}
PngPainter::~PngPainter() = default;

void PngPainter::write(const render::Picture& picture, const std::string& path) {
  gl_->renderer.draw(
      picture, render::cameraFor(picture, render::View::Top, kOverlayWidth_px, kOverlayHeight_px));
  render::writePng(gl_->renderer.readImage(), path);
}

}  // namespace baize::tools
