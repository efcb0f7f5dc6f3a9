// The constant parameters of a shot: the cloth, the cushion and ball-ball models and their
// options, and the event budget.
#pragma once

#include "engine/sim/cushion_contact.h"
#include "physics/ball_ball_impact.h"
#include "physics/cloth_motion.h"
#include "physics/cushion_exact_solver.h"
#include "physics/cushion_model.h"
#include "physics/cushion_simple_model.h"

namespace baize::engine {

// Constants of a shot. The ball radius and mass come from `cushion` (and must agree with `cloth`
// and `ball_ball`, which simulate() checks).
struct SimulationParams {
  physics::ClothParams cloth = physics::poolCloth();
  physics::CushionParams cushion;  // the Mathavan 2010 model; mass, radius and nose height of the balls
  // The model every cushion and jaw hit goes through (engine/sim/cushion_contact.h), and the options of
  // each: the exact solver's, the paper scheme's step count N, the simple rule's restitution.
  CushionModelChoice cushion_model = CushionModelChoice::Mathavan2010Exact;
  physics::ExactSolverOptions cushion_solver;
  int cushion_paper_steps = 5000;  // N, as in the paper
  physics::SimpleCushionParams cushion_simple;
  physics::BallBallParams ball_ball;
  long max_events = 100000;          // a shot needing more stops with an error saying so
  bool record_trajectories = false;  // fill SimulationResult::trajectories (costs memory only)
};

// Pool defaults throughout: 57.15 mm, 0.17 kg balls, the nose at 0.635 of the diameter above the
// slate, e_e 0.98 and mu_w 0.14 for the cushion (the values of Mathavan 2010), cloth friction 0.2.
SimulationParams poolSimulationParams();

}  // namespace baize::engine
