// `baize bench shots [--csv FILE]`: wall time per shot of the shipped scenes and of a seeded set of
// random shots, with their event counts.
#pragma once

namespace CLI {
class App;
}

namespace baize::tools {

void addBenchShotsCommand(CLI::App& parent);

}  // namespace baize::tools
