// simulate(): one shot from its start to rest through the event loop
// (engine/sim/shot_simulation.h), the call most programs need. This header brings the whole
// simulation API: the parameters, the table geometry, the input checks, the events and results, and
// the steppable loop itself.
#pragma once

#include <string>
#include <vector>

#include "engine/sim/contact_geometry.h"
#include "engine/sim/shot_events.h"
#include "engine/sim/shot_simulation.h"
#include "engine/sim/simulation_input.h"
#include "engine/sim/simulation_params.h"
#include "engine/sim/table_geometry.h"

namespace baize::engine {

class CushionImpactWorker;  // engine/sim/cushion_impact_worker.h

// Simulates until every ball is at rest or pocketed. Throws std::invalid_argument on invalid input
// (parameters, a non-finite state, overlapping balls, a ball off the table, `ball_ids` neither
// empty nor one per ball), std::runtime_error when the shot needs more than max_events events and
// BallLeftTableError when a ball leaves the table. Messages name balls as
// validateSimulationInput() does. `worker`: see ShotSimulation.
SimulationResult simulate(const SimulationParams& params, const TableGeometry& table,
                          const std::vector<physics::BallState>& balls,
                          const std::vector<std::string>& ball_ids = {},
                          CushionImpactWorker* worker = nullptr);

}  // namespace baize::engine
