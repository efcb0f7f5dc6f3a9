#include "tools/baize/drawing.h"

#include <CLI/CLI.hpp>

#include "tools/baize/cli_errors.h"
#include "tools/baize/command_lookup.h"

namespace baize::tools {

CLI::Option* needsDrawing(const CLI::App& command, CLI::Option* option, const Drawing* drawing) {
  if (drawing != nullptr) return option;
  const std::string refusal =
      "'" + commandPath(command) + " " + option->get_name() + "' draws, and " + kNoRendering;
  option->description(option->get_description() + " [not in this build: BAIZE_WITH_RENDER=OFF]");
  // The check runs as the command line is read, before the command's own callback does any work.
  option->check(CLI::Validator(
      [refusal](const std::string&) -> std::string { throw UsageError(refusal); }, ""));
  return option;
}

}  // namespace baize::tools
