// An event the loop has predicted: when (from the time it was predicted, or absolute once stored),
// what kind and which balls, cushion, jaw or pocket. Ordered so that the same input always resolves
// in the same order.
#pragma once

#include <limits>
#include <tuple>

#include "engine/sim/shot_events.h"

namespace baize::engine {

// The time of an event that never comes, s.
inline constexpr double kNever = std::numeric_limits<double>::infinity();

struct PredictedEvent {
  double dt_s = kNever;  // from when it was predicted; absolute (from the shot's start) once stored
  EventKind kind = EventKind::StateChange;
  int ball = -1, other = -1, index = -1;  // other: BallBall's second ball; index: the cushion, ...

  // Earliest first; ties broken by kind, then by the balls' and the cushion's or pocket's numbers.
  bool operator<(const PredictedEvent& c) const {
    return std::make_tuple(dt_s, static_cast<int>(kind), ball, other, index) <
           std::make_tuple(c.dt_s, static_cast<int>(c.kind), c.ball, c.other, c.index);
  }
  bool sameContact(const PredictedEvent& c) const {
    return kind == c.kind && ball == c.ball && other == c.other && index == c.index;
  }
};

}  // namespace baize::engine
