// The simplest ball-cushion rule, kept to compare against the Mathavan 2010 model
// (cushion_exact_solver.h): the velocity component into the cushion reverses and is scaled by a
// restitution e; the component along the cushion and the whole angular velocity are kept. No
// friction acts at the nose or on the cloth, so the rebound angle does not depend on spin and
// sidespin does not throw the ball; the only loss is (1 - e^2) of the normal part of the
// translational energy, so energy never grows.
//
// Frame and units as in cushion_model.h: the local cushion frame (x along the cushion, y into it,
// z up); SI units.
#pragma once

#include "physics/cushion_model.h"  // BallVelocity

namespace baize::physics {

struct SimpleCushionParams {
  // e in (0, 1]: v_y' = -e v_y. The default is the low-speed slope of measured head-on rolling
  // rebounds on a snooker cushion, about 0.91 (physics-notes section 1), which is what this rule
  // gives head-on.
  double restitution = 0.91;
};

// Throws std::invalid_argument naming the value unless 0 < e <= 1 (e = 0 would leave the ball
// touching the cushion with no normal speed).
void validateSimpleCushionParams(const SimpleCushionParams& params);

// The ball after the impact, local cushion frame: (v_x, -e v_y, 0) with w unchanged. Throws
// std::invalid_argument on invalid parameters or an incoming ball that validateIncomingBall
// refuses.
BallVelocity simpleCushionRebound(const SimpleCushionParams& params, const BallVelocity& incoming);

}  // namespace baize::physics
