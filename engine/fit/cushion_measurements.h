// Measured cushion impacts, read from a CSV file (docs/calibrate.md): one row per impact with the
// incoming ball as `baize cushion` takes it and the rebound measured.
//
//   speed_mps,angle_deg,topspin,sidespin,rebound_speed_mps,rebound_angle_deg
//
// topspin, sidespin (in units of V0/R) and rebound_angle_deg are optional columns; without topspin
// the ball rolls (1), without sidespin it has none, and an empty rebound_angle_deg field means the
// angle of that impact was not measured.
#pragma once

#include <optional>
#include <string>
#include <vector>

namespace baize::engine {

struct CushionMeasurement {
  int line = 0;                // in the file, for messages
  double speed_mps = 0;        // V0
  double angle_deg = 90;       // alpha, from the cushion line, 90 head-on
  double topspin_k = 1;        // w_T R / V0
  double sidespin_k = 0;       // w_S R / V0
  double rebound_speed_mps = 0;
  std::optional<double> rebound_angle_deg;  // from the cushion line, 90 straight back
};

// Reads and checks the file. Throws std::invalid_argument naming the file, the line and the column
// for a missing column, a field that is not a number, a speed that is not > 0, an angle outside
// (0, 180), and a rebound no impact can give: a rebound speed that is not > 0 or that would need
// more energy than the incoming ball carries (speed and spin together).
std::vector<CushionMeasurement> readCushionMeasurements(const std::string& path);

}  // namespace baize::engine
