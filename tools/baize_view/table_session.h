// A person playing on a scene in the viewer: the shot on show, stepped through the event loop as
// the viewer's clock runs (engine::ShotSimulation, trajectories recorded for drawing and going
// back), the cue's aim, speed and tip offset, and striking again from where the balls came to
// rest. Pure logic (no SDL).
#pragma once

#include <memory>
#include <optional>
#include <string>

#include "engine/io/scene.h"
#include "engine/sim/shot_simulation.h"
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
  // Starts the scene's own shot (nothing resolved yet). Throws as engine::runScene does.
  explicit TableSession(engine::Scene scene);
  ~TableSession();

  // What the shot on show has done up to the time it was advanced to: its events and the balls'
  // paths, with end_time_s that time (the end, once at rest).
  const render::ShotRecord& shot() const { return shot_; }
  const engine::Scene& scene() const { return scene_; }
  // Steps the shot on show to t_s (a time already passed changes nothing: shot() holds it).
  void advanceTo(double t_s);
  // Whether the shot on show is over: every ball at rest or fallen, or the event loop failed.
  bool atRest() const { return at_rest_; }
  // Why the event loop stopped the shot on show early (a ball left the table, too many events).
  const std::optional<std::string>& failure() const { return failure_; }

  // Where the cue ball stands when the shot on show is over (its start spot if it was pocketed).
  // Steps the shot to its end first.
  Eigen::Vector2d cueBallAtRest();
  void aimAt(const Eigen::Vector2d& point_m);
  void changeSpeed(int steps);
  // Moves the tip right (side) and up (height) by steps of kTipStep_R, kept within kMaxTipOffset_R.
  void moveTip(int side_steps, int height_steps);
  const physics::CueShot& cue() const { return cue_; }

  // Strikes from where the balls came to rest; the new shot replaces the one on show. Returns an
  // error message instead when the engine refuses it (nothing changes then).
  std::optional<std::string> strike();

 private:
  // The event loop of the shot on show, with what it holds by reference.
  struct Live {
    engine::SceneStart start;
    engine::TableGeometry table;
    std::unique_ptr<engine::ShotSimulation> simulation;
  };
  static std::unique_ptr<Live> startShot(const engine::Scene& scene);
  void show(engine::Scene scene, std::unique_ptr<Live> live);
  void copyProgress();

  engine::Scene scene_;  // the balls where the shot on show started, and its cue
  Eigen::Vector2d cue_start_m_;
  std::unique_ptr<Live> live_;
  render::ShotRecord shot_;
  bool at_rest_ = false;
  std::optional<std::string> failure_;
  physics::CueShot cue_;
};

}  // namespace baize::tools
