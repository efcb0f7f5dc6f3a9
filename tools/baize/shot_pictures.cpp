#include "tools/baize/shot_pictures.h"

#include <CLI/CLI.hpp>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <iomanip>
#include <iostream>
#include <sstream>

#include "render/camera.h"
#include "render/gl_renderer.h"
#include "render/osmesa_context.h"
#include "render/png_writer.h"
#include "render/shot_picture.h"
#include "tools/baize/atomic_file.h"
#include "tools/baize/cli_errors.h"

namespace baize::tools {
namespace {

// Frame rates allowed, frames per second.
constexpr double kMaxFps = 240;

std::string frameName(long index) {
  std::ostringstream name;
  name << "frame_" << std::setw(5) << std::setfill('0') << index << ".png";
  return name.str();
}

}  // namespace

void addPictureFlags(CLI::App& command, PictureFlags& flags) {
  command.add_option("--png", flags.png_path, "write a picture of the shot here (PNG)")
      ->check(notEmpty());
  command.add_option("--width", flags.width_px, "picture width, px (default 1600)");
  command.add_option("--height", flags.height_px, "picture height, px (default 800)");
  command.add_option("--view", flags.view, "top (default) or angled");
  command.add_flag("--legend", flags.legend,
                   "add a legend: each ball that moves with its speed and spin, and the key");
  command.add_option("--at", flags.at_s,
                     "draw the balls at this time, s, and the traces up to it (default: the end)");
  command
      .add_option("--frames", flags.frames_dir,
                  "write the shot as numbered frames DIR/frame_00000.png ... in real time")
      ->check(notEmpty());
  command.add_option("--fps", flags.fps, "frames per second with --frames (default 30)");
}

void checkPictureFlags(const PictureFlags& flags) {
  if (flags.width_px < render::kMinImageSide_px || flags.width_px > render::kMaxImageSide_px) {
    rejectFlag("--width", flags.width_px,
               "it must lie in [" + std::to_string(render::kMinImageSide_px) + ", " +
                   std::to_string(render::kMaxImageSide_px) + "] px");
  }
  if (flags.height_px < render::kMinImageSide_px || flags.height_px > render::kMaxImageSide_px) {
    rejectFlag("--height", flags.height_px,
               "it must lie in [" + std::to_string(render::kMinImageSide_px) + ", " +
                   std::to_string(render::kMaxImageSide_px) + "] px");
  }
  if (flags.view != "top" && flags.view != "angled") {
    throw UsageError("--view = " + flags.view + " is not allowed: it must be top or angled");
  }
  if (flags.at_s) {
    requireFiniteFlag("--at", *flags.at_s);
    if (*flags.at_s < 0) rejectFlag("--at", *flags.at_s, "it must be >= 0 s");
  }
  requireFiniteFlag("--fps", flags.fps);
  if (!(flags.fps > 0 && flags.fps <= kMaxFps)) {
    rejectFlag("--fps", flags.fps, "it must lie in (0, 240] frames per second");
  }
  if (!flags.png_path.empty()) checkOutputPath("--png", flags.png_path);
  if (!flags.frames_dir.empty()) {
    checkOutputPath("--frames", (std::filesystem::path(flags.frames_dir) / frameName(0)).string());
  }
}

void writePictures(const render::ShotRecord& shot, const PictureFlags& flags) {
  render::OsmesaContext context;
  render::GlRenderer renderer(context);
  const render::View view = render::viewNamed(flags.view);
  render::PictureOptions options;
  options.pixel_size_m = render::pixelSizeFor(shot.table, flags.width_px, flags.height_px);
  options.legend = flags.legend;
  const auto draw = [&](double time_s, const std::string& path) {
    options.time_s = time_s;
    const render::Picture picture = render::buildShotPicture(shot, options);
    renderer.draw(picture, render::cameraFor(picture, view, flags.width_px, flags.height_px));
    render::writePng(renderer.readImage(), path);
  };
  if (!flags.png_path.empty()) {
    draw(flags.at_s.value_or(shot.end_time_s), flags.png_path);
    std::cout << "picture: " << flags.png_path << " (" << flags.width_px << " x " << flags.height_px
              << " px, " << flags.view << " view)\n";
  }
  if (!flags.frames_dir.empty()) {
    const double frames = std::ceil(shot.end_time_s * flags.fps);
    if (frames + 1 > kMaxFrames) {
      rejectFlag("--fps", flags.fps,
                 "the shot lasts " + std::to_string(shot.end_time_s) +
                     " s, which would make more than " + std::to_string(kMaxFrames) + " frames");
    }
    const long count = static_cast<long>(frames) + 1;  // the last frame shows the shot at rest
    for (long k = 0; k < count; ++k) {
      const double t = std::min(static_cast<double>(k) / flags.fps, shot.end_time_s);
      draw(t, (std::filesystem::path(flags.frames_dir) / frameName(k)).string());
    }
    std::cout << "frames: " << count << " in " << flags.frames_dir << " (" << flags.fps
              << " per second, " << frameName(0) << " to " << frameName(count - 1) << ")\n";
  }
}

}  // namespace baize::tools
