// The tables `baize stress` shoots on, and where a ball may be on each: the pocketless rectangle
// of the first stress runs, the 9 ft pool table and the 12 ft snooker table with their real
// pockets, jaws and facings (engine/io/table.h).
//
// "On the table" (docs/engine.md, "Stress and verification"): a ball that has not fallen into a
// pocket must have its centre
//   1. inside the cushion outline (engine/io/table.h, cushionOutline; TableGeometry::outline): the
//      polygon through the ends of every straight cushion nose in outline order (rails and pocket
//      facings; a jaw's rounding is replaced by its chord, which lies behind the rounding, and each
//      pocket's opening is closed by the straight line from the deep end of one facing to the deep
//      end of the other), and
//   2. not closer than R to any straight cushion where its contact point would lie between the
//      cushion's ends, nor closer than jaw radius + R to a jaw's centre within the jaw's angular
//      range (the contacts the event loop models; simulate() refuses the same as input).
// A ball running into a pocket passes the mouth between the facings and enters the capture circle
// before it reaches the closing line (the engine refuses tables whose capture circles do not cover
// the throat there for the balls in use: engine/io/table.h, checkCapturesCoverOpenings), so a ball
// centre beyond that line that is not pocketed has left the table. simulate() itself fails on
// condition 1 (BallLeftTableError); the stress checks add condition 2 and the overlap tolerance.
#pragma once

#include <Eigen/Core>
#include <string>
#include <vector>

#include "engine/io/ball_set.h"
#include "engine/io/scene.h"
#include "engine/io/table.h"
#include "engine/sim/shot_simulator.h"

namespace baize::engine {

enum class StressTableId { Rectangle, Pool9ft, Snooker12ft };

struct StressTable {
  StressTableId id = StressTableId::Rectangle;
  std::string name;      // "rectangle", "pool-9ft", "snooker-12ft" (the state files' "table")
  bool has_scene_table;  // a built-in table a scene can name (not the rectangle)
  engine::Table table;   // for the rectangle: only length_m and width_m are set
  engine::BallSet ball_set;
  engine::TableGeometry geometry;
  engine::SimulationParams params;  // as a scene on this table has them by default
};

// The table by id (built once per call: callers keep it).
StressTable makeStressTable(StressTableId id);
// The table of a scene, with the scene's physics (its overrides included).
StressTable stressTableOfScene(const engine::Scene& scene);
// The table by its name; throws std::invalid_argument naming it when unknown.
StressTableId stressTableIdByName(const std::string& name);

// Condition 1 and 2 above for a centre, with the overlap tolerance `slack_m` (m). Empty when the
// centre is on the table, else what is wrong ("beyond cushion 3 by 2e-06 m").
std::string offTableReason(const StressTable& table, const Eigen::Vector2d& centre, double slack_m);

// Whether the centre lies inside the capture circle of a pocket.
bool inPocket(const StressTable& table, const Eigen::Vector2d& centre);

}  // namespace baize::engine
