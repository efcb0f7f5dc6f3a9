#include "tools/baize/stress_tables.h"

#include <cmath>
#include <sstream>
#include <stdexcept>

#include "engine/scene.h"

namespace baize::tools {
namespace {

// The pocketless table of the first stress runs: a 9 ft playing surface, m.
constexpr double kRectangleLength_m = 2.54;
constexpr double kRectangleWidth_m = 1.27;

// Crossing-number test: whether p lies inside the simple polygon (boundary points may go
// either way; callers only care about centres at least R - slack from the boundary).
bool insidePolygon(const std::vector<Eigen::Vector2d>& polygon, const Eigen::Vector2d& p) {
  bool inside = false;
  for (std::size_t i = 0, j = polygon.size() - 1; i < polygon.size(); j = i++) {
    const Eigen::Vector2d& a = polygon[i];
    const Eigen::Vector2d& b = polygon[j];
    if ((a.y() > p.y()) != (b.y() > p.y()) &&
        p.x() < (b.x() - a.x()) * (p.y() - a.y()) / (b.y() - a.y()) + a.x()) {
      inside = !inside;
    }
  }
  return inside;
}

// Whether the direction from the jaw's centre to p lies within the jaw's angular range.
bool withinJawRange(const engine::JawArc& jaw, const Eigen::Vector2d& p) {
  const Eigen::Vector2d d = p - jaw.centre_m;
  double angle = std::atan2(d.y(), d.x());
  while (angle < jaw.start_angle_rad) angle += 2 * M_PI;
  while (angle >= jaw.start_angle_rad + 2 * M_PI) angle -= 2 * M_PI;
  return angle <= jaw.end_angle_rad;
}

// The cushion noses are listed in outline order, counterclockwise (engine/table.h), so their ends
// in turn trace the outline with jaw roundings cut by chords and pocket openings closed.
void traceOutline(StressTable* t) {
  for (const engine::CushionSegment& c : t->geometry.cushions) {
    t->outline.push_back(c.start_m);
    t->outline.push_back(c.end_m);
  }
  if (t->outline.size() < 3 || !insidePolygon(t->outline, Eigen::Vector2d::Zero())) {
    throw std::invalid_argument("table " + t->name +
                                ": its cushion outline does not surround the table's centre");
  }
}

// The escape check's premise (stress_tables.h): a ball centre reaching the line that closes a
// pocket's opening, R clear of both facings, is already inside the pocket's capture circle. Checked
// at kCaptureSamples points along each closing line; a table that breaks it is refused.
constexpr int kCaptureSamples = 1000;

void checkCapturesCoverOpenings(const StressTable& t) {
  const double R = t.params.cushion.radius_m;
  const std::vector<engine::CushionSegment>& noses = t.geometry.cushions;
  for (std::size_t k = 0; k < t.table.pockets.size(); ++k) {
    if (noses.size() < 3 * k + 2 || noses[3 * k].pocket != static_cast<int>(k) ||
        noses[3 * k + 1].pocket != static_cast<int>(k)) {
      throw std::invalid_argument("table " + t.name + ": pocket " + std::to_string(k) +
                                  "'s facings are not where engine/table.h lists them");
    }
    const engine::CushionSegment& entry = noses[3 * k];
    const engine::CushionSegment& exit = noses[3 * k + 1];
    for (int i = 0; i <= kCaptureSamples; ++i) {
      const Eigen::Vector2d p =
          entry.end_m + (static_cast<double>(i) / kCaptureSamples) * (exit.start_m - entry.end_m);
      const bool reachable = entry.inward_normal.dot(p - entry.start_m) >= R &&
                             exit.inward_normal.dot(p - exit.start_m) >= R;
      if (reachable &&
          (p - t.table.pockets[k].capture.centre_m).norm() >= t.table.pockets[k].capture.radius_m) {
        throw std::invalid_argument(
            "table " + t.name + ": a ball can pass the ends of pocket " + std::to_string(k) +
            "'s facings outside its capture circle, so escapes cannot be told from pocketed balls");
      }
    }
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
  }
  traceOutline(&t);
  checkCapturesCoverOpenings(t);
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
  traceOutline(&t);
  checkCapturesCoverOpenings(t);
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
  const double R = table.params.cushion.radius_m;
  std::ostringstream why;
  why.precision(17);
  if (!insidePolygon(table.outline, centre)) {
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

}  // namespace baize::tools
