// `baize cushion`: one ball-cushion impact (or, with --sweep DIR, the paper's figure families as
// CSV files) from flags in the paper's terms. See docs/cushion.md for the frame and the outputs.
#pragma once

namespace CLI {
class App;
}

namespace baize::tools {

void addCushionCommand(CLI::App& parent);

}  // namespace baize::tools
