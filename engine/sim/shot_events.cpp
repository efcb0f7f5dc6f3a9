#include "engine/sim/shot_events.h"

#include <algorithm>
#include <cmath>

#include "physics/value_text.h"

namespace baize::engine {

const char* eventKindName(EventKind kind) {
  switch (kind) {
    case EventKind::StateChange:
      return "state change";
    case EventKind::BallBall:
      return "ball-ball";
    case EventKind::Cushion:
      return "cushion";
    case EventKind::Jaw:
      return "jaw";
    case EventKind::Pocket:
      return "pocket";
  }
  return "?";
}

physics::BallState sampleTrajectory(const physics::ClothParams& cloth, const Trajectory& trajectory,
                                    double t_s) {
  if (trajectory.empty()) throw std::invalid_argument("sampleTrajectory: the trajectory is empty");
  if (!(t_s >= 0) || !std::isfinite(t_s))
    physics::rejectValue("sample time (s)", t_s, "it must be finite and >= 0");
  auto piece =
      std::upper_bound(trajectory.begin(), trajectory.end(), t_s,
                       [](double t, const TrajectoryPiece& q) { return t < q.start_time_s; });
  --piece;  // the last piece starting at or before t_s (the first starts at 0)
  if (piece->pocketed) return piece->state;
  return physics::advance(cloth, piece->state, t_s - piece->start_time_s);
}

}  // namespace baize::engine
