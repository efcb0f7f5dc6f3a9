#include "tools/baize/drawing.h"

#include <CLI/CLI.hpp>

#include "tools/baize/cli_errors.h"

namespace baize::tools {

std::string commandPath(const CLI::App& command) {
  std::string path = command.get_name();
  for (const CLI::App* parent = command.get_parent(); parent; parent = parent->get_parent()) {
    path = parent->get_name() + " " + path;
  }
  return path;
}

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
