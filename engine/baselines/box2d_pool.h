// A pool simulator built on Box2D 2.4.1, set up the way a careful game developer would: the
// baseline `baize bench accuracy` compares the event loop against. It takes the event loop's inputs
// and returns its result shape, so outcomes can be compared shot for shot. Box2D stays inside this
// file pair (and the tools that use it): engine/ and physics/ never see it.
//
// The model, and where it departs from the event loop's physics:
// - Balls are circles (radius R, mass m, moment of inertia (2/5) m R^2 about z, the solid ball's).
//   Box2D's rotation is the spin about z; the spin about the horizontal axes (topspin, draw) is
//   kept beside Box2D per ball, since a 2D engine has no such axes.
// - Cloth: for half a step before and half a step after every Box2D step, each ball's velocity
//   and spin follow the cloth model's closed form (physics::advance: sliding friction against the
//   contact slip turning into rolling, rolling resistance mu_r m g, the spin about z running
//   down), so Box2D moves the ball with its mid-step velocity (Strang splitting; the cloth's effect
//   on positions is then second order in dt). That is the best Box2D allows: it has no friction
//   with a ground plane of its own, and linear damping would give an exponential, not a constant,
//   deceleration.
// - Cushions and jaws: Box2D edge chains along the cushion noses, the jaw arcs split into short
//   edges, one-sided so a ball is pushed back to the table side. Each chain is set back by Box2D's
//   edge skin (b2_polygonRadius) so that a ball touches it at R from the real nose. Ball-cushion
//   contacts get Box2D restitution and Coulomb friction: the restitution is the chosen cushion
//   model's own head-on rebound ratio of a rolling ball (what a developer would tune to), the
//   friction and nose height its RigidCushionContact (Mathavan 2010: mu_w and h; the simple rule:
//   none, at the equator). Box2D resolves the contact at the ball's equator; the
//   horizontal impulse it applied is then also applied, as torque on the kept horizontal spin, at
//   the real nose height (that is how a cushion takes topspin off). What it still misses: the
//   friction at the nose and the cloth during the impact, which the Mathavan 2010 model integrates,
//   so the spin after a rebound is off (for a rolling head-on hit it takes off too much topspin).
// - Ball-ball contacts get Newton restitution e and Coulomb friction from the chosen ball-ball
//   model's RigidBallContact (the frictional model: Alciatore's fitted mu at a 1 m/s slip); Box2D's
//   friction changes only the spin about z. The vertical friction of topspin or draw at the
//   contact, which throws spin onto the object ball in the event loop's model, has no place in a 2D
//   contact: missing.
// - Pockets: a ball whose centre is inside a capture circle after a step is removed.
// - Units: Box2D's tolerances are compiled in (5 mm linear slop, 1 cm edge skin at one unit per
//   metre) and it clamps any body to 2 units of travel per step. One Box2D unit is therefore
//   box2dLengthUnit_m(dt) metres: 1 cm, or more when a 16 m/s ball would otherwise hit the travel
//   clamp (at dt = 1/60 s one unit is 13 cm and the slop 0.7 mm). Time stays in seconds.
// - restitutionThreshold is lowered to 1 mm/s (Box2D's default 1 m/s would make most pool contacts
//   perfectly inelastic); sleeping is off (the cloth model stops balls exactly); a ball that would
//   move more than a quarter of its radius in a step is a bullet (continuous collision against
//   other balls).
#pragma once

#include <limits>
#include <vector>

#include "engine/sim/shot_simulator.h"

namespace baize::engine {

struct Box2dPoolSettings {
  double time_step_s = 1.0 / 240;  // a fixed Box2D step, s
  int velocity_iterations = 10;    // Box2D recommends 8; more for racks of touching balls
  int position_iterations = 8;     // Box2D recommends 3; more to remove overlap in clusters
  // Stop after this much simulated time even if balls still move, s (tests look at a shot midway).
  double stop_after_s = std::numeric_limits<double>::infinity();
};

// Accepted time steps, s: below 1e-6 s a shot takes 1e7 steps and float time resolution suffers;
// above 0.1 s balls cross the table in a few steps.
inline constexpr double kMinBox2dTimeStep_s = 1e-6;
inline constexpr double kMaxBox2dTimeStep_s = 0.1;
// A shot still moving after this much simulated time stops with std::runtime_error, s (as the
// fixed-step integrator's bound).
inline constexpr double kMaxBox2dShotTime_s = 1000;

// Metres per Box2D length unit for a time step (see above).
double box2dLengthUnit_m(double time_step_s);

// Restitution given to ball-cushion contacts: the chosen cushion model's rebound speed over the
// incoming speed for a rolling ball hitting a cushion head on at 1 m/s, with these parameters.
double calibratedCushionRestitution(const engine::SimulationParams& params);

// Simulates the shot in Box2D until every ball is at rest or pocketed. Events: BallBall, Cushion,
// Jaw (index of the table's cushion or jaw whose edge was touched) and Pocket, each when a contact
// begins while approaching, timed at the end of its step; before and after stay empty (Box2D does
// not expose the states at the contact). final_balls: positions, velocities and spins (w_x, w_y
// kept beside Box2D, w_z Box2D's). Throws std::invalid_argument on invalid parameters or settings
// or a non-finite ball state (overlap is not checked: Box2D pushes overlapping balls apart) and
// std::runtime_error past kMaxBox2dShotTime_s.
engine::SimulationResult simulateBox2d(const engine::SimulationParams& params,
                                       const engine::TableGeometry& table,
                                       const std::vector<physics::BallState>& balls,
                                       const Box2dPoolSettings& settings);

}  // namespace baize::engine
