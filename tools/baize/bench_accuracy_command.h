// `baize bench accuracy [--csv FILE] [--shots N] [--repeat N]`: run time against error for whole
// shots. A fixed, seeded set of shots is simulated by the event loop (the reference), by the
// fixed-step integrator of the same physics (engine/baselines/fixed_step_simulator.h) at dt = 10 ms
// to 10 us, and by the Box2D baseline (engine/baselines/box2d_pool.h) at dt = 1/60 s to 100 us;
// each configuration gets its median wall time per shot and its error against the reference.
#pragma once

namespace CLI {
class App;
}

namespace baize::tools {

void addBenchAccuracyCommand(CLI::App& parent);

}  // namespace baize::tools
