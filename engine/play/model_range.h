// Which cushion and jaw impacts of a shot lie beyond the cushion model's stated range: those whose
// normal speed (the ball's velocity into the cushion just before the impact) is above the scene's
// physics.cushion.valid_normal_speed_mps. Read from the recorded events after the run; it changes
// no result.
#pragma once

#include <vector>

#include "engine/io/scene.h"
#include "engine/sim/shot_events.h"
#include "engine/sim/table_geometry.h"

namespace baize::engine {

// The normal speed the scene's impacts are checked against, m/s: its
// physics.cushion.valid_normal_speed_mps, else its table's (kRigidCushionValidNormalSpeedMps unless
// the table file gives one).
double validNormalSpeedFor(const Scene& scene);

// The speed (m/s) at which a Cushion or Jaw event's ball moves into the cushion or jaw just before
// it: minus its velocity along the contact normal; 0 or less when it moves along or away. Throws
// std::invalid_argument for an event of another kind.
double impactNormalSpeedMps(const TableGeometry& table, const Event& event);

// The indices (into `events`) of the Cushion and Jaw events whose normal speed is above
// `valid_normal_speed_mps`, in order.
std::vector<long> impactsBeyondModelRange(const TableGeometry& table,
                                          const std::vector<Event>& events,
                                          double valid_normal_speed_mps);

// The same for a run of `scene`.
std::vector<long> impactsBeyondModelRange(const Scene& scene, const SceneRun& run);

}  // namespace baize::engine
