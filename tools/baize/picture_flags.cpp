#include "tools/baize/picture_flags.h"

#include <CLI/CLI.hpp>

#include "tools/baize/cli_errors.h"
#include "tools/baize/drawing.h"

namespace baize::tools {

void addPictureFlags(CLI::App& command, PictureFlags& flags, const Drawing* drawing) {
  const auto drawn = [&](CLI::Option* option) { return needsDrawing(command, option, drawing); };
  drawn(command.add_option("--png", flags.png_path,
                           "write a picture of the shot here (PNG; -: standard output)"))
      ->check(notEmpty());
  drawn(command
            .add_option("--png-dir", flags.frames_dir,
                        "write the shot as numbered frames DIR/frame_00000.png ... in real time"))
      ->check(notEmpty());
  drawn(command.add_option("--gif", flags.gif_path,
                           "write the shot as an animated GIF here, in real time"))
      ->check(notEmpty());
  flags.fps_option = drawn(
      command.add_option("--fps", flags.fps, "frames per second of --png-dir and --gif (default 30)"));
  flags.shaping_options = {
      drawn(command.add_option("--width", flags.width_px, "picture width, px (default 1600)")),
      drawn(command.add_option("--height", flags.height_px, "picture height, px (default 800)")),
      drawn(command.add_option("--view", flags.view, "top (default) or angled")),
      drawn(command.add_flag("--legend", flags.legend,
                             "add a legend: each ball that moves with its speed and spin, and the key"))};
  flags.at_option = drawn(command.add_option(
      "--at", flags.at_s,
      "with --png: draw the balls at this time, s, and the traces up to it (default: the end)"));
}

}  // namespace baize::tools
