// Helpers for the model tests: a model chosen as a scene's "physics" group would choose it, and a
// ball rolling on the cloth.
#pragma once

#include <algorithm>
#include <nlohmann/json.hpp>
#include <stdexcept>

#include "engine/models/model_registry.h"
#include "engine/sim/shot_simulator.h"

namespace baize::engine {

// The model a "physics.cushion" group gives, with the pool defaults.
inline std::shared_ptr<const CushionContactModel> cushionModel(const nlohmann::json& group) {
  return cushionModels().read(JsonReader(group, "test.json", "physics.cushion"), ModelDefaults{});
}

// The model a "physics.ball_ball" group gives, with the pool defaults.
inline std::shared_ptr<const BallBallContactModel> ballBallModel(const nlohmann::json& group) {
  return ballBallModels().read(JsonReader(group, "test.json", "physics.ball_ball"),
                               ModelDefaults{});
}

inline physics::BallState rollingBallAt(double x, double y, double vx, double vy, double radius_m) {
  physics::BallState b;
  b.position = {x, y};
  b.velocity = {vx, vy, 0};
  b.angular_velocity = {-vy / radius_m, vx / radius_m, 0};  // rolling: v + R z x w = 0
  return b;
}

inline const Event& firstEventOf(const SimulationResult& r, EventKind kind) {
  const auto hit = std::find_if(r.events.begin(), r.events.end(),
                                [&](const Event& e) { return e.kind == kind; });
  if (hit == r.events.end()) throw std::logic_error("no such event");
  return *hit;
}

}  // namespace baize::engine
