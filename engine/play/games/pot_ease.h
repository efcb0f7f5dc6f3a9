// A cheap estimate of how makeable a pot is, from geometry alone (no simulation): the cut, the
// distances and whether the paths are clear. The game player ranks candidate pots with it and
// scores the position a shot leaves for the next one.
#pragma once

#include <Eigen/Core>
#include <string>
#include <vector>

#include "engine/io/rack.h"
#include "engine/io/table.h"
#include "engine/play/games/game_state.h"

namespace baize::engine {

// Cuts thinner than this are not played for (deg): a small aim error misses them.
constexpr double kMaxPlayedCut_deg = 75;
// A ball entering a pocket this far from the pocket's axis is rejected by its jaws (deg):
// side pockets have narrow acceptance at a shallow angle.
constexpr double kMaxSidePocketEntry_deg = 50;
constexpr double kMaxCornerPocketEntry_deg = 60;
// Distance scale of the ease, m: every metre the balls travel loses a share of it (aim errors
// grow with distance).
constexpr double kEaseDistance_m = 2.0;
// Room a path must leave to other balls beyond 2R, m (the execution error over a metre).
constexpr double kPathClearance_m = 0.003;

// The ghost-ball position: where the cue ball's centre must be when it meets ball `object_m` to
// send it to the pocket's mouth centre.
Eigen::Vector2d ghostBall(const Eigen::Vector2d& object_m, const Pocket& pocket, double radius_m);

// In [0, 1]: 0 when the pot is not on (a path blocked, the cut or the pocket entry too steep),
// else cos(cut) x exp(-(cue to ghost + object to mouth) / kEaseDistance_m). `balls` are all balls
// on the table; the cue ball's and the object's own entries are skipped by id.
double potEase(const std::vector<PlacedBall>& balls, const Eigen::Vector2d& cue_m,
               const std::string& object, int pocket, const Table& table, double radius_m);

// Whether no ball of `balls` other than `skip_a` and `skip_b` comes within 2R + clearance of the
// segment from `from_m` to `to_m`.
bool pathClear(const std::vector<PlacedBall>& balls, const Eigen::Vector2d& from_m,
               const Eigen::Vector2d& to_m, const std::string& skip_a, const std::string& skip_b,
               double radius_m);

// The best ease over the legal targets of `state` and every pocket, from the cue ball where it
// stands (1 when the frame is over).
double bestPotEase(const GameState& state, const Table& table, double radius_m);

}  // namespace baize::engine
