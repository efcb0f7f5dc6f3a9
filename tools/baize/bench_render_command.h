// `baize bench render`: how long drawing the shipped 9-ball break takes off-screen (OSMesa,
// llvmpipe), median over repeated renders (docs/render.md).
#pragma once

namespace CLI {
class App;
}

namespace baize::tools {

void addBenchRenderCommand(CLI::App& parent);

}  // namespace baize::tools
