#include "engine/sim/shot_simulator.h"

namespace baize::engine {

SimulationResult simulate(const SimulationParams& params, const TableGeometry& table,
                          const std::vector<physics::BallState>& balls,
                          const std::vector<std::string>& ball_ids, CushionImpactWorker* worker) {
  return ShotSimulation(params, table, balls, ball_ids, worker).runToRest();
}

}  // namespace baize::engine
