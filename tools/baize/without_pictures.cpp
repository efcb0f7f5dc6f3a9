// picture_commands.h in a build without rendering (BAIZE_WITH_RENDER=OFF): the commands that only
// draw keep their names, so that typing one says why it is missing rather than that it is unknown.
#include <CLI/CLI.hpp>

#include "tools/baize/cli_errors.h"
#include "tools/baize/command_lookup.h"
#include "tools/baize/drawing.h"
#include "tools/baize/picture_commands.h"

namespace baize::tools {
namespace {

void refuseDrawingCommand(CLI::App& parent, const std::string& name) {
  addRefusedCommand(parent, name, "not in this build: it draws (BAIZE_WITH_RENDER=OFF)",
                    std::string("draws, and ") + kNoRendering);
}

}  // namespace

void addRenderCommand(CLI::App& parent) { refuseDrawingCommand(parent, "render"); }
void addChartCommand(CLI::App& parent) { refuseDrawingCommand(parent, "chart"); }
void addBenchRenderCommand(CLI::App& bench) { refuseDrawingCommand(bench, "render"); }

const Drawing* renderedDrawing() { return nullptr; }

}  // namespace baize::tools
