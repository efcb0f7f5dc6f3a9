// `baize plan SCENE.json --ball N --pocket P [--region ...] [--budget K] [--noise-samples S]
// [--seed S] [--png OUT.png] [--compare-grid]`: searches the shot most likely, under execution
// error, to pot ball N in pocket P and leave the cue ball in the region (docs/positional.md,
// "Shot planning").
#pragma once

namespace CLI {
class App;
}

namespace baize::tools {

class Drawing;

// `drawing` makes its pictures; null in a build without rendering (picture_commands.h).
void addPlanCommand(CLI::App& parent, const Drawing* drawing);

}  // namespace baize::tools
