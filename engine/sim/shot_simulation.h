// The event loop as an object that owns one shot: balls move in closed form on the cloth between
// events, and every event happens at an exact root of the polynomial that describes it (a quartic
// for two balls or a ball and a pocket's capture circle, a quadratic for a ball and a straight
// cushion). The earliest event is resolved by the model for it and what it changed is predicted
// again.
//
// Model and data apart: the parameters and the table are constant and held by reference (they
// must outlive the simulation); everything that changes (the balls, their predicted events, the
// caches that keep predictions cheap) is this object's. It can be stepped one event at a time
// (the viewer, a debugger, a test), advanced to a time, or run to rest (simulate()). Stepping
// gives exactly the events and states of one run to rest, bit for bit.
#pragma once

#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "engine/sim/broad_phase.h"
#include "engine/sim/cushion_solve_ahead.h"
#include "engine/sim/predicted_event.h"
#include "engine/sim/shot_events.h"
#include "engine/sim/simulation_params.h"
#include "engine/sim/table_geometry.h"
#include "physics/cloth_motion.h"

namespace baize::engine {

class CushionImpactWorker;  // engine/sim/cushion_impact_worker.h

class ShotSimulation {
 public:
  // Checks the input as validateSimulationInput() does (std::invalid_argument naming the ball and
  // the value) and sets the balls at t = 0. `worker`, when given, is a thread the caller hands
  // over to solve cushion impacts ahead (engine/sim/cushion_impact_worker.h); the results are the
  // same to the bit with or without it.
  ShotSimulation(const SimulationParams& params, const TableGeometry& table,
                 const std::vector<physics::BallState>& balls,
                 const std::vector<std::string>& ball_ids = {},
                 CushionImpactWorker* worker = nullptr);
  ~ShotSimulation();
  ShotSimulation(const ShotSimulation&) = delete;
  ShotSimulation& operator=(const ShotSimulation&) = delete;

  // The next event (its time from the shot's start, kind and balls), or none when every ball is at
  // rest or pocketed. Throws std::runtime_error when the shot needs more than max_events events.
  std::optional<PredictedEvent> nextEvent();
  // Resolves the next event and returns it (valid until the next call that resolves one), or null
  // when every ball is at rest or pocketed. Throws as nextEvent() does, and BallLeftTableError when
  // a ball leaves the table.
  const Event* step();
  // Resolves every event up to and including time t_s (s) and moves the clock to t_s, where
  // ballAt() samples the balls. A time before the clock is refused (std::invalid_argument).
  void advanceTo(double t_s);
  // Resolves every event left and hands over the result (the simulation is spent afterwards).
  SimulationResult runToRest();

  double time() const { return clock_s_; }  // the clock, s: the last event or advanceTo()
  int ballCount() const { return static_cast<int>(balls_.size()); }
  // Ball i's state at the clock (as it fell, for a pocketed ball), and whether it is pocketed.
  physics::BallState ballAt(int i) const;
  bool pocketed(int i) const { return balls_[i].pocketed; }
  // The events resolved so far, and (when SimulationParams::record_trajectories) every ball's path
  // up to the last of them.
  const std::vector<Event>& events() const { return result_.events; }
  const std::vector<Trajectory>& trajectories() const { return result_.trajectories; }

 private:
  // What the loop keeps of each ball. Its state is kept at its own reference time and moved on only
  // when an event involves it: a ball nothing happens to costs nothing per event. Its path, the
  // time its motion state changes and the box it sweeps until then are computed once per state.
  struct Track {
    physics::BallState state;
    double reference_time_s = 0;
    double change_dt_s = kNever;      // from the reference time to its next state change
    physics::MotionState motion = physics::MotionState::Stationary;  // its state until then
    physics::PositionQuadratic path;  // from the reference time
    bool moves = false;               // sliding or rolling: its centre moves
    bool pocketed = false;
    int pocket = -1;
    // Until when its path holds for certain (its next own event: a state change, cushion, jaw or
    // pocket; pairs are predicted no further) and the box it sweeps (inflated by R) until then.
    double valid_until_s = kNever;
    Box box;
  };

  // Setting up (the constructor).
  void startBalls(const std::vector<physics::BallState>& input);
  void settle(int i, double time_s);
  physics::PositionQuadratic pathFrom(int i, double t) const;
  physics::BallState advanceTrack(const Track& b, double dt_s) const;

