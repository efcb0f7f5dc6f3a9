#include "engine/sim/simulation_params.h"

namespace baize::engine {

SimulationParams poolSimulationParams() {
  SimulationParams p;
  p.cushion.mass_kg = 0.17;
  p.cushion.radius_m = 0.028575;
  p.cushion.contact_height_m = 0.635 * 2 * p.cushion.radius_m;
  p.cushion.cloth_friction = p.cloth.sliding_friction;
  return p;
}

}  // namespace baize::engine
