// `baize bench play`: how well the game player plays (docs/games.md): over seeded frames at a few
// execution-noise levels, the 9-ball (or 10-, 8-ball) run-out rate from the break or the snooker
// mean break, each with its 95 % interval, and the time per shot decision on one core.
#pragma once

namespace CLI {
class App;
}

namespace baize::tools {

void addBenchPlayCommand(CLI::App& bench);

}  // namespace baize::tools
