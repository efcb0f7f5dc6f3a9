// A table as data: its playing surface, cushions, pockets and markings, loaded from a JSON file
// (docs/tables.md describes the format), and the geometry the event loop collides with.
//
// Table frame: origin at the centre of the playing surface, x along the long side (towards the
// foot / top cushion), y across, metres. The cushion noses lie on the edges of the rectangle
// [-length/2, length/2] x [-width/2, width/2]; pockets sit at the four corners and the middles of
// the long sides.
#pragma once

#include <Eigen/Core>
#include <Eigen/Geometry>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <vector>

#include "engine/io/assets_directory.h"  // builtinTable reads from it; callers list its files
#include "engine/sim/table_geometry.h"
#include "physics/cushion_model.h"

namespace baize::engine {

enum class TableKind { Pool, Snooker };
enum class PocketKind { Corner, Side };

// The shape of one kind of pocket, as given in the file (angles already in radians).
struct PocketSpec {
  double mouth_width_m = 0;     // between the jaw tips (where rail and facing lines meet)
  double facing_angle_rad = 0;  // between the rail nose and the facing, inside the cushion
  double jaw_radius_m = 0;      // rounding of the jaw tip, tangent to rail and facing
  double facing_length_m = 0;   // from the jaw tip along the facing
  double capture_offset_m = 0;  // capture-circle centre behind the mouth, along the pocket axis
  double capture_radius_m = 0;  // a ball whose centre enters the capture circle is pocketed
};

struct Pocket {
  PocketKind kind = PocketKind::Corner;
  // The jaw tips in outline order: the one reached first going counterclockwise, then the other.
  Eigen::Vector2d jaw_tips_m[2] = {Eigen::Vector2d::Zero(), Eigen::Vector2d::Zero()};
  Eigen::Vector2d mouth_centre_m = Eigen::Vector2d::Zero();
  Eigen::Vector2d axis = Eigen::Vector2d::Zero();  // unit, from the mouth out of the table
  Circle capture;
};

struct PoolMarkings {
  int diamonds_per_rail_segment = 0;
  double diamond_setback_m = 0;             // from the cushion nose outwards to the diamond centre
  std::vector<Eigen::Vector2d> diamonds_m;  // on the rail tops, outside the playing rectangle
  Eigen::Vector2d foot_spot_m = Eigen::Vector2d::Zero();  // centre of the foot half (+x)
  Eigen::Vector2d head_spot_m = Eigen::Vector2d::Zero();  // centre of the head half (-x)
  double head_string_x_m = 0;  // the line x = head_string_x_m behind which the cue ball breaks
};

struct SnookerMarkings {
  double baulk_line_x_m = 0;  // the baulk line is x = baulk_line_x_m (bottom cushion at -x)
  double d_radius_m = 0;      // the D: half-disc behind the baulk line centred on the brown spot
  Eigen::Vector2d yellow_spot_m, green_spot_m, brown_spot_m, blue_spot_m, pink_spot_m, black_spot_m;
};

// The normal speed (m/s, the ball's velocity into the cushion) up to which Mathavan, Jackson &
// Parkin (2010) state their rigid-cushion model holds; impacts above it are reported, not changed.
inline constexpr double kRigidCushionValidNormalSpeedMps = 2.5;
inline constexpr const char* kValidNormalSpeedKey = "valid_normal_speed_mps";

struct Table {
  std::string source;  // the file it was read from (or the document's name), for messages
  std::string name;
  std::string description;
  TableKind kind = TableKind::Pool;
  double length_m = 0;  // playing surface, between the cushion noses
  double width_m = 0;
  double cushion_contact_height_m = 0;  // height of the cushion nose contact above the slate
  // The cushion model's defaults on this table (the file's optional "cushion" object; without it
  // the Mathavan 2010 paper's snooker values). A scene's physics.cushion overrides them.
  double cushion_restitution = physics::CushionParams{}.restitution;  // e_e
  double cushion_friction = physics::CushionParams{}.cushion_friction;  // mu_w
  // The normal speed (m/s) up to which the cushion model is taken to hold on this table (the
  // "cushion" object's valid_normal_speed_mps); a scene's physics.cushion overrides it.
  double cushion_valid_normal_speed_mps = kRigidCushionValidNormalSpeedMps;
  PocketSpec corner_pocket, side_pocket;

  // Counterclockwise from the bottom-left corner: corner (-x,-y), side (-y), corner (+x,-y),
  // corner (+x,+y), side (+y), corner (-x,+y).
  std::vector<Pocket> pockets;
  // For each pocket k in order: its entry facing, its exit facing, then the rail from pocket k to
  // pocket k+1. Going counterclockwise the outline is: rail, entry jaw arc, entry facing, (the
  // pocket opening), exit facing, exit jaw arc, next rail.
  std::vector<CushionSegment> cushions;
  // For each pocket k: entry jaw arc, exit jaw arc (the outline crosses them clockwise).
  std::vector<JawArc> jaw_arcs;

  std::optional<PoolMarkings> pool_markings;        // set for pool tables
  std::optional<SnookerMarkings> snooker_markings;  // set for snooker tables
};

// Builds a table from a parsed JSON document; `source` names it in error messages. Throws
// std::invalid_argument naming the source, the key path, the value and what is allowed.
Table tableFromJson(const nlohmann::json& document, const std::string& source);

// Reads and validates a table file.
Table loadTable(const std::string& path);

// Checks that the table's pockets swallow every ball of radius `ball_radius_m` that passes their
// facings: the entrance through which a ball centre gets past them (the gates past converging
// facings' deep ends, or the part of the triangle they bound next to the closing line; for
// facings that do not converge, the parts of the closing line neither facing holds; docs/tables.md)
// must lie strictly inside the capture circle, or a ball could run past the facings without
// falling and leave the table. A table file cannot know the radius, so scenes check this where the
// table meets the ball set. Throws std::invalid_argument naming the table's source, the pocket,
// the key (corner_pocket.capture_offset_m or ...capture_radius_m) and its value, and the offsets
// or the smallest radius that would cover the entrance.
void checkCapturesCoverOpenings(const Table& table, double ball_radius_m);

// Whether `point` lies past both facings' deep ends of one of the table's pockets (beyond each deep
// end's line along its facing's inward normal): no facing holds a ball there, and
// checkCapturesCoverOpenings says nothing of a ball that starts there.
bool pastBothDeepEnds(const Table& table, const Eigen::Vector2d& point);

// Whether `point` lies in one of the table's pockets' capture circles (on its edge included): a
// ball whose centre starts there would start pocketed.
bool inCaptureCircle(const Table& table, const Eigen::Vector2d& point);

// The pockets' names in Table::pockets order, seen with +x to the right and +y up: "bottom-left",
// "bottom-middle", "bottom-right", "top-right", "top-middle", "top-left".
const std::vector<std::string>& pocketNames();

// The shipped tables: "pool-7ft", "pool-8ft", "pool-9ft", "snooker-12ft".
std::vector<std::string> builtinTableNames();
Table builtinTable(const std::string& name);

// The geometry the event loop collides with (engine/sim/table_geometry.h), its cushion outline
// included.
TableGeometry geometryOf(const Table& table);
// geometryOf(table), kept for the next call on the same thread and built again only when the
// table's cushions, jaw arcs or capture circles differ from the kept ones bit for bit: shots run
// back to back (a bench, a search over many shots, a batch) mostly share one table. The reference
// holds until the next call on this thread.
const TableGeometry& cachedGeometryOf(const Table& table);

}  // namespace baize::engine
