// picture_commands.h in a build without rendering (BAIZE_WITH_RENDER=OFF): the commands that only
// draw keep their names, so that typing one says why it is missing rather than that it is unknown.
#include <CLI/CLI.hpp>

#include "tools/baize/cli_errors.h"
#include "tools/baize/command_lookup.h"
#include "tools/baize/drawing.h"
#include "tools/baize/picture_commands.h"

namespace baize::tools {
namespace {

// A command that takes any words and refuses them all, naming itself, before any work.
void addRefusedCommand(CLI::App& parent, const std::string& name) {
  CLI::App* command =
      parent.add_subcommand(name, "not in this build: it draws (BAIZE_WITH_RENDER=OFF)");
  command->prefix_command();  // every word after the name is left unread
  command->set_help_flag();   // --help included: it is refused as the rest
  command->callback([command] {
    throw UsageError("'" + commandPath(*command) + "' draws, and " + kNoRendering);
  });
}

}  // namespace

void addRenderCommand(CLI::App& parent) { addRefusedCommand(parent, "render"); }
void addChartCommand(CLI::App& parent) { addRefusedCommand(parent, "chart"); }
void addBenchRenderCommand(CLI::App& bench) { addRefusedCommand(bench, "render"); }

const Drawing* renderedDrawing() { return nullptr; }

}  // namespace baize::tools
