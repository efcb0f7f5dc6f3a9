// The data behind the Mathavan 2010 paper's figures 6, 7, 8 and 10, as CSV files for later charts:
//   fig6.csv   rebound speed and angle against alpha for several speeds, rolling, no side;
//   fig7.csv   the same for several topspins at V0 = 1 m/s, no side;
//   fig8.csv   the same for several sidespins at V0 = 1 m/s, rolling;
//   fig10.csv  slip speeds and directions at the cushion and the cloth against the impulse P for
//              V0 = 2 m/s, alpha = 45 deg, w_S = 2 V0/R, w_T = 1.5 V0/R.
// Families 6-8 sweep alpha = 1, 2, ..., 179 deg (the paper plots 0-90; past 90 sidespin breaks the
// mirror symmetry, so the whole range is kept). docs/cushion.md lists the columns.
#pragma once

#include <string>
#include <vector>

#include "physics/cushion_model.h"
#include "tools/baize/cushion_run.h"

namespace baize::tools {

// Writes the four files into `directory` (created if missing), each atomically; returns their
// paths. Throws std::runtime_error when a file cannot be written.
std::vector<std::string> writeCushionSweep(const std::string& directory,
                                           const physics::CushionParams& params,
                                           const SolverSetting& setting);

}  // namespace baize::tools
