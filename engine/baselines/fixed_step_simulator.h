// A fixed-step integrator of exactly the event loop's physics, kept as the yardstick the event loop
// is measured against (`baize bench accuracy`): the same cloth motion, the same ball-ball and
// cushion impact models, but contacts found by overlap at the end of each time step instead of at
// exact event times.
//
// One step of length dt:
//  1. every ball moves by physics::advance over dt (the closed-form cloth motion; a sliding ball
//     that starts rolling within the step, or a rolling ball that stops, is handled by advance);
//  2. a ball whose centre is inside a pocket's capture circle falls in;
//  3. every contact that overlaps (or touches) and approaches is resolved by its impact model, the
//     one estimated to have begun earliest (overlap depth / approach speed) first, until none
//     approaches: ball-ball by the chosen ball-ball model, straight cushions and jaws by the chosen
//     cushion model in the frame of the contact normal (as engine::simulate);
//  4. overlap that remains is removed by moving positions only (push-out): velocities and spins are
//     untouched, and on a level table a position carries no energy, so push-out never adds energy.
//
// Its error is first order in dt: a contact is found up to one step late, by up to |v| dt of
// overlap. Table frame and units as engine/sim/shot_simulator.h.
#pragma once

#include <functional>
#include <vector>

#include "engine/sim/shot_simulator.h"

namespace baize::engine {

// Smallest and largest time step accepted, s: below 1e-7 s a shot takes more than 1e8 steps; above
// 0.1 s a ball at break speed crosses the table in one step.
inline constexpr double kMinFixedTimeStep_s = 1e-7;
inline constexpr double kMaxFixedTimeStep_s = 0.1;
// A shot still moving after this much simulated time stops with std::runtime_error, s: the slowest
// physical stop (a 16 m/s ball rolling out at mu_r = 0.005, or 3 V/R of sidespin spinning down) is
// well under it.
inline constexpr double kMaxFixedStepShotTime_s = 1000;

// Called after every step with the time at its end (s) and every ball's state then (tests watch
// invariants with it: energy, overlap, escape).
using FixedStepObserver = std::function<void(double time_s, const std::vector<BallRecord>& balls)>;

// Simulates until every ball is at rest or pocketed, with time steps of time_step_s. The result has
// the shape of engine::simulate's: events (kinds and balls as there; time_s is the end of the step
// in which the contact was found; a StateChange event marks a step in which a ball's motion state
// changed) and final_balls. predictions and skipped_predictions stay 0 and trajectories empty.
//
// Throws std::invalid_argument for invalid parameters, a time step outside [kMinFixedTimeStep_s,
// kMaxFixedTimeStep_s], a non-finite ball state, overlapping balls or a ball beyond a cushion, and
// std::runtime_error when the shot is still moving after kMaxFixedStepShotTime_s or records more
// than params.max_events events.
SimulationResult simulateFixedStep(const SimulationParams& params, const TableGeometry& table,
                                   const std::vector<physics::BallState>& balls, double time_step_s,
                                   const FixedStepObserver& observer = {});

}  // namespace baize::engine
