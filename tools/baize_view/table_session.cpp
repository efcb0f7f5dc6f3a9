#include "tools/baize_view/table_session.h"

#include <algorithm>
#include <cmath>
#include <limits>
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

TableSession::TableSession(engine::Scene scene) {
  std::unique_ptr<Live> live = startShot(scene);
  show(std::move(scene), std::move(live));
  cue_ = scene_.shot;
}

TableSession::~TableSession() = default;

std::unique_ptr<TableSession::Live> TableSession::startShot(const engine::Scene& scene) {
  auto live = std::make_unique<Live>();
  live->start = engine::sceneStart(scene, /*record_trajectories=*/true);
  live->table = engine::geometryOf(scene.table);
  const std::string prefix = scene.source.empty() ? "" : scene.source + ": ";
  try {
    live->simulation = std::make_unique<engine::ShotSimulation>(
        live->start.params, live->table, live->start.balls, live->start.ball_ids);
  } catch (const std::invalid_argument& e) {  // as runScene names the scene
    throw std::invalid_argument(prefix + e.what());
  }
  return live;
}

void TableSession::show(engine::Scene scene, std::unique_ptr<Live> live) {
  scene_ = std::move(scene);
  for (const engine::PlacedBall& b : scene_.balls) {
    if (b.id == scene_.cue_ball) cue_start_m_ = b.position_m;
  }
  live_ = std::move(live);
  at_rest_ = false;
  failure_.reset();
  shot_ = render::ShotRecord{};
  shot_.table = scene_.table;
  shot_.ball_set = scene_.ball_set;
  shot_.cloth = live_->start.params.cloth;
  shot_.ball_ids = live_->start.ball_ids;
  copyProgress();
}

void TableSession::advanceTo(double t_s) {
  if (at_rest_ || !(t_s > live_->simulation->time())) return;
  engine::ShotSimulation& sim = *live_->simulation;
  try {
    sim.advanceTo(t_s);
    at_rest_ = !sim.nextEvent().has_value();
  } catch (const std::exception& e) {  // the shot stops where it failed, and says why
    failure_ = (scene_.source.empty() ? "" : scene_.source + ": ") + e.what();
    at_rest_ = true;
  }
  copyProgress();
}

// The new events and path pieces since the last copy; the end time once the shot is over.
void TableSession::copyProgress() {
  const engine::ShotSimulation& sim = *live_->simulation;
  const std::vector<engine::Event>& events = sim.events();
  shot_.events.insert(shot_.events.end(), events.begin() + shot_.events.size(), events.end());
  shot_.trajectories = sim.trajectories();
  const bool ended = at_rest_ && !failure_;
  shot_.end_time_s = ended ? (events.empty() ? 0 : events.back().time_s) : sim.time();
}

Eigen::Vector2d TableSession::cueBallAtRest() {
  advanceTo(std::numeric_limits<double>::infinity());
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
  const Eigen::Vector2d cue_at = cueBallAtRest();  // steps the shot on show to its end
  for (std::size_t i = 0; i < shot_.ball_ids.size(); ++i) {
    const std::string& id = shot_.ball_ids[i];
    if (id == scene_.cue_ball) {
      next.balls.insert(next.balls.begin(), engine::PlacedBall{id, cue_at});
    } else if (!pocketedAtEnd(shot_, static_cast<int>(i))) {
      next.balls.push_back(engine::PlacedBall{
          id,
          engine::sampleTrajectory(shot_.cloth, shot_.trajectories[i], shot_.end_time_s).position});
    }
  }
  next.shot = cue_;
  try {
    std::unique_ptr<Live> live = startShot(next);
    show(std::move(next), std::move(live));
  } catch (const std::exception& e) {
    return std::string(e.what());
  }
  return std::nullopt;
}

}  // namespace baize::tools
