// The picture flags shared by `baize render` and `baize simulate` (--png, --width, --height,
// --view, --legend, --at, --frames, --fps) and writing the pictures they ask for: one PNG of the
// shot at a time (the end by default) and/or numbered PNG frames of it in real time.
#pragma once

#include <memory>
#include <optional>
#include <string>

#include "render/shot_record.h"

namespace CLI {
class App;
}

namespace baize::tools {

struct PictureFlags {
  std::string png_path;
  int width_px = 1600;
  int height_px = 800;
  std::string view = "top";
  bool legend = false;
  std::optional<double> at_s;  // draw the balls at this time (default: the end of the shot)
  std::string frames_dir;      // numbered frames frame_00000.png ... when set
  double fps = 30;

  bool wanted() const { return !png_path.empty() || !frames_dir.empty(); }
};

// The most frames one command writes (an hour at 30 frames a second would be far beyond any shot).
constexpr long kMaxFrames = 20000;

void addPictureFlags(CLI::App& command, PictureFlags& flags);

// Checks every flag and that the outputs can be created (making missing parent folders), before
// any simulation or drawing; throws UsageError naming the flag otherwise.
void checkPictureFlags(const PictureFlags& flags);

// Draws and writes what the flags ask for; prints one line per file (frames: one line in all).
void writePictures(const render::ShotRecord& shot, const PictureFlags& flags);

}  // namespace baize::tools
