// `baize render SCENE_OR_RESULT.json --png OUT.png`: draws a shot (a scene, simulated now, or a
// result written by `baize simulate --json`) as a PNG picture or numbered frames (docs/render.md).
#pragma once

namespace CLI {
class App;
}

namespace baize::tools {

void addRenderCommand(CLI::App& parent);

}  // namespace baize::tools
