// Putting balls back on the table: pool balls on the foot spot or the long string behind it, snooker
// colours on their own spot, the highest free one, or the nearest free point towards the top
// cushion (docs/games.md cites the rules). A spot is free when a ball placed there would touch no
// other ball.
#pragma once

#include <Eigen/Core>
#include <optional>
#include <string>
#include <vector>

#include "engine/io/rack.h"
#include "engine/io/table.h"

namespace baize::engine {

// Room kept between a spotted ball and its neighbours beyond 2R, m: the racks' frozen gap, so
// that a spotted ball frozen to another is apart by an amount the event loop never rounds away.
constexpr double kSpotGap_m = kFrozenGap_m;

// Whether a ball of radius `radius_m` at `point_m` would lie on the playing surface and touch none
// of `balls`.
bool spotFree(const std::vector<PlacedBall>& balls, const Eigen::Vector2d& point_m,
              const Table& table, double radius_m);

// The free point on the line from `start_m` along the unit `direction` nearest to the start, the
// start itself when free; nothing when the line has no free point on the playing surface.
std::optional<Eigen::Vector2d> nearestFreeOnLine(const std::vector<PlacedBall>& balls,
                                                 const Eigen::Vector2d& start_m,
                                                 const Eigen::Vector2d& direction,
                                                 const Table& table, double radius_m);

// Pool (WPA General Rules, spotting balls): on the foot spot, else as near to it as possible on
// the long string towards the foot cushion, else towards the head. Adds the ball to `balls`.
void spotPoolBall(const std::string& id, std::vector<PlacedBall>* balls, const Table& table,
                  double radius_m);

// Snooker colours (WPBSA Section 3, spotting colours): those whose own spot is free go there; the
// others, highest value first, to the highest-value free spot, else the nearest free point from
// their own spot towards the top cushion (+x), else towards the bottom cushion. Adds them to
// `balls` and returns them in the order placed.
std::vector<std::string> spotSnookerColours(std::vector<std::string> colours,
                                            std::vector<PlacedBall>* balls, const Table& table,
                                            double radius_m);

// A snooker ball's value: a red ("red..." ids) 1, yellow 2, green 3, brown 4, blue 5, pink 6,
// black 7; 0 for anything else (the cue ball).
int snookerValue(const std::string& id);
bool isRed(const std::string& id);
// The colours from yellow to black.
const std::vector<std::string>& snookerColours();
Eigen::Vector2d colourSpot(const std::string& colour, const Table& table);

}  // namespace baize::engine
