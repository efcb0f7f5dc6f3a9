#include "engine/io/table.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <limits>
#include <map>
#include <mutex>
#include <stdexcept>
#include <utility>

#include "engine/io/assets_directory.h"
#include "engine/io/json_reader.h"
#include "physics/value_text.h"

namespace baize::engine {
namespace {

using Eigen::Vector2d;

constexpr double kPi = 3.14159265358979323846;
constexpr double kRadiansPerDegree = kPi / 180.0;
// Significant digits of the limits a capture-circle refusal suggests: enough to land within a few
// micrometres of the exact limit, few enough to type. They are rounded towards the allowed side.
constexpr int kSuggestedLimitDigits = 6;

Vector2d leftNormal(const Vector2d& direction) { return Vector2d(-direction.y(), direction.x()); }
Vector2d rightNormal(const Vector2d& direction) { return Vector2d(direction.y(), -direction.x()); }

// The widest facing angle a table file may give, deg (see readPocketSpec).
constexpr double kMaxFacingAngle_deg = 170;

PocketSpec readPocketSpec(const JsonReader& pocket) {
  pocket.requireExactKeys({"mouth_width_m", "facing_angle_deg", "jaw_radius_m", "facing_length_m",
                           "capture_offset_m", "capture_radius_m"});
  PocketSpec spec;
  spec.mouth_width_m = pocket.positiveNumber("mouth_width_m");
  const double facing_angle_deg = pocket.finiteNumber("facing_angle_deg");
  // At 90 degrees or less the facings would open outwards or fold back; towards 180 a facing
  // folds back along its rail (no real pocket: 100 to 145 degrees), and near it the pocket's
  // entrance degenerates (a probe found balls escaping the capture check within 1e-4 deg of 180).
  if (!(facing_angle_deg > 90 && facing_angle_deg <= kMaxFacingAngle_deg)) {
    pocket.reject("facing_angle_deg",
                  "it must lie in (90, " + physics::valueText(kMaxFacingAngle_deg) + "] degrees");
  }
  spec.facing_angle_rad = facing_angle_deg * kRadiansPerDegree;
  spec.jaw_radius_m = pocket.positiveNumber("jaw_radius_m");
  spec.facing_length_m = pocket.positiveNumber("facing_length_m");
  spec.capture_offset_m = pocket.nonNegativeNumber("capture_offset_m");
  spec.capture_radius_m = pocket.positiveNumber("capture_radius_m");
  // The rounding must end on the facing, not beyond it.
  const double tangent_distance_m = spec.jaw_radius_m / std::tan(spec.facing_angle_rad / 2);
  if (!(tangent_distance_m < spec.facing_length_m)) {
    pocket.reject("jaw_radius_m",
                  "the jaw rounding must end on the facing: jaw_radius_m / "
                  "tan(facing_angle / 2) must be less than facing_length_m");
  }
  return spec;
}

// Distance from a pocket's centre point (corner or middle of the rail) to each of its jaw tips,
// measured along the rail.
double jawTipSetback(PocketKind kind, const PocketSpec& spec) {
  return kind == PocketKind::Corner ? spec.mouth_width_m / std::sqrt(2.0) : spec.mouth_width_m / 2;
}

// Length of the rail along the nose taken by a pocket's jaw: tip setback plus the rounding.
double railTakenByJaw(PocketKind kind, const PocketSpec& spec) {
  return jawTipSetback(kind, spec) + spec.jaw_radius_m / std::tan(spec.facing_angle_rad / 2);
}

// One jaw: the tip on the rail line, the rail direction towards the pocket and the outward normal.
struct Jaw {
  Vector2d tip;
  Vector2d towards_pocket;
  Vector2d outward;
};

struct JawGeometry {
  Vector2d rail_tangent_point;
  Vector2d facing_tangent_point;
  Vector2d facing_end;
  JawArc arc;
};

JawGeometry buildJaw(const Jaw& jaw, const PocketSpec& spec, int pocket) {
  const double phi = spec.facing_angle_rad;
  // The facing leaves the rail line turning away from the table by pi - phi.
  const Vector2d facing = -std::cos(phi) * jaw.towards_pocket + std::sin(phi) * jaw.outward;
  const double tangent_distance = spec.jaw_radius_m / std::tan(phi / 2);
  JawGeometry geometry;
  geometry.rail_tangent_point = jaw.tip - tangent_distance * jaw.towards_pocket;
  geometry.facing_tangent_point = jaw.tip + tangent_distance * facing;
  geometry.facing_end = jaw.tip + spec.facing_length_m * facing;
  // The arc centre is inside the cushion, one radius from both lines.
  geometry.arc.centre_m = geometry.rail_tangent_point + spec.jaw_radius_m * jaw.outward;
  geometry.arc.radius_m = spec.jaw_radius_m;
  geometry.arc.pocket = pocket;
  const Vector2d to_rail = geometry.rail_tangent_point - geometry.arc.centre_m;
  const Vector2d to_facing = geometry.facing_tangent_point - geometry.arc.centre_m;
  const double rail_angle = std::atan2(to_rail.y(), to_rail.x());
  const double facing_angle = std::atan2(to_facing.y(), to_facing.x());
  const double sweep = kPi - phi;
  // The arc turns from one tangent point to the other by pi - phi; start where it turns
  // counterclockwise.
  const bool counterclockwise_from_rail =
      to_rail.x() * to_facing.y() - to_rail.y() * to_facing.x() > 0;
  geometry.arc.start_angle_rad = counterclockwise_from_rail ? rail_angle : facing_angle;
  geometry.arc.end_angle_rad = geometry.arc.start_angle_rad + sweep;
  return geometry;
}

CushionSegment segment(const Vector2d& start, const Vector2d& end, int pocket) {
  CushionSegment piece;
  piece.start_m = start;
  piece.end_m = end;
  piece.inward_normal = leftNormal((end - start).normalized());
  piece.pocket = pocket;
  return piece;
}

// Pockets counterclockwise from the bottom-left corner, each as its centre point and the
// counterclockwise travel directions along the rail arriving at it and leaving it.
struct PocketPlace {
  PocketKind kind;
  Vector2d centre;
  Vector2d arriving;
  Vector2d leaving;
};

std::vector<PocketPlace> pocketPlaces(double half_length, double half_width) {
  const Vector2d east(1, 0), west(-1, 0), north(0, 1), south(0, -1);
  return {{PocketKind::Corner, {-half_length, -half_width}, south, east},
          {PocketKind::Side, {0, -half_width}, east, east},
          {PocketKind::Corner, {half_length, -half_width}, east, north},
          {PocketKind::Corner, {half_length, half_width}, north, west},
          {PocketKind::Side, {0, half_width}, west, west},
          {PocketKind::Corner, {-half_length, half_width}, west, south}};
}

void buildCushions(Table& table) {
  const auto places = pocketPlaces(table.length_m / 2, table.width_m / 2);
  std::vector<JawGeometry> entries, exits;
  for (std::size_t k = 0; k < places.size(); ++k) {
    const PocketPlace& place = places[k];
    const PocketSpec& spec =
        place.kind == PocketKind::Corner ? table.corner_pocket : table.side_pocket;
    const double setback = jawTipSetback(place.kind, spec);
    const Jaw entry{place.centre - setback * place.arriving, place.arriving,
                    rightNormal(place.arriving)};
    const Jaw exit{place.centre + setback * place.leaving, -place.leaving,
                   rightNormal(place.leaving)};
    entries.push_back(buildJaw(entry, spec, static_cast<int>(k)));
    exits.push_back(buildJaw(exit, spec, static_cast<int>(k)));

    Pocket pocket;
    pocket.kind = place.kind;
    pocket.jaw_tips_m[0] = entry.tip;
    pocket.jaw_tips_m[1] = exit.tip;
    pocket.mouth_centre_m = (entry.tip + exit.tip) / 2;
    pocket.axis = (entry.outward + exit.outward).normalized();
    pocket.capture.centre_m = pocket.mouth_centre_m + spec.capture_offset_m * pocket.axis;
    pocket.capture.radius_m = spec.capture_radius_m;
    table.pockets.push_back(pocket);
  }
  for (std::size_t k = 0; k < places.size(); ++k) {
    const int index = static_cast<int>(k);
    const JawGeometry& next_entry = entries[(k + 1) % places.size()];
    table.cushions.push_back(
        segment(entries[k].facing_tangent_point, entries[k].facing_end, index));
    table.cushions.push_back(segment(exits[k].facing_end, exits[k].facing_tangent_point, index));
    table.cushions.push_back(
        segment(exits[k].rail_tangent_point, next_entry.rail_tangent_point, -1));
    table.jaw_arcs.push_back(entries[k].arc);
    table.jaw_arcs.push_back(exits[k].arc);
  }
}

// The facings of one pocket converge (facing angle above 90 degrees); they must not cross.
void checkFacingsDoNotCross(const Table& table, const JsonReader& corner, const JsonReader& side) {
  for (std::size_t k = 0; k < table.pockets.size(); ++k) {
    const Pocket& pocket = table.pockets[k];
    const Vector2d across = pocket.jaw_tips_m[1] - pocket.jaw_tips_m[0];
    const double entry_side = across.dot(table.cushions[3 * k].end_m - pocket.mouth_centre_m);
    const double exit_side = across.dot(table.cushions[3 * k + 1].start_m - pocket.mouth_centre_m);
    if (!(entry_side < 0 && exit_side > 0)) {
      (pocket.kind == PocketKind::Corner ? corner : side)
          .reject("facing_length_m",
                  "the two facings of a pocket converge and must end before "
                  "they meet on the pocket axis");
    }
  }
}

void checkRailsRemain(const Table& table, const JsonReader& corner, const JsonReader& side) {
  const double short_rail_m =
      table.width_m - 2 * railTakenByJaw(PocketKind::Corner, table.corner_pocket);
  if (!(short_rail_m > 0)) {
    corner.reject("mouth_width_m",
                  "the corner mouths and jaw roundings take the whole short rail "
                  "(width " +
                      physics::valueText(table.width_m) + " m)");
  }
  const double long_rail_m = table.length_m / 2 -
                             railTakenByJaw(PocketKind::Corner, table.corner_pocket) -
                             railTakenByJaw(PocketKind::Side, table.side_pocket);
  if (!(long_rail_m > 0)) {
    side.reject("mouth_width_m",
                "the corner and side mouths and jaw roundings take the whole long "
                "rail between them (half length " +
                    physics::valueText(table.length_m / 2) + " m)");
  }
}

PoolMarkings readPoolMarkings(const JsonReader& markings, const Table& table) {
  markings.requireExactKeys({"diamonds_per_rail_segment", "diamond_setback_m"});
  PoolMarkings pool;
  pool.diamonds_per_rail_segment = markings.integer("diamonds_per_rail_segment", 1, 20);
  pool.diamond_setback_m = markings.positiveNumber("diamond_setback_m");
  const double half_length = table.length_m / 2, half_width = table.width_m / 2;
  const int count = pool.diamonds_per_rail_segment;
  for (int i = 1; i <= count; ++i) {
    const double fraction = static_cast<double>(i) / (count + 1);
    // Long rails: two segments each (corner to side pocket); short rails: one segment.
    for (const double y :
         {-half_width - pool.diamond_setback_m, half_width + pool.diamond_setback_m}) {
      pool.diamonds_m.emplace_back(-half_length + fraction * half_length, y);
      pool.diamonds_m.emplace_back(fraction * half_length, y);
    }
    for (const double x :
         {-half_length - pool.diamond_setback_m, half_length + pool.diamond_setback_m}) {
      pool.diamonds_m.emplace_back(x, -half_width + fraction * table.width_m);
    }
  }
  pool.foot_spot_m = Vector2d(half_length / 2, 0);
  pool.head_spot_m = Vector2d(-half_length / 2, 0);
  pool.head_string_x_m = -half_length / 2;
  return pool;
}

SnookerMarkings readSnookerMarkings(const JsonReader& markings, const Table& table) {
  markings.requireExactKeys(
      {"baulk_line_from_bottom_cushion_m", "d_radius_m", "black_spot_from_top_cushion_m"});
  const double half_length = table.length_m / 2, half_width = table.width_m / 2;
  const double baulk_m = markings.positiveNumber("baulk_line_from_bottom_cushion_m");
  if (!(baulk_m < half_length)) {
    markings.reject("baulk_line_from_bottom_cushion_m", "it must be less than half the length");
  }
  const double d_radius_m = markings.positiveNumber("d_radius_m");
  if (!(d_radius_m < half_width && d_radius_m < baulk_m)) {
    markings.reject("d_radius_m",
                    "the D must fit on the table: less than half the width and "
                    "than the baulk line's distance from the bottom cushion");
  }
  const double black_m = markings.positiveNumber("black_spot_from_top_cushion_m");
  // The black spot lies between the pink spot (half way to the top cushion) and the top cushion.
  if (!(black_m < half_length / 2)) {
    markings.reject("black_spot_from_top_cushion_m",
                    "it must be less than a quarter of the length");
  }
  SnookerMarkings snooker;
  snooker.baulk_line_x_m = -half_length + baulk_m;
  snooker.d_radius_m = d_radius_m;
  // Seen from the baulk end (looking along +x) the yellow is on the right (-y), the green on the
  // left.
  snooker.yellow_spot_m = Vector2d(snooker.baulk_line_x_m, -d_radius_m);
  snooker.green_spot_m = Vector2d(snooker.baulk_line_x_m, d_radius_m);
  snooker.brown_spot_m = Vector2d(snooker.baulk_line_x_m, 0);
  snooker.blue_spot_m = Vector2d(0, 0);
  snooker.pink_spot_m = Vector2d(half_length / 2, 0);
  snooker.black_spot_m = Vector2d(half_length - black_m, 0);
  return snooker;
}

// `value` rounded to kSuggestedLimitDigits significant digits, strictly above it (`up`) or below,
// so that a limit a message suggests, used as written, satisfies a strict inequality.
double roundedLimit(double value, bool up) {
  if (!std::isfinite(value)) return value;
  const double magnitude = value == 0 ? 0 : std::floor(std::log10(std::abs(value)));
  const double scale = std::pow(10.0, kSuggestedLimitDigits - 1 - magnitude);
  double units = up ? std::ceil(value * scale) : std::floor(value * scale);
  if (up ? !(units / scale > value) : !(units / scale < value)) units += up ? 1 : -1;
  return units / scale;
}

double cross(const Vector2d& p, const Vector2d& q) { return p.x() * q.y() - p.y() * q.x(); }

std::string pointText(const Vector2d& p) {
  return "[" + physics::valueText(p.x()) + ", " + physics::valueText(p.y()) + "]";
}

// Facings whose inward normals' cross product is below this are parallel: at a corner pocket's
// 135 deg the computed normals differ by rounding (about 1e-15), and the lines through the deep
// ends would "meet" anywhere.
constexpr double kParallelFacings = 1e-9;

// A point this close to a facing's end (m, along it) counts as beside the facing: with parallel
// facings the closing line runs exactly through both deep ends' perpendiculars, and rounding
// (about 1e-16 m) must not put its points past them.
constexpr double kBesideSlack_m = 1e-9;

// The interval of t where f0 + f1 t lies in [lo, hi] (empty: first > second).
std::pair<double, double> linearWithin(double f0, double f1, double lo, double hi) {
  if (f1 == 0) {
    const bool inside = f0 >= lo && f0 <= hi;
    return inside ? std::make_pair(-std::numeric_limits<double>::infinity(),
                                   std::numeric_limits<double>::infinity())
                  : std::make_pair(1.0, 0.0);
  }
  const double t0 = (lo - f0) / f1, t1 = (hi - f0) / f1;
  return {std::min(t0, t1), std::max(t0, t1)};
}

// A pocket's entrance: what a ball centre must cross to leave the table there, as sets of points
// any one of which, inside the (convex) capture circle, keeps every ball in; empty when no ball
// gets past the facings. `entry` ends at its deep end a, `exit` starts at its deep end b; a facing
// holds a ball where the ball's centre lies beside it (between its ends) less than R in front of
// its line; past its deep end (beyond the line through a along its inward normal) nothing holds
// the ball.
//  - Facings that converge towards the back (every shipped pocket): the lines through a and b
//    along the inward normals meet at `meet` in front of the closing line [a, b], and every point
//    of the triangle a, b, meet is past both deep ends. A centre gets in only across those lines,
//    at least R in front of the facings: the gates [a + R n_entry, meet] and [b + R n_exit, meet].
//    Either the gates lie inside the circle, or the part of the triangle next to the closing line,
//    a, a + R n_entry, b + R n_exit, b, does (every way from the gates to the closing line
//    crosses [a + R n_entry, b + R n_exit]): two covers, the smaller circle wins (the second for
//    facings nearly along the rail, whose lines meet far out on the table).
//  - Facings parallel or diverging: the centre reaches the closing line only where neither facing
//    holds it; the ends of those parts of the line. (Jaw roundings are left out: they only hold
//    more balls, so leaving them out asks for more.)
std::vector<std::vector<Vector2d>> entranceCovers(const CushionSegment& entry,
                                                  const CushionSegment& exit,
                                                  const Vector2d& outward, double R) {
  const Vector2d a = entry.end_m, b = exit.start_m;
  const double across = cross(entry.inward_normal, exit.inward_normal);
  if (std::abs(across) > kParallelFacings) {
    const double s_meet =
        cross(b - a, exit.inward_normal) / across;  // a + s n_entry = b + t n_exit
    const Vector2d meet = a + s_meet * entry.inward_normal;
    if (s_meet > 0 && (meet - a).dot(outward) < 0) {
      if (!(s_meet > R)) return {};  // the lines meet within R of the deep ends: no way in
      const Vector2d a_gate = a + R * entry.inward_normal, b_gate = b + R * exit.inward_normal;
      return {{a_gate, b_gate, meet}, {a, a_gate, b_gate, b}};
    }
  }
  // The closing line p(t) = a + t (b - a), t in [0, 1]; where each facing holds the centre is an
  // interval of t (beside it and less than R in front: both linear in t).
  std::vector<std::pair<double, double>> held;
  for (const CushionSegment* facing : {&entry, &exit}) {
    const Vector2d along = facing->end_m - facing->start_m;
    const double slack = kBesideSlack_m * along.norm();
    const auto beside = linearWithin(along.dot(a - facing->start_m), along.dot(b - a), -slack,
                                     along.squaredNorm() + slack);
    const auto near =
        linearWithin(facing->inward_normal.dot(a - facing->start_m),
                     facing->inward_normal.dot(b - a), -std::numeric_limits<double>::infinity(), R);
    held.push_back({std::max(beside.first, near.first), std::min(beside.second, near.second)});
  }
  std::sort(held.begin(), held.end());
  std::vector<Vector2d> ends;  // of the parts of [0, 1] neither interval covers
  double from = 0;
  for (const auto& [lo, hi] : held) {
    if (!(lo <= hi)) continue;  // empty
    if (lo > from) {
      ends.push_back(a + from * (b - a));
      ends.push_back(a + std::min(lo, 1.0) * (b - a));
    }
    from = std::max(from, hi);
    if (from >= 1) break;
  }
  if (from < 1) {
    ends.push_back(a + from * (b - a));
    ends.push_back(b);
  }
  if (ends.empty()) return {};
  return {ends};
}

}  // namespace

void checkCapturesCoverOpenings(const Table& table, double R) {
  if (!(R > 0 && std::isfinite(R))) {
    physics::rejectValue("ball radius (m)", R, "it must be finite and > 0");
  }
  if (table.cushions.size() != 3 * table.pockets.size() || table.pockets.size() > 6) {
    throw std::invalid_argument(table.source +
                                ": the table's pockets and cushions are not laid out as "
                                "engine/io/table.h lists them");
  }
  for (std::size_t k = 0; k < table.pockets.size(); ++k) {
    const Pocket& pocket = table.pockets[k];
    const std::vector<std::vector<Vector2d>> covers =
        entranceCovers(table.cushions[3 * k], table.cushions[3 * k + 1], pocket.axis, R);
    if (covers.empty()) continue;  // no ball gets past the facings
    // The cover that needs the smallest circle at this offset: its farthest point's distance.
    const std::vector<Vector2d>* gates = nullptr;
    std::size_t worst = 0;
    double needed_m = std::numeric_limits<double>::infinity();
    for (const std::vector<Vector2d>& cover : covers) {
      std::size_t farthest = 0;
      double distance = 0;
      for (std::size_t e = 0; e < cover.size(); ++e) {
        const double d = (cover[e] - pocket.capture.centre_m).norm();
        if (d > distance) distance = d, farthest = e;
      }
      if (distance < needed_m) needed_m = distance, gates = &cover, worst = farthest;
    }
    if (needed_m < pocket.capture.radius_m) continue;

    // The offsets at which this radius would do: for a cover, |point - mouth - offset * axis| <
    // radius at each of its points, an interval around each point's depth behind the mouth
    // (offsets are >= 0); of the covers' intervals, the widest is suggested.
    const double r = pocket.capture.radius_m;
    double offset_lo = -1, offset_hi = -2;
    for (const std::vector<Vector2d>& cover : covers) {
      double lo = -1, hi = std::numeric_limits<double>::infinity();
      for (const Vector2d& point : cover) {
        const Vector2d from_mouth = point - pocket.mouth_centre_m;
        const double depth = from_mouth.dot(pocket.axis);
        const double half_width_sq = r * r - (from_mouth.squaredNorm() - depth * depth);
        if (!(half_width_sq > 0)) {
          hi = -2;
          break;
        }
        lo = std::max(lo, depth - std::sqrt(half_width_sq));
        hi = std::min(hi, depth + std::sqrt(half_width_sq));
      }
      if (hi - std::max(lo, 0.0) > offset_hi - std::max(offset_lo, 0.0))
        offset_lo = lo, offset_hi = hi;
    }
    const double lowest_offset = offset_lo < 0 ? 0 : roundedLimit(offset_lo, true);
    const double highest_offset = roundedLimit(offset_hi, false);
    const bool offset_would_do = offset_lo < offset_hi && lowest_offset <= highest_offset;
    const double smallest_radius = roundedLimit(needed_m, true);

    const bool corner = pocket.kind == PocketKind::Corner;
    const PocketSpec& spec = corner ? table.corner_pocket : table.side_pocket;
    const std::string key = std::string(corner ? "corner_pocket" : "side_pocket") +
                            (offset_would_do ? ".capture_offset_m" : ".capture_radius_m");
    const double value = offset_would_do ? spec.capture_offset_m : spec.capture_radius_m;
    const std::string other =
        offset_would_do ? "capture_radius_m = " + physics::valueText(r)
                        : "capture_offset_m = " + physics::valueText(spec.capture_offset_m);
    std::string allowed =
        "with " + other + " and balls of radius " + physics::valueText(R) +
        " m, a ball can run between the facings of pocket " + std::to_string(k) + " (" +
        pocketNames().at(k) +
        ") and leave the table without entering the capture circle: the circle must cover the "
        "pocket's entrance (where a ball centre gets past the facings' deep ends), but " +
        pointText((*gates)[worst]) + " m is " + physics::valueText(needed_m) +
        " m from its centre; ";
    if (offset_would_do) {
      allowed += "capture_offset_m must lie in [" + physics::valueText(lowest_offset) + ", " +
                 physics::valueText(highest_offset) +
                 "] m at this radius, or capture_radius_m must be at least " +
                 physics::valueText(smallest_radius) + " m at this offset";
    } else {
      allowed += "capture_radius_m must be at least " + physics::valueText(smallest_radius) +
                 " m at this offset";
    }
    throw std::invalid_argument(table.source + ": " + key + " = " + physics::valueText(value) +
                                " is not allowed: " + allowed);
  }
}

bool inCaptureCircle(const Table& table, const Vector2d& point) {
  for (const Pocket& pocket : table.pockets) {
    if ((point - pocket.capture.centre_m).norm() <= pocket.capture.radius_m) return true;
  }
  return false;
}

bool pastBothDeepEnds(const Table& table, const Vector2d& point) {
  for (std::size_t k = 0; k < table.pockets.size(); ++k) {
    const CushionSegment& entry = table.cushions[3 * k];
    const CushionSegment& exit = table.cushions[3 * k + 1];
    if ((point - entry.end_m).dot(entry.end_m - entry.start_m) > 0 &&
        (point - exit.start_m).dot(exit.start_m - exit.end_m) > 0) {
      return true;
    }
  }
  return false;
}

const std::vector<std::string>& pocketNames() {
  static const std::vector<std::string> names = {"bottom-left", "bottom-middle", "bottom-right",
                                                 "top-right",   "top-middle",    "top-left"};
  return names;
}

namespace {

// The cushion model's defaults. Their bound against the nose height (mu_w < tan theta) needs the
// ball's radius: scenes check it where the table meets the ball set.
void readCushionDefaults(const JsonReader& cushion, Table* table) {
  cushion.requireKeys({"restitution", "friction"}, {kValidNormalSpeedKey});
  table->cushion_restitution = cushion.positiveNumber("restitution");
  if (!(table->cushion_restitution >= physics::kMinRestitution && table->cushion_restitution <= 1))
    cushion.reject("restitution", "it must lie in [" + physics::valueText(physics::kMinRestitution) +
                                      ", 1] (the energetic coefficient e_e)");
  table->cushion_friction = cushion.nonNegativeNumber("friction");
  if (cushion.has(kValidNormalSpeedKey))
    table->cushion_valid_normal_speed_mps = cushion.positiveNumber(kValidNormalSpeedKey);
}

}  // namespace

Table tableFromJson(const nlohmann::json& document, const std::string& source) {
  const JsonReader root(document, source);
  root.requireKeys({"name", "kind", "description", "playing_surface", "cushion_contact_height_m",
                    "corner_pocket", "side_pocket", "markings"},
                   {"cushion"});
  Table table;
  table.source = source;
  table.name = root.text("name");
  table.description = root.text("description");
  const std::string kind = root.text("kind");
  if (kind != "pool" && kind != "snooker")
    root.reject("kind", "it must be \"pool\" or \"snooker\"");
  table.kind = kind == "pool" ? TableKind::Pool : TableKind::Snooker;

  const JsonReader surface = root.object("playing_surface");
  surface.requireExactKeys({"length_m", "width_m"});
  table.length_m = surface.positiveNumber("length_m");
  table.width_m = surface.positiveNumber("width_m");
  if (!(table.width_m < table.length_m)) {
    surface.reject("width_m", "it must be less than length_m (x runs along the long side)");
  }
  table.cushion_contact_height_m = root.positiveNumber("cushion_contact_height_m");
  if (root.has("cushion")) readCushionDefaults(root.object("cushion"), &table);

  const JsonReader corner = root.object("corner_pocket");
  const JsonReader side = root.object("side_pocket");
  table.corner_pocket = readPocketSpec(corner);
  table.side_pocket = readPocketSpec(side);
  checkRailsRemain(table, corner, side);
  buildCushions(table);
  checkFacingsDoNotCross(table, corner, side);

  const JsonReader markings = root.object("markings");
  if (table.kind == TableKind::Pool) {
    table.pool_markings = readPoolMarkings(markings, table);
  } else {
    table.snooker_markings = readSnookerMarkings(markings, table);
  }
  return table;
}

Table loadTable(const std::string& path) {
  return tableFromJson(JsonReader::parseFile(path), path);
}

std::vector<std::string> builtinTableNames() {
  return {"pool-7ft", "pool-8ft", "pool-9ft", "snooker-12ft"};
}

Table builtinTable(const std::string& name) {
  // Read once per process: batch runs load a scene per shot, and the files do not change.
  static std::mutex mutex;
  static std::map<std::string, Table> loaded;
  for (const std::string& known : builtinTableNames()) {
    if (name != known) continue;
    const std::lock_guard<std::mutex> lock(mutex);
    auto found = loaded.find(name);
    if (found == loaded.end())
      found =
          loaded.emplace(name, loadTable(assetsDirectory() + "/tables/" + name + ".json")).first;
    return found->second;
  }
  std::string allowed;
  for (const std::string& known : builtinTableNames())
    allowed += (allowed.empty() ? "" : ", ") + known;
  throw std::invalid_argument("table name \"" + name +
                              "\" is not allowed: the built-in tables are " + allowed);
}

TableGeometry geometryOf(const Table& table) {
  TableGeometry geometry;
  geometry.cushions = table.cushions;
  geometry.jaws = table.jaw_arcs;
  for (const Pocket& pocket : table.pockets) geometry.pockets.push_back(pocket.capture);
  geometry.outline = cushionOutline(table.cushions);
  geometry.rail_box = railBoxInsideOutline(geometry.outline);
  return geometry;
}

namespace {

// Bit for bit, so that nothing (not even the sign of a zero) tells two tables that share a
// geometry apart.
bool sameBits(double a, double b) { return std::memcmp(&a, &b, sizeof a) == 0; }
bool sameBits(const Eigen::Vector2d& a, const Eigen::Vector2d& b) {
  return sameBits(a.x(), b.x()) && sameBits(a.y(), b.y());
}

// Whether a[i] and b[i] are the same for every i (and the sizes agree).
template <typename A, typename B, typename Same>
bool sameEach(const std::vector<A>& a, const std::vector<B>& b, Same same) {
  if (a.size() != b.size()) return false;
  for (std::size_t i = 0; i < a.size(); ++i) {
    if (!same(a[i], b[i])) return false;
  }
  return true;
}

bool sameCushion(const CushionSegment& a, const CushionSegment& b) {
  return sameBits(a.start_m, b.start_m) && sameBits(a.end_m, b.end_m) &&
         sameBits(a.inward_normal, b.inward_normal) && a.pocket == b.pocket;
}

bool sameJaw(const JawArc& a, const JawArc& b) {
  return sameBits(a.centre_m, b.centre_m) && sameBits(a.radius_m, b.radius_m) &&
         sameBits(a.start_angle_rad, b.start_angle_rad) &&
         sameBits(a.end_angle_rad, b.end_angle_rad) && a.pocket == b.pocket;
}

bool sameCapture(const Pocket& pocket, const Circle& capture) {
  return sameBits(pocket.capture.centre_m, capture.centre_m) &&
         sameBits(pocket.capture.radius_m, capture.radius_m);
}

}  // namespace

const TableGeometry& cachedGeometryOf(const Table& table) {
  // The geometry holds the cushions, jaws and captures it was built from (geometryOf copies them
  // unchanged), so they are the key. Building it (the outline and the rail box) took about a tenth
  // of the event loop's own instructions in a random single shot.
  thread_local TableGeometry kept;
  thread_local bool filled = false;
  if (!filled || !sameEach(table.cushions, kept.cushions, sameCushion) ||
      !sameEach(table.jaw_arcs, kept.jaws, sameJaw) ||
      !sameEach(table.pockets, kept.pockets, sameCapture)) {
    filled = false;  // stays so if building throws
    kept = geometryOf(table);
    filled = true;
  }
  return kept;
}

}  // namespace baize::engine
