// The event loop: balls move in closed form on the cloth between events, and every event happens at
// an exact root of the polynomial that describes it (a quartic for two balls or a ball and a
// pocket's capture circle, a quadratic for a ball and a straight cushion). The earliest event is
// resolved by the physical model for it and the rest are predicted again.
//
// Table frame: origin anywhere on the slate, x and y in the table plane, z up; SI units.
#pragma once

#include <Eigen/Core>
#include <optional>
#include <string>
#include <vector>

#include "physics/ball_ball_impact.h"
#include "physics/cloth_motion.h"
#include "physics/cushion_exact_solver.h"
#include "physics/cushion_model.h"

namespace baize::engine {

// A straight cushion: the line the cushion's nose runs along at contact height, between two ends,
// with the unit normal pointing into the playing area. A ball touches it when its centre is R from
// the line (measured along the normal) and its contact point lies between the ends.
struct CushionSegment {
  Eigen::Vector2d start = Eigen::Vector2d::Zero();  // m
  Eigen::Vector2d end = Eigen::Vector2d::Zero();    // m
  Eigen::Vector2d inward_normal = Eigen::Vector2d::UnitY();
};

// A rounded cushion (a pocket's jaw tip): a circular arc of the nose line, centre and radius in the
// table plane, over the directions from the centre between start_angle and end_angle (rad,
// counter-clockwise from +x; end_angle may exceed pi). A ball touches it when its centre is
// radius + R from the centre in a direction within that range; the contact normal points from the
// centre to the ball.
struct CushionArc {
  Eigen::Vector2d centre = Eigen::Vector2d::Zero();  // m
  double radius_m = 0;
  double start_angle_rad = 0;
  double end_angle_rad = 0;
};

// A ball whose centre enters this circle has fallen into the pocket.
struct PocketCircle {
  Eigen::Vector2d centre = Eigen::Vector2d::Zero();  // m
  double radius_m = 0;
};

struct TableGeometry {
  std::vector<CushionSegment> cushions;
  std::vector<CushionArc> jaws;
  std::vector<PocketCircle> pockets;
};

// A table with a rectangular playing area and no pockets: four cushions, inward normals.
TableGeometry rectangularTable(double length_m, double width_m);

// Constants of a shot. The ball radius and mass come from `cushion` (and must agree with `cloth`
// and `ball_ball`, which simulate() checks).
struct SimulationParams {
  physics::ClothParams cloth = physics::poolCloth();
  physics::CushionParams cushion;  // the seed model; mass, radius and nose height of the balls
  physics::ExactSolverOptions cushion_solver;
  physics::BallBallParams ball_ball;
  long max_events = 100000;          // a shot needing more stops with an error saying so
  bool record_trajectories = false;  // fill SimulationResult::trajectories (costs memory only)
};

// Pool defaults throughout: 57.15 mm, 0.17 kg balls, the nose at 0.635 of the diameter above the
// slate, e_e 0.98 and mu_w 0.14 for the cushion (the seed's values), cloth friction 0.2.
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
  physics::BallState state;
  bool pocketed = false;
};

struct Event {
  double time_s = 0;
  EventKind kind = EventKind::StateChange;
  int ball = 0;
  int other = -1;                          // BallBall: the second ball
  int index = -1;                          // Cushion: the cushion; Pocket: the pocket
  std::vector<physics::BallState> before;  // the balls involved, just before (ball, then other)
  std::vector<physics::BallState> after;   // and just after
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

// Simulates until every ball is at rest or pocketed. Throws std::invalid_argument on invalid input
// (parameters, a non-finite state, overlapping balls, a ball off the table) and std::runtime_error
// when the shot needs more than max_events events.
SimulationResult simulate(const SimulationParams& params, const TableGeometry& table,
                          const std::vector<physics::BallState>& balls);

}  // namespace baize::engine
