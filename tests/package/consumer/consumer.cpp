// Builds a scene in code (no scene file), simulates it with the installed Baize and checks the
// result: the cue ball moved and hit the ball it was aimed at, the events run forward in time,
// and the balls end at rest with less energy than the strike gave them. Exit 0 when all hold.
#include <cmath>
#include <iostream>

#include "engine/io/scene.h"
#include "engine/play/shot_outcome.h"

namespace {

int failures = 0;

void check(bool holds, const char* what) {
  if (!holds) {
    std::cerr << "FAIL: " << what << "\n";
    ++failures;
  }
}

double kineticEnergy_J(const Eigen::Vector3d& v_mps, const Eigen::Vector3d& w_radps, double mass_kg,
                       double radius_m) {
  const double inertia = 0.4 * mass_kg * radius_m * radius_m;  // solid sphere, 2/5 m R^2
  return 0.5 * mass_kg * v_mps.squaredNorm() + 0.5 * inertia * w_radps.squaredNorm();
}

}  // namespace

int main() {
  using namespace baize::engine;
  Scene scene;
  scene.source = "consumer";
  scene.table = builtinTable("pool-9ft");  // from the installed assets
  scene.ball_set = builtinBallSet("pool");
  scene.cue_ball = "cue";
  const Eigen::Vector2d cue_start(-0.6, 0.05), object_start(0.3, 0.0);
  scene.balls = {{"cue", cue_start}, {"1", object_start}};
  scene.shot.speed_mps = 2.5;
  scene.shot.heading_rad = std::atan2(object_start.y() - cue_start.y(),
                                      object_start.x() - cue_start.x());
  scene.shot.height_offset = 0.2;

  const SceneRun run = runScene(scene);
  const ShotOutcome outcome = shotOutcome(run, "cue");
  const double mass = scene.ball_set.mass_kg, radius = scene.ball_set.radius_m;

  check((outcome.cue_ball_final_m - cue_start).norm() > radius, "the cue ball moved");
  check(outcome.first_hit && *outcome.first_hit == "1", "the cue ball hit the 1 ball first");
  check(!run.result.events.empty(), "the shot has events");
  for (std::size_t i = 1; i < run.result.events.size(); ++i)
    check(run.result.events[i].time_s >= run.result.events[i - 1].time_s, "events in time order");
  // Only the cue ball moves after the strike; every ball's energy counts at the end.
  const double start_energy = kineticEnergy_J(run.strike.ball.v, run.strike.ball.w, mass, radius);
  double end_energy = 0;
  for (const BallRecord& b : run.result.final_balls)
    end_energy += kineticEnergy_J(b.state.velocity, b.state.angular_velocity, mass, radius);
  check(start_energy > 0, "the strike gave the cue ball energy");
  check(end_energy < start_energy, "the energy went down");
  std::cout << "events: " << run.result.events.size() << ", cue ball stopped at ["
            << outcome.cue_ball_final_m.x() << ", " << outcome.cue_ball_final_m.y()
            << "] m, energy " << start_energy << " J -> " << end_energy << " J\n";
  return failures == 0 ? 0 : 1;
}