  // Predicting (one pass after each event, over the balls it changed).
  void prepareNext();
  void predictChanged();
  void forgetPairsOfChanged();
  void predictOwnOfChanged();
  void updateActiveBalls();
  void predictPairsOfChanged();
  void predictPairsOf(int i);
  void refreshEarliest();
  void handOverImpacts();
  PredictedEvent earliest() const;
  void predictOwn(int i);
  void predictCushions(int i, double* horizon, PredictedEvent* best_own);
  void predictJaws(int i, double* horizon, PredictedEvent* best_own);
  void predictPockets(int i, double* horizon, PredictedEvent* best_own);
  void predictPair(int i, int j);
  void rescan(int k);
  void solveAhead(int i);
  physics::RootSearchResult solveGap(const physics::PolynomialCoefficients& gap, double horizon);
  PredictedEvent absolute(PredictedEvent c) const;
  PredictedEvent pairCandidate(int i, int j) const;
  double& pairTime(int i, int j);

  // Resolving the event prepareNext() found.
  void resolveNext();
  void moveToEvent(int i);
  void resolveCushionContact(Event* event);
  void resolveBallContact(Event* event);
  void finishEvent(Event&& event);
  void markChanged(int i);
  SimulationResult finish();

  // The model: constant for the shot.
  const SimulationParams& params_;
  const TableGeometry& table_;
  std::vector<std::string> ball_ids_;
  double R_ = 0;  // ball radius, m
  std::vector<Box> cushion_boxes_, jaw_boxes_, pocket_boxes_;

  // The data: the balls, the clock and what the loop has predicted.
  SimulationResult result_;
  std::vector<Track> balls_;
  int n_ = 0;
  double now_ = 0;      // the last event's time, s: predictions are made from it
  double clock_s_ = 0;  // now_, or later after advanceTo()
  long passes_ = 0;     // prediction passes made (one per event, and one per stale prediction)
  bool prediction_due_ = true;  // the balls in changed_ have not been predicted again yet
  bool at_rest_ = false;
  bool first_pass_ = true;  // every ball is new; pairs of resting balls are left unpredicted
  PredictedEvent next_;     // the next event, once prepareNext() has found it
  double next_time_s_ = 0;  // its time, never before now_ (absolute times round)
  PredictedEvent last_;     // the contact resolved last, not to be found again at the same instant
  bool last_valid_ = false;

  // Predictions, as absolute times, stay valid until one of their balls changes its motion; only
  // those are solved again. own_: a ball's state change, cushion, jaw or pocket; pair times: when
  // balls i < j touch, at [i * n + j]; next_of_: each ball's earliest of its own and its pairs'.
  std::vector<PredictedEvent> own_, next_of_;
  // Left unset (filling n^2 entries would cost more than a whole shot among many resting balls):
  // a pair's time is read only through partners_, which lists only pairs whose time was written.
  std::unique_ptr<double[]> pair_time_;
  // Per ball, every ball it has a finite pair time with (and some it no longer has, and repeats;
  // right after a ball changed and was predicted again, exactly those it has): what a ball's
  // earliest candidate and a change of its motion need to look at, not every ball.
  std::vector<std::vector<int>> partners_;
  std::vector<char> listed_;  // in rescan()'s cleaned list, by ball
  // A pair's prediction is finite only while one of its balls moves (it is predicted again when
  // either changes), so the next event is the earliest candidate of a ball that moves or has an
  // event of its own ahead (a spinning ball's stop): only those "active" balls' earliest
  // candidates are kept, and a resting ball costs nothing per event.
  std::vector<int> active_, movers_;         // movers_: the active balls that move
  std::vector<char> is_active_, rescanned_;  // rescanned_: its candidate found anew
  // The balls resting at the start, by place; those that come to rest later are looked at one by
  // one (a few at most, in practice).
  RestingGrid resting_grid_;
  std::vector<int> resting_later_;
  std::vector<char> in_grid_, is_resting_later_;
  int on_table_ = 0;                  // balls not pocketed
  std::vector<int> self_predicting_;  // changed balls that predict their pairs with changed balls
  std::vector<int> changed_;          // balls whose motion changed at the last event
  std::vector<char> is_changed_;      // the same, by ball
  // Balls exactly at rest at the start: nothing to predict in the first pass (no event of their
  // own, and their pairs with the moving balls are predicted by those); only counted.
  std::vector<char> starts_at_rest_;
  long resting_from_start_ = 0;
  // predictCushions()' scratch (kept to allocate nothing per event): the cushions a ball's box
  // reaches, their gaps, and when each roughly closes.
  struct CushionGap {
    double rough_time_s;
    int cushion;
    physics::PolynomialCoefficients gap;
  };
  std::vector<CushionGap> cushion_gaps_;
  // Impacts solved ahead on the caller's worker, if one was handed over.
  CushionSolveAhead ahead_;
  bool solve_ahead_ = false;
};

}  // namespace baize::engine
