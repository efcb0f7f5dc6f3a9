// The event loop: balls move in closed form on the cloth between events, and every event happens at
// an exact root of the polynomial that describes it (a quartic for two balls or a ball and a
// pocket's capture circle, a quadratic for a ball and a straight cushion). The earliest event is
// resolved by the physical model for it and the rest are predicted again.
//
// Table frame: origin anywhere on the slate, x and y in the table plane, z up; SI units.
#pragma once

#include <Eigen/Core>
#include <array>
#include <initializer_list>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include "engine/sim/cushion_contact.h"
#include "engine/sim/table_geometry.h"
#include "physics/ball_ball_impact.h"
#include "physics/cloth_motion.h"
#include "physics/cushion_exact_solver.h"
#include "physics/cushion_model.h"
#include "physics/cushion_simple_model.h"

namespace baize::engine {

// A ball that is not pocketed was found outside the table's cushion outline: it ran past a
// pocket's facings without entering the capture circle (which validation of a scene's table
// rules out: engine/io/table.h, checkCapturesCoverOpenings), or the event loop has a fault. Never a
// result: the shot fails. The message names the ball, where and when it was and that it left.
class BallLeftTableError : public std::logic_error {
 public:
  using std::logic_error::logic_error;
};

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

enum class EventKind {
  StateChange,  // a ball's motion state changed (sliding -> rolling, rolling -> stopped, ...)
  BallBall,     // balls `ball` and `other` collided
  Cushion,      // `ball` hit straight cushion number `index`
  Jaw,          // `ball` hit jaw (rounded cushion) number `index`
  Pocket,       // `ball` fell into pocket number `index`
};

const char* eventKindName(EventKind kind);

struct BallRecord {
  physics::BallState state;  // a pocketed ball's: as it fell in
  bool pocketed = false;
  int pocket = -1;  // the pocket it fell into (TableGeometry::pockets), when pocketed
};

// The states of the balls an event involves (one, or two for a ball-ball contact), held in place:
// an event allocates nothing (two vectors per event were a tenth of a break's time).
class EventBalls {
 public:
  static constexpr std::size_t kCapacity = 2;
  EventBalls() = default;
  EventBalls(std::initializer_list<physics::BallState> states) {
    for (const physics::BallState& s : states) push_back(s);
  }
  void push_back(const physics::BallState& state) {
    if (size_ == kCapacity) throw std::logic_error("an event involves at most two balls");
    states_[size_++] = state;
  }
  void clear() { size_ = 0; }
  std::size_t size() const { return size_; }
  bool empty() const { return size_ == 0; }
  const physics::BallState& operator[](std::size_t i) const { return states_[i]; }
  physics::BallState& operator[](std::size_t i) { return states_[i]; }
  const physics::BallState* begin() const { return states_.data(); }
  const physics::BallState* end() const { return states_.data() + size_; }

 private:
  std::array<physics::BallState, kCapacity> states_{};
  std::size_t size_ = 0;
};

struct Event {
  double time_s = 0;
  EventKind kind = EventKind::StateChange;
  int ball = 0;
  int other = -1;     // BallBall: the second ball
  int index = -1;     // Cushion: the cushion; Pocket: the pocket
  EventBalls before;  // the balls involved, just before (ball, then other)
  EventBalls after;   // and just after
};

// The contact normal (unit, from the cushion or jaw to the ball) of a Cushion or Jaw event whose
// ball is centred at `position`: a straight cushion's inward normal, or the direction from the
// jaw's centre to the ball. The cushion model works in the frame it sets (ContactFrame,
// engine/sim/contact_geometry.h): the event's `before` ball in that frame is the model's input where
// it moves into the cushion (v.y > 0; otherwise there is no impact: the ball touches it moving
// along or away, perhaps pressed against it).
Eigen::Vector2d contactNormal(const TableGeometry& table, EventKind kind, int index,
                              const Eigen::Vector2d& position);

// A ball's path as its exact closed-form pieces: from each piece's start time the ball moves as
// physics::advance says from that state, until the next piece (an event changed its motion).
struct TrajectoryPiece {
  double start_time_s = 0;
  physics::BallState state;  // at start_time_s
  bool pocketed = false;     // from start_time_s on the ball is in a pocket
};
using Trajectory = std::vector<TrajectoryPiece>;

// The ball's state at time t_s >= 0 (its state when it fell for a pocketed ball).
physics::BallState sampleTrajectory(const physics::ClothParams& cloth, const Trajectory& trajectory,
                                    double t_s);

struct SimulationResult {
  std::vector<Event> events;
  std::vector<BallRecord> final_balls;
  double end_time_s = 0;         // when the last ball stopped (or fell)
  long predictions = 0;          // event predictions solved
  long skipped_predictions = 0;  // pairs skipped without solving (both balls at rest, far apart)
  std::vector<Trajectory> trajectories;  // per ball, when SimulationParams::record_trajectories
};

// The checks simulate() makes of its input, for other simulators of the same scenes: consistent
// parameters (ball radius and mass agree across the models), a well-formed table, finite states,
// no overlapping balls, no ball beyond a cushion or inside a jaw. Throws std::invalid_argument
// naming the ball and the value. `ball_ids`, when given (one per ball), names the balls in
// messages ("ball 'cue'"); otherwise they are named by number ("ball 0").
void validateSimulationInput(const SimulationParams& params, const TableGeometry& table,
                             const std::vector<physics::BallState>& balls,
                             const std::vector<std::string>& ball_ids = {});

// Simulates until every ball is at rest or pocketed. Throws std::invalid_argument on invalid input
// (parameters, a non-finite state, overlapping balls, a ball off the table, `ball_ids` neither
// empty nor one per ball), std::runtime_error when the shot needs more than max_events events and
// BallLeftTableError when a ball leaves the table. Messages name balls as
// validateSimulationInput() does.
SimulationResult simulate(const SimulationParams& params, const TableGeometry& table,
                          const std::vector<physics::BallState>& balls,
                          const std::vector<std::string>& ball_ids = {});

}  // namespace baize::engine
