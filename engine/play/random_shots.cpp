#include "engine/play/random_shots.h"

#include <cmath>
#include <random>
#include <stdexcept>
#include <string>

#include "engine/models/cushion_mathavan2010.h"
#include "engine/sim/contact_geometry.h"
#include "engine/sim/shot_simulator.h"

namespace baize::engine {

engine::Scene nineFootPoolScene() {
  engine::Scene scene;
  scene.table = engine::builtinTable("pool-9ft");
  scene.ball_set = engine::builtinBallSet("pool");
  scene.cue_ball = "cue";
  return scene;
}

std::vector<engine::Scene> randomSingleShots(int count, std::uint64_t seed) {
  std::mt19937_64 engine(seed);
  auto uniform = [&](double lo, double hi) {
    return lo + (hi - lo) * ((engine() >> 11) * 0x1.0p-53);
  };
  const engine::Scene base = nineFootPoolScene();
  const double R = base.ball_set.radius_m;
  const double x = base.table.length_m / 2 - R, y = base.table.width_m / 2 - R;
  // Between the rails, yet a corner pocket's capture circle reaches in: a ball there would start
  // pocketed, which no scene file may ask for either (loadScene refuses it).
  const auto startsInPocket = [&](const Eigen::Vector2d& p) {
    return engine::inCaptureCircle(base.table, p) || engine::pastBothDeepEnds(base.table, p);
  };
  std::vector<engine::Scene> shots;
  while (static_cast<int>(shots.size()) < count) {
    engine::Scene s = base;
    s.balls = {{"cue", {uniform(-x, x), uniform(-y, y)}}, {"1", {uniform(-x, x), uniform(-y, y)}}};
    if ((s.balls[0].position_m - s.balls[1].position_m).norm() < 2 * R) continue;
    if (startsInPocket(s.balls[0].position_m) || startsInPocket(s.balls[1].position_m)) continue;
    s.shot.speed_mps = uniform(0.5, 4);
    s.shot.heading_rad = uniform(-M_PI, M_PI);
    const double offset = uniform(0, 0.45), angle = uniform(-M_PI, M_PI);
    s.shot.side_offset = offset * std::cos(angle);
    s.shot.height_offset = offset * std::sin(angle);
    shots.push_back(s);
  }
  return shots;
}

namespace {

// Appends the impacts of `run`, the run of `shot`: each cushion and jaw contact moving into the
// cushion, as the incoming ball in the contact's local frame.
void appendCushionImpacts(const engine::Scene& shot, const engine::SceneRun& run,
                          std::vector<physics::BallVelocity>* impacts) {
  const engine::TableGeometry table = engine::geometryOf(shot.table);
  for (const engine::Event& event : run.result.events) {
    if (event.kind != engine::EventKind::Cushion && event.kind != engine::EventKind::Jaw) continue;
    const physics::BallState& ball = event.before[0];
    const engine::ContactFrame frame(
        engine::contactNormal(table, event.kind, event.index, ball.position));
    const physics::BallVelocity incoming = frame.toLocal(ball);
    if (incoming.v.y() > 0) impacts->push_back(incoming);  // the loop's rule for an impact
  }
}

// The Mathavan 2010 parameters of a shot's table and balls, with its physics.cushion overrides.
physics::CushionParams mathavanParamsOf(const engine::Scene& shot) {
  const engine::ModelDefaults defaults = engine::modelDefaultsFor(shot);
  const engine::SimulationParams params = engine::simulationParamsFor(shot);
  if (!shot.overrides.cushion)
    return engine::impactParams(engine::readMathavan2010(defaults, nullptr), params);
  const engine::JsonReader overrides(*shot.overrides.cushion, shot.overrides.source,
                                     "physics.cushion");
  return engine::impactParams(engine::readMathavan2010(defaults, &overrides), params);
}

}  // namespace

std::vector<physics::BallVelocity> cushionImpactsOf(const std::vector<engine::Scene>& shots,
                                                    physics::CushionParams* params) {
  std::vector<physics::BallVelocity> impacts;
  for (std::size_t i = 0; i < shots.size(); ++i) {
    const engine::Scene& shot = shots[i];
    // One table and ball set throughout, so that one cushion stands for every impact.
    if (shot.table.name != shots[0].table.name || shot.ball_set.name != shots[0].ball_set.name)
      throw std::logic_error("cushionImpactsOf: the shots do not share one table and ball set");
    engine::SceneRun run;
    try {
      run = engine::runScene(shot);
    } catch (const std::exception& failure) {
      throw std::runtime_error("random single shot " + std::to_string(i + 1) + ": " +
                               failure.what());
    }
    appendCushionImpacts(shot, run, &impacts);
  }
  // The Mathavan 2010 parameters of the shots' table and balls (random shots override none).
  if (!shots.empty()) *params = mathavanParamsOf(shots[0]);
  return impacts;
}

std::vector<physics::BallVelocity> cushionImpactsOfScene(const engine::Scene& scene,
                                                         physics::CushionParams* params) {
  const std::string model = engine::simulationParamsFor(scene).cushion->name();
  if (model != "exact" && model != "tabulated" && model != "paper")
    throw std::invalid_argument("its cushion model is \"" + model +
                                "\" (physics.cushion.model); its impacts are scored on the "
                                "Mathavan 2010 model's solvers, so it must be exact, tabulated "
                                "or paper");
  std::vector<physics::BallVelocity> impacts;
  appendCushionImpacts(scene, engine::runScene(scene), &impacts);
  *params = mathavanParamsOf(scene);
  return impacts;
}

}  // namespace baize::engine
