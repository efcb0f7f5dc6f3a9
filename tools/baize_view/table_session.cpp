#include "tools/baize_view/table_session.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace baize::tools {
namespace {

int ballIndex(const render::ShotRecord& shot, const std::string& id) {
  for (std::size_t i = 0; i < shot.ball_ids.size(); ++i) {
    if (shot.ball_ids[i] == id) return static_cast<int>(i);
  }
  throw std::invalid_argument("ball '" + id + "' is not in the shot");
}

bool pocketedAtEnd(const render::ShotRecord& shot, int i) {
  return shot.trajectories[i].back().pocketed;
}

}  // namespace

TableSession::TableSession(engine::Scene scene) : scene_(std::move(scene)) {
  for (const engine::PlacedBall& b : scene_.balls) {
    if (b.id == scene_.cue_ball) cue_start_m_ = b.position_m;
  }
  shot_ = render::shotRecordOf(scene_, engine::runScene(scene_, /*record_trajectories=*/true));
  cue_ = scene_.shot;
}

Eigen::Vector2d TableSession::cueBallAtRest() const {
  const int cue = ballIndex(shot_, scene_.cue_ball);
  if (pocketedAtEnd(shot_, cue)) return cue_start_m_;
  return engine::sampleTrajectory(shot_.cloth, shot_.trajectories[cue], shot_.end_time_s).position;
}

void TableSession::aimAt(const Eigen::Vector2d& point_m) {
  const Eigen::Vector2d d = point_m - cueBallAtRest();
  if (d.norm() > 0) cue_.heading_rad = std::atan2(d.y(), d.x());
}

void TableSession::changeSpeed(int steps) {
  cue_.speed_mps =
      std::clamp(cue_.speed_mps + steps * kCueSpeedStep_mps, kMinCueSpeed_mps, kMaxCueSpeed_mps);
}

void TableSession::moveTip(int side_steps, int height_steps) {
  double side = cue_.side_offset + side_steps * kTipStep_R;
  double height = cue_.height_offset + height_steps * kTipStep_R;
  const double r = std::hypot(side, height);
  if (r > kMaxTipOffset_R) {
    side *= kMaxTipOffset_R / r;
    height *= kMaxTipOffset_R / r;
  }
  cue_.side_offset = side;
  cue_.height_offset = height;
}

std::optional<std::string> TableSession::strike() {
  engine::Scene next = scene_;
  next.balls.clear();
  for (std::size_t i = 0; i < shot_.ball_ids.size(); ++i) {
    const std::string& id = shot_.ball_ids[i];
    if (id == scene_.cue_ball) {
      next.balls.insert(next.balls.begin(), engine::PlacedBall{id, cueBallAtRest()});
    } else if (!pocketedAtEnd(shot_, static_cast<int>(i))) {
      next.balls.push_back(engine::PlacedBall{
          id,
          engine::sampleTrajectory(shot_.cloth, shot_.trajectories[i], shot_.end_time_s).position});
    }
  }
  next.shot = cue_;
  try {
    const engine::SceneRun run = engine::runScene(next, /*record_trajectories=*/true);
    shot_ = render::shotRecordOf(next, run);
    scene_ = next;
  } catch (const std::exception& e) {
    return std::string(e.what());
  }
  return std::nullopt;
}

}  // namespace baize::tools
