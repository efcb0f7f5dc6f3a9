// What a shot did, in the terms players and referees use: the balls pocketed (and where), the first
// ball the cue ball hit, the cushions it touched before that, where it stopped, and whether the
// shot was a foul. Read from a SceneRun's events; no physics of its own.
#pragma once

#include <Eigen/Core>
#include <optional>
#include <string>
#include <vector>

#include "engine/io/scene.h"

namespace baize::engine {

struct PocketedBall {
  std::string ball;
  int pocket = 0;  // index into Table::pockets (counterclockwise from the bottom-left corner)
};

struct FinalBall {
  std::string id;
  Eigen::Vector2d position_m = Eigen::Vector2d::Zero();  // where it stopped (or fell)
  bool pocketed = false;
  int cushion_contacts = 0;  // its cushion and jaw contacts over the whole shot
};

enum class Foul {
  None,
  CueBallPocketed,  // the cue ball fell into a pocket
  NoBallHit,        // the cue ball touched no other ball
};

const char* foulName(Foul foul);

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

// The outcome of a run whose cue ball is `cue_ball`. Throws std::invalid_argument when the run has
// no ball of that id.
ShotOutcome shotOutcome(const SceneRun& run, const std::string& cue_ball);

}  // namespace baize::engine
