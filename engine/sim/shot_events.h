// What a simulated shot gives: its events (each with the balls involved just before and after),
// the balls' final states, and on request every ball's path as exact closed-form pieces.
//
// Table frame: x and y in the table plane, z up; SI units.
#pragma once

#include <array>
#include <initializer_list>
#include <stdexcept>
#include <vector>

#include "physics/cloth_motion.h"

namespace baize::engine {

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

// A ball that is not pocketed was found outside the table's cushion outline: it ran past a
// pocket's facings without entering the capture circle (which validation of a scene's table
// rules out: engine/io/table.h, checkCapturesCoverOpenings), or the event loop has a fault. Never a
// result: the shot fails. The message names the ball, where and when it was and that it left.
class BallLeftTableError : public std::logic_error {
 public:
  using std::logic_error::logic_error;
};

}  // namespace baize::engine
