// A person playing on a scene in the viewer: the shot on show, the cue's aim, speed and tip offset,
// and striking again from where the balls came to rest (engine::runScene; trajectories recorded).
// Pure logic (no SDL).
#pragma once

#include <optional>
#include <string>

#include "engine/io/scene.h"
#include "render/shot_record.h"

namespace baize::tools {

// Cue settings the keys move within, and their steps.
constexpr double kMinCueSpeed_mps = 0.25;
constexpr double kMaxCueSpeed_mps = 12;
constexpr double kCueSpeedStep_mps = 0.25;
constexpr double kTipStep_R = 0.05;
constexpr double kMaxTipOffset_R = 0.45;  // inside the 0.5 R miscue limit

class TableSession {
 public:
  // Runs the scene's own shot.
  explicit TableSession(engine::Scene scene);

  const render::ShotRecord& shot() const { return shot_; }
  const engine::Scene& scene() const { return scene_; }

  // Where the cue ball stands when the shot on show is over (its start spot if it was pocketed).
  Eigen::Vector2d cueBallAtRest() const;
  void aimAt(const Eigen::Vector2d& point_m);
  void changeSpeed(int steps);
  // Moves the tip right (side) and up (height) by steps of kTipStep_R, kept within kMaxTipOffset_R.
  void moveTip(int side_steps, int height_steps);
  const physics::CueShot& cue() const { return cue_; }

  // Strikes from where the balls came to rest; the new shot replaces the one on show. Returns an
  // error message instead when the engine refuses it (nothing changes then).
  std::optional<std::string> strike();

 private:
  engine::Scene scene_;  // the balls where the shot on show started, and its cue
  Eigen::Vector2d cue_start_m_;
  render::ShotRecord shot_;
  physics::CueShot cue_;
};

}  // namespace baize::tools
