#include "tools/baize/picture_commands.h"

#include <CLI/CLI.hpp>
#include <memory>

#include "render/shot_record.h"
#include "tools/baize/cli_errors.h"
#include "tools/baize/pictures/shot_pictures.h"

namespace baize::tools {
namespace {

struct RenderFlags {
  std::string input;
  PictureFlags pictures;
};

void runRender(const RenderFlags& flags) {
  if (!flags.pictures.wanted()) {
    throw UsageError("nothing to write: give --png FILE, --png-dir DIR or --gif FILE");
  }
  checkPictureFlags(flags.pictures);
  writePictures(render::loadShotRecord(flags.input), flags.pictures);
}

}  // namespace

void addRenderCommand(CLI::App& parent) {
  auto flags = std::make_shared<RenderFlags>();
  CLI::App* command =
      parent.add_subcommand("render", "Draw a shot (a scene or a result file) as a PNG picture, numbered PNG frames or an animated GIF");
  command
      ->add_option("input", flags->input,
                   "a scene file (docs/scenes.md) or a result file of 'baize simulate --json' or "
                   "'baize batch' (docs/results.md)")
      ->required();
  addPictureFlags(*command, flags->pictures, renderedDrawing());
  command->callback([flags] {
    if (const int status = runReportingErrors("render", [&] { runRender(*flags); })) {
      throw CLI::RuntimeError(status);
    }
  });
}

}  // namespace baize::tools
