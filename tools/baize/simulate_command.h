// `baize simulate SCENE.json [--json OUT.json]`: strikes the scene's cue ball, simulates the shot to
// rest on its table and prints what happened (docs/scenes.md).
#pragma once

namespace CLI {
class App;
}

namespace baize::tools {

class Drawing;

// `drawing` makes its pictures; null in a build without rendering (picture_commands.h).
void addSimulateCommand(CLI::App& parent, const Drawing* drawing);

}  // namespace baize::tools
