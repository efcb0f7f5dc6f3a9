#include "tools/baize/pictures/shot_pictures.h"

#include <CLI/CLI.hpp>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <functional>
#include <optional>
#include <iomanip>
#include <iostream>
#include <sstream>

#include "render/camera.h"
#include "render/gif_writer.h"
#include "render/gl_renderer.h"
#include "render/osmesa_context.h"
#include "render/png_writer.h"
#include "render/shot_picture.h"
#include "tools/baize/atomic_file.h"
#include "tools/baize/cli_errors.h"
#include "tools/baize/output_folder.h"
#include "tools/baize/progress.h"

namespace baize::tools {
namespace {

const OutputFileNames kFrameNames{"frame_", ".png"};

std::string frameName(long index) {
  std::ostringstream name;
  name << "frame_" << std::setw(5) << std::setfill('0') << index << ".png";
  return name.str();
}

// A flag that would do nothing is refused: whoever gives it expects it to matter.
void refuseUnusedFlags(const PictureFlags& flags) {
  for (const CLI::Option* option : flags.shaping_options) {
    if (option->count() > 0 && !flags.wanted()) {
      throw UsageError(option->get_name() + " shapes a picture: give --png, --png-dir or --gif");
    }
  }
  if (flags.fps_option->count() > 0 && !flags.animated()) {
    throw UsageError("--fps sets the frame rate of --png-dir and --gif: give one of them");
  }
  if (flags.at_option->count() > 0 && flags.png_path.empty()) {
    throw UsageError("--at sets the time of the one picture of --png: give --png");
  }
}

}  // namespace

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
    throw UsageError("--view " + flags.view + " is not allowed: it must be top or angled");
  }
  if (flags.at_s) {
    requireFiniteFlag("--at", *flags.at_s);
    if (*flags.at_s < 0) rejectFlag("--at", *flags.at_s, "it must be >= 0 s");
  }
  requireFiniteFlag("--fps", flags.fps);
  if (!(flags.fps > 0 && flags.fps <= render::kMaxGifFps)) {
    rejectFlag("--fps", flags.fps, "it must lie in (0, 100] frames per second");
  }
  refuseUnusedFlags(flags);
  if (!flags.png_path.empty()) checkOutputPath("--png", flags.png_path);
  if (!flags.gif_path.empty()) checkOutputPath("--gif", flags.gif_path);
  if (!flags.frames_dir.empty()) prepareOutputFolder("--png-dir", flags.frames_dir, kFrameNames);
}

namespace {

// The shot in real time, one frame per 1/fps s and one at rest, as numbered PNGs and/or a GIF.
void writeFrames(const render::ShotRecord& shot, const PictureFlags& flags,
                 const std::function<render::Image(double)>& draw) {
  const double frames = std::ceil(shot.end_time_s * flags.fps);
  if (frames + 1 > kMaxFrames) {
    rejectFlag("--fps", flags.fps,
               "the shot lasts " + std::to_string(shot.end_time_s) +
                   " s, which would make more than " + std::to_string(kMaxFrames) + " frames");
  }
  const long count = static_cast<long>(frames) + 1;  // the last frame shows the shot at rest
  std::optional<render::GifWriter> gif;
  if (!flags.gif_path.empty()) gif.emplace(flags.width_px, flags.height_px, flags.fps);
  Progress progress("frames", count);
  for (long k = 0; k < count; ++k) {
    const render::Image image = draw(std::min(static_cast<double>(k) / flags.fps, shot.end_time_s));
    if (!flags.frames_dir.empty()) {
      render::writePng(image, (std::filesystem::path(flags.frames_dir) / frameName(k)).string());
    }
    if (gif) gif->addFrame(image);
    progress.advance();
  }
  if (!flags.frames_dir.empty()) {
    note(std::cout) << "frames: " << count << " in " << flags.frames_dir << " (" << flags.fps
                    << " per second, " << frameName(0) << " to " << frameName(count - 1) << ")\n";
  }
  if (gif) {
    gif->finish(flags.gif_path);
    note(std::cout) << "animation: " << flags.gif_path << " (" << count << " frames, "
                    << flags.width_px << " x " << flags.height_px << " px, " << flags.fps
                    << " per second)\n";
  }
}

}  // namespace

void writePictures(const render::ShotRecord& shot, const PictureFlags& flags) {
  render::OsmesaContext context;
  render::GlRenderer renderer(context);
  const render::View view = render::viewNamed(flags.view);
  render::PictureOptions options;
  options.pixel_size_m = render::pixelSizeFor(shot.table, flags.width_px, flags.height_px);
  options.legend = flags.legend;
  const auto draw = [&](double time_s) {
    options.time_s = time_s;
    const render::Picture picture = render::buildShotPicture(shot, options);
    renderer.draw(picture, render::cameraFor(picture, view, flags.width_px, flags.height_px));
    return renderer.readImage();
  };
  if (!flags.png_path.empty()) {
    render::writePng(draw(flags.at_s.value_or(shot.end_time_s)), flags.png_path);
    note(std::cout) << "picture: " << flags.png_path << " (" << flags.width_px << " x "
                    << flags.height_px << " px, " << flags.view << " view)\n";
  }
  if (flags.animated()) writeFrames(shot, flags, draw);
}

}  // namespace baize::tools
