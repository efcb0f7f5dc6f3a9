// Racks: the starting positions of the balls for a game, placed on a table by name.
//
// Racked balls are "frozen" (touching their neighbours) up to a tiny gap: centres of neighbours are
// exactly 2R + gap apart. Exact contact (distance 2R) would leave it to rounding whether two balls
// overlap, touch or are apart, and the event loop would have to guess whether a collision is due
// at t = 0; a gap far below any measurable distance removes that ambiguity while the break still
// sees a frozen rack.
#pragma once

#include <Eigen/Core>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "engine/io/ball_set.h"
#include "engine/io/table.h"

namespace baize::engine {

// Default centre-to-centre gap between frozen neighbours beyond 2R, m: far below cloth and ball
// tolerances (~1e-5 m), far above the rounding of table coordinates (~1e-15 m).
constexpr double kFrozenGap_m = 1e-7;
// Largest gap accepted, m: beyond a millimetre the balls are no longer a frozen rack.
constexpr double kMaxGap_m = 1e-3;
// Largest jitter radius accepted, m: the gap that keeps a rack jittered by it from overlapping
// (jitteredRackGap_m) reaches kMaxGap_m.
constexpr double kMaxJitterRadius_m = kMaxGap_m / 2;

// The tightest gap that a rack jittered by `jitter_radius_m` (in [0, kMaxJitterRadius_m]) can have:
// two neighbours move towards each other by at most twice the radius, so max(kFrozenGap_m, 2 x
// radius) keeps them at least 2R apart (the frozen gap itself for radii up to half of it).
double jitteredRackGap_m(double jitter_radius_m);

struct RackOptions {
  double gap_m = kFrozenGap_m;  // in (0, kMaxGap_m]
  // With a seed, every ball of the triangle or diamond moves by a random vector of length at most
  // jitter_radius_m, which must lie in [0, gap_m / 2]: neighbours then stay at least 2R apart.
  std::optional<std::uint64_t> jitter_seed;
  double jitter_radius_m = 0;
};

struct PlacedBall {
  std::string id;                                        // the ball set's id
  Eigen::Vector2d position_m = Eigen::Vector2d::Zero();  // table frame
};

// The known racks: "8-ball", "9-ball", "10-ball" (pool tables), "snooker" (snooker tables).
std::vector<std::string> rackNames();

// Places the named rack with the cue ball at its default position: pool on the head spot (the
// centre of the head string), snooker in the D half its radius behind the brown spot. Throws
// std::invalid_argument for an unknown name, a rack for the other kind of table, a ball set
// without the balls the rack needs, bad options, or a rack that does not fit on the table.
// The cue ball comes first; the rest follow rack order (see docs/tables.md).
std::vector<PlacedBall> placeRack(const std::string& rack_name, const Table& table,
                                  const BallSet& balls, const RackOptions& options = {});

}  // namespace baize::engine
