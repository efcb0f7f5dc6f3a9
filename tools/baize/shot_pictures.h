// The picture flags shared by `baize render` and `baize simulate` (--png, --png-dir, --gif,
// --width, --height, --view, --legend, --at, --fps) and writing the pictures they ask for: one PNG
// of the shot at a time (the end by default), numbered PNG frames of it in real time, and/or an
// animated GIF of the same frames.
#pragma once

#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "render/shot_record.h"

namespace CLI {
class App;
class Option;
}

namespace baize::tools {

struct PictureFlags {
  std::string png_path;
  int width_px = 1600;
  int height_px = 800;
  std::string view = "top";
  bool legend = false;
  std::optional<double> at_s;  // draw the balls at this time (default: the end of the shot)
  std::string frames_dir;      // numbered frames frame_00000.png ... when set (--png-dir)
  std::string gif_path;        // the animation, when set
  double fps = 30;
  // The parser's options, to tell a flag given from its default: each of these is refused
  // without the output it shapes.
  std::vector<const CLI::Option*> shaping_options;  // --width ... --legend: any picture output
  const CLI::Option* fps_option = nullptr;          // --png-dir or --gif
  const CLI::Option* at_option = nullptr;           // --png

  bool animated() const { return !frames_dir.empty() || !gif_path.empty(); }
  bool wanted() const { return !png_path.empty() || animated(); }
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
