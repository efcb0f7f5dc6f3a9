#include "engine/play/games/pot_ease.h"

#include <algorithm>
#include <cmath>

#include "engine/play/games/game_rules.h"

namespace baize::engine {
namespace {

using Eigen::Vector2d;

constexpr double kDegToRad = M_PI / 180;

double distanceToSegment(const Vector2d& p, const Vector2d& a, const Vector2d& b) {
  const Vector2d ab = b - a;
  const double length2 = ab.squaredNorm();
  const double t = length2 > 0 ? std::clamp((p - a).dot(ab) / length2, 0.0, 1.0) : 0;
  return (p - (a + t * ab)).norm();
}

}  // namespace

Vector2d ghostBall(const Vector2d& object_m, const Pocket& pocket, double radius_m) {
  return object_m - 2 * radius_m * (pocket.mouth_centre_m - object_m).normalized();
}

bool pathClear(const std::vector<PlacedBall>& balls, const Vector2d& from_m, const Vector2d& to_m,
               const std::string& skip_a, const std::string& skip_b, double radius_m) {
  const double room = 2 * radius_m + kPathClearance_m;
  return std::none_of(balls.begin(), balls.end(), [&](const PlacedBall& b) {
    return b.id != skip_a && b.id != skip_b && distanceToSegment(b.position_m, from_m, to_m) < room;
  });
}

double potEase(const std::vector<PlacedBall>& balls, const Vector2d& cue_m,
               const std::string& object, int pocket_index, const Table& table, double radius_m) {
  const auto at = std::find_if(balls.begin(), balls.end(),
                               [&](const PlacedBall& b) { return b.id == object; });
  if (at == balls.end()) return 0;
  const Pocket& pocket = table.pockets.at(pocket_index);
  const Vector2d o = at->position_m;
  const Vector2d to_mouth = pocket.mouth_centre_m - o;
  const Vector2d u = to_mouth.normalized();
  const double max_entry_deg =
      pocket.kind == PocketKind::Side ? kMaxSidePocketEntry_deg : kMaxCornerPocketEntry_deg;
  if (u.dot(pocket.axis) < std::cos(max_entry_deg * kDegToRad)) return 0;
  const Vector2d ghost = ghostBall(o, pocket, radius_m);
  const Vector2d to_ghost = ghost - cue_m;
  const double cos_cut = to_ghost.norm() > 0 ? to_ghost.normalized().dot(u) : 1;
  if (cos_cut < std::cos(kMaxPlayedCut_deg * kDegToRad)) return 0;
  if (!pathClear(balls, o, pocket.mouth_centre_m, object, "cue", radius_m) ||
      !pathClear(balls, cue_m, ghost, object, "cue", radius_m)) {
    return 0;
  }
  return cos_cut * std::exp(-(to_ghost.norm() + to_mouth.norm()) / kEaseDistance_m);
}

double bestPotEase(const GameState& state, const Table& table, double radius_m) {
  if (state.frame_over) return 1;
  double best = 0;
  const Vector2d cue = state.balls.front().position_m;
  for (const std::string& target : legalTargets(state)) {
    for (int k = 0; k < static_cast<int>(table.pockets.size()); ++k) {
      best = std::max(best, potEase(state.balls, cue, target, k, table, radius_m));
    }
  }
  return best;
}

}  // namespace baize::engine
