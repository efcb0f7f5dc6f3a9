// The picture flags shared by `baize render` and `baize simulate` (--png, --png-dir, --gif,
// --width, --height, --view, --legend, --at, --fps): what they ask for, and their registration. The
// drawing they ask for is the renderer's (pictures/shot_pictures.h).
#pragma once

#include <optional>
#include <string>
#include <vector>

namespace CLI {
class App;
class Option;
}

namespace baize::tools {

class Drawing;

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

// Adds the flags to `command`; without a Drawing (a build without rendering) each is refused when
// given (drawing.h, needsDrawing).
void addPictureFlags(CLI::App& command, PictureFlags& flags, const Drawing* drawing);

}  // namespace baize::tools
