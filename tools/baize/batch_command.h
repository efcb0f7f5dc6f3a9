// `baize batch [INPUT] [--threads N]`: shots as JSON lines in, one JSON result line per shot out,
// in input order and identical whatever the thread count (docs/positional.md, "Batch runs").
#pragma once

namespace CLI {
class App;
}

namespace baize::tools {

void addBatchCommand(CLI::App& parent);

}  // namespace baize::tools
