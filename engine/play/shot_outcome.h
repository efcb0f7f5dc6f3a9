// What a shot did, in the terms players and referees use: the balls pocketed (and where), the first
// ball the cue ball hit, the cushions it touched before that, where it stopped, and whether the
// shot was a foul. Read from a SceneRun's events; no physics of its own. PocketedBall and Foul are
// declared with the result file that records them (engine/io/result_file.h).
#pragma once

#include <Eigen/Core>
#include <optional>
#include <string>
#include <vector>

#include "engine/io/result_file.h"
#include "engine/io/scene.h"

namespace baize::engine {

struct FinalBall {
  std::string id;
  Eigen::Vector2d position_m = Eigen::Vector2d::Zero();  // where it stopped (or fell)
  bool pocketed = false;
  int cushion_contacts = 0;  // its cushion and jaw contacts over the whole shot
};

struct ShotOutcome {
  std::string cue_ball;
  std::vector<PocketedBall> pocketed;    // in the order they fell, the cue ball included
  std::optional<std::string> first_hit;  // the first ball the cue ball touched
  // Cushion and jaw contacts of the cue ball before it first touched another ball (all of its
  // cushion contacts when it touched none).
  int cushions_before_first_hit = 0;
  int cushion_contacts = 0;  // cushion and jaw contacts of all balls
  bool cue_ball_pocketed = false;
  Eigen::Vector2d cue_ball_final_m = Eigen::Vector2d::Zero();
  std::vector<FinalBall> final_balls;  // in the scene's order
  Foul foul = Foul::None;              // a pocketed cue ball counts before a miss when both happen
  long events = 0;

  const FinalBall* ball(const std::string& id) const;  // nullptr for a ball not in the scene
  bool wasPocketed(const std::string& id) const;
};

// The result file of a run of `scene` (engine/io/result_file.h): the scene as read, the parameters
// it ran with, the outcome and, when `with_recording`, the run's events with their states and its
// trajectories (when it recorded them). The scene is taken by value: a caller done with it moves it
// in (a batch writes thousands of results a second).
ShotResult shotResult(Scene scene, const SceneRun& run, bool with_recording);

// The outcome of a run whose cue ball is `cue_ball`. Throws std::invalid_argument when the run has
// no ball of that id.
ShotOutcome shotOutcome(const SceneRun& run, const std::string& cue_ball);

}  // namespace baize::engine
