#include "engine/play/model_range.h"

#include <stdexcept>

#include "engine/sim/contact_geometry.h"

namespace baize::engine {

double validNormalSpeedFor(const Scene& scene) {
  return scene.overrides.valid_normal_speed_mps.value_or(
      scene.table.cushion_valid_normal_speed_mps);
}

double impactNormalSpeedMps(const TableGeometry& table, const Event& event) {
  if (event.kind != EventKind::Cushion && event.kind != EventKind::Jaw) {
    throw std::invalid_argument(std::string("a ") + eventKindName(event.kind) +
                                " event is not allowed: only cushion and jaw events have a "
                                "normal speed");
  }
  const physics::BallState& before = event.before[0];
  const Eigen::Vector2d normal = contactNormal(table, event.kind, event.index, before.position);
  return -before.velocity.head<2>().dot(normal);
}

std::vector<long> impactsBeyondModelRange(const TableGeometry& table,
                                          const std::vector<Event>& events,
                                          double valid_normal_speed_mps) {
  std::vector<long> beyond;
  for (std::size_t i = 0; i < events.size(); ++i) {
    const EventKind kind = events[i].kind;
    if (kind != EventKind::Cushion && kind != EventKind::Jaw) continue;
    if (impactNormalSpeedMps(table, events[i]) > valid_normal_speed_mps) {
      beyond.push_back(static_cast<long>(i));
    }
  }
  return beyond;
}

std::vector<long> impactsBeyondModelRange(const Scene& scene, const SceneRun& run) {
  return impactsBeyondModelRange(cachedGeometryOf(scene.table), run.result.events,
                                 validNormalSpeedFor(scene));
}

}  // namespace baize::engine
