// Execution error: a player never strikes exactly the shot intended. Each sample perturbs the tip
// offsets, elevation, aim and speed by independent Gaussian errors (physics-notes section 4, the
// noise model of computational pool tournaments). The generator is seeded and written out here
// (Box-Muller on std::mt19937_64's bits, whose sequence the C++ standard fixes), because
// std::normal_distribution may differ between standard libraries: the same seed gives the same
// samples everywhere.
#pragma once

#include <cstdint>
#include <random>

#include "physics/cue_strike.h"

namespace baize::engine {

// Standard deviations of the errors. Defaults: physics-notes section 4.
struct ExecutionNoise {
  double tip_offset_sigma_m =
      0.0005;  // on each of the side and height offsets, on the ball's surface
  double elevation_sigma_deg = 0.1;
  double aim_sigma_deg = 0.125;  // heading
  double speed_sigma_mps = 0.075;
};

// Throws std::invalid_argument naming the sigma unless each is finite and >= 0.
void validateExecutionNoise(const ExecutionNoise& noise);

// Normal deviates from a std::mt19937_64 by the Box-Muller transform; both deviates of each pair
// are used, in order.
class NormalGenerator {
 public:
  explicit NormalGenerator(std::uint64_t seed);
  double next();  // mean 0, standard deviation 1

 private:
  double uniformOpenClosed();  // in (0, 1], from the top 53 bits
  std::mt19937_64 bits_;
  double spare_ = 0;
  bool has_spare_ = false;
};

// One draw of the errors, in the shot's own units.
struct ExecutionError {
  double side_offset = 0;    // units of R
  double height_offset = 0;  // units of R
  double elevation_rad = 0;
  double heading_rad = 0;
  double speed_mps = 0;
};

// Draws side, height, elevation, aim and speed errors, in that order.
ExecutionError drawExecutionError(const ExecutionNoise& noise, double ball_radius_m,
                                  NormalGenerator* normal);

// The intended shot with the error added. Elevation cannot go below level (the cue lies on the
// rail or the cloth), so a negative elevation is folded back to its magnitude; a negative speed
// becomes 0 (no strike). The offsets are not clamped: a sample beyond the miscue limit is a miscue,
// which the caller counts (strikeCueBall refuses it).
physics::CueShot perturbedShot(const physics::CueShot& intended, const ExecutionError& error);

// A seed for sample `sample` of case `case_index` under run seed `seed` (SplitMix64 mixing), so
// that each sample's errors depend on nothing but these three numbers.
std::uint64_t sampleSeed(std::uint64_t seed, std::uint64_t case_index, std::uint64_t sample);

}  // namespace baize::engine
