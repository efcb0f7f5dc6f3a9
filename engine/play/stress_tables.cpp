#include "engine/play/stress_tables.h"

#include <cmath>
#include <sstream>
#include <stdexcept>

#include "engine/io/scene.h"

namespace baize::engine {
namespace {

// The pocketless table of the first stress runs: a 9 ft playing surface, m.
constexpr double kRectangleLength_m = 2.54;
constexpr double kRectangleWidth_m = 1.27;

// Whether the direction from the jaw's centre to p lies within the jaw's angular range.
bool withinJawRange(const engine::JawArc& jaw, const Eigen::Vector2d& p) {
  const Eigen::Vector2d d = p - jaw.centre_m;
  double angle = std::atan2(d.y(), d.x());
  while (angle < jaw.start_angle_rad) angle += 2 * M_PI;
  while (angle >= jaw.start_angle_rad + 2 * M_PI) angle -= 2 * M_PI;
  return angle <= jaw.end_angle_rad;
}

// The outline is the engine's (TableGeometry::outline); it must surround the table's centre, or
// every ball would count as off the table.
void checkOutline(const StressTable& t) {
  const std::vector<Eigen::Vector2d>& outline = t.geometry.outline;
  if (outline.size() < 3 || !engine::insideOutline(outline, Eigen::Vector2d::Zero())) {
    throw std::invalid_argument("table " + t.name +
                                ": its cushion outline does not surround the table's centre");
  }
}

}  // namespace

StressTable makeStressTable(StressTableId id) {
  StressTable t;
  t.id = id;
  if (id == StressTableId::Rectangle) {
    t.name = "rectangle";
    t.has_scene_table = false;
    t.table.length_m = kRectangleLength_m;
    t.table.width_m = kRectangleWidth_m;
    t.ball_set = engine::builtinBallSet("pool");
    t.geometry = engine::rectangularTable(kRectangleLength_m, kRectangleWidth_m);
    t.params = engine::poolSimulationParams();
  } else {
    const bool pool = id == StressTableId::Pool9ft;
    t.name = pool ? "pool-9ft" : "snooker-12ft";
    t.has_scene_table = true;
    engine::Scene scene;
    scene.table = engine::builtinTable(t.name);
    scene.ball_set = engine::builtinBallSet(pool ? "pool" : "snooker");
    t.table = scene.table;
    t.ball_set = scene.ball_set;
    t.geometry = engine::geometryOf(scene.table);
    t.params = engine::simulationParamsFor(scene);
    // The escape check's premise (stress_tables.h), as a scene on this table checks it.
    engine::checkCapturesCoverOpenings(t.table, t.ball_set.radius_m);
  }
  checkOutline(t);
  return t;
}

StressTable stressTableOfScene(const engine::Scene& scene) {
  StressTable t;
  t.id = StressTableId::Pool9ft;  // unused for a scene's table
  t.name = scene.table.name;
  t.has_scene_table = true;
  t.table = scene.table;
  t.ball_set = scene.ball_set;
  t.geometry = engine::geometryOf(scene.table);
  t.params = engine::simulationParamsFor(scene);
  checkOutline(t);  // the escape check's premise was checked when the scene was loaded
  return t;
}

StressTableId stressTableIdByName(const std::string& name) {
  if (name == "rectangle") return StressTableId::Rectangle;
  if (name == "pool-9ft") return StressTableId::Pool9ft;
  if (name == "snooker-12ft") return StressTableId::Snooker12ft;
  throw std::invalid_argument("stress table '" + name +
                              "' is not allowed: it must be rectangle, pool-9ft or snooker-12ft");
}

std::string offTableReason(const StressTable& table, const Eigen::Vector2d& centre,
                           double slack_m) {
  const double R = table.params.ball.radius_m;
  std::ostringstream why;
  why.precision(17);
  if (!engine::insideOutline(table.geometry.outline, centre)) {
    why << "centre outside the cushion outline";
    return why.str();
  }
  for (std::size_t k = 0; k < table.geometry.cushions.size(); ++k) {
    const engine::CushionSegment& c = table.geometry.cushions[k];
    const Eigen::Vector2d along = c.end_m - c.start_m;
    const double s = (centre - c.start_m).dot(along) / along.squaredNorm();
    const double distance = c.inward_normal.dot(centre - c.start_m);
    if (s >= 0 && s <= 1 && distance < R - slack_m) {
      why << "beyond cushion " << k << " by " << R - distance << " m";
      return why.str();
    }
  }
  for (std::size_t k = 0; k < table.geometry.jaws.size(); ++k) {
    const engine::JawArc& jaw = table.geometry.jaws[k];
    const double distance = (centre - jaw.centre_m).norm();
    if (distance < jaw.radius_m + R - slack_m && withinJawRange(jaw, centre)) {
      why << "inside jaw " << k << " by " << jaw.radius_m + R - distance << " m";
      return why.str();
    }
  }
  return "";
}

bool inPocket(const StressTable& table, const Eigen::Vector2d& centre) {
  for (const engine::Circle& c : table.geometry.pockets) {
    if ((centre - c.centre_m).norm() < c.radius_m) return true;
  }
  return false;
}

}  // namespace baize::engine
