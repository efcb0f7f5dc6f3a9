// Where a ball meets a cushion or a jaw, and the frame the cushion model works in: shared by the
// event loop and the fixed-step integrator so both resolve a contact the same way.
#pragma once

#include <Eigen/Core>

#include "engine/sim/shot_events.h"
#include "engine/sim/table_geometry.h"
#include "physics/cloth_motion.h"
#include "physics/cushion_model.h"

namespace baize::engine {

// The cushion model's local frame for a contact normal n (unit, pointing from the cushion or jaw
// towards the ball): y into the cushion (-n), x along it (n turned +90 degrees), z up.
struct ContactFrame {
  Eigen::Vector3d x, y;
  explicit ContactFrame(const Eigen::Vector2d& n);
  physics::BallVelocity toLocal(const physics::BallState& ball) const;
  // Sets the ball's velocity and spin from the local ones (its position is left alone).
  void toTable(const physics::BallVelocity& local, physics::BallState* ball) const;
};

// Whether the direction from a jaw's centre to point q lies within the jaw's angular range.
bool onJawArc(const JawArc& jaw, const Eigen::Vector2d& q);

// Whether a ball centred at q lies beside a straight cushion: its contact point between the ends.
bool besideSegment(const CushionSegment& cushion, const Eigen::Vector2d& q);

// The contact normal (unit, from the cushion or jaw to the ball) of a Cushion or Jaw event whose
// ball is centred at `position`: a straight cushion's inward normal, or the direction from the
// jaw's centre to the ball. The cushion model works in the frame it sets (ContactFrame,
// engine/sim/contact_geometry.h): the event's `before` ball in that frame is the model's input
// where it moves into the cushion (v.y > 0; otherwise there is no impact: the ball touches it
// moving along or away, perhaps pressed against it).
Eigen::Vector2d contactNormal(const TableGeometry& table, EventKind kind, int index,
                              const Eigen::Vector2d& position);

}  // namespace baize::engine
