// `baize stress`: many seeded shots through the event loop (state shots on a pocketless table and
// the 9 ft pool table, cue shots and balls in pocket mouths on the 9 ft pool and 12 ft snooker
// tables: engine/play/stress_shots.h), each checked at every event (engine/play/stress_checks.h).
// Runs on any number of threads with the same results, within an optional time budget; prints a
// summary and writes a reproduction of each failing shot (a scene file, or a state file that
// `baize stress --replay` checks); exits 1 on any failure.
#pragma once

namespace CLI {
class App;
}

namespace baize::tools {

void addStressCommand(CLI::App& parent);

}  // namespace baize::tools
