// `baize stress`: many seeded random shots through the event loop, each checked at every event for
// finite values, overlapping balls, balls beyond a cushion, kinetic energy growing and shots that
// never come to rest. Prints a summary and a copy-pasteable JSON reproduction of each failing shot;
// exits 1 on any failure.
#pragma once

namespace CLI {
class App;
}

namespace baize::tools {

void addStressCommand(CLI::App& parent);

}  // namespace baize::tools
