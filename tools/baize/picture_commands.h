// The part of baize that draws, and the one choice of whether it is there: tools/CMakeLists.txt
// links either tools/baize/pictures/ (BAIZE_WITH_RENDER=ON: these commands, and the renderer's
// Drawing for the other commands' picture flags) or without_pictures.cpp (a core build: the same
// commands registered only to refuse by name, and no Drawing, so every picture flag refuses itself).
#pragma once

namespace CLI {
class App;
}

namespace baize::tools {

class Drawing;

// `baize render SCENE_OR_RESULT.json --png OUT.png`: draws a shot (a scene, simulated now, or a
// result written by `baize simulate --json`) as a PNG picture, numbered frames or a GIF
// (docs/render.md).
void addRenderCommand(CLI::App& parent);

// `baize chart`: PNG charts of the cushion model's CSV outputs (render/line_chart, Cairo):
//   baize chart sweep DIR                      the figure families of `baize cushion --sweep DIR`
//   baize chart bench-cushion CSV --png OUT    time against error from `baize bench cushion --csv`
// Reading CSV files rather than rerunning the model keeps a chart reproducible from the table it
// shows. docs/cushion.md describes the charts.
void addChartCommand(CLI::App& parent);

// `baize bench render`: how long drawing the shipped 9-ball break takes off-screen (OSMesa,
// llvmpipe), median over repeated renders (docs/render.md).
void addBenchRenderCommand(CLI::App& bench);

// What the other commands draw with; null in a build without rendering.
const Drawing* renderedDrawing();

}  // namespace baize::tools
