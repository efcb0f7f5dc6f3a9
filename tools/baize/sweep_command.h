// `baize sweep SCENE.json --vary NAME=START:STOP:STEP [--vary ...] [--csv OUT] [--object ID]`:
// simulates the scene's shot over a grid of one or two shot parameters and writes the outcomes as
// CSV, and with --png the position map (docs/positional.md, "Position maps").
#pragma once

namespace CLI {
class App;
}

namespace baize::tools {

class Drawing;

// `drawing` makes its pictures; null in a build without rendering (picture_commands.h).
void addSweepCommand(CLI::App& parent, const Drawing* drawing);

}  // namespace baize::tools
