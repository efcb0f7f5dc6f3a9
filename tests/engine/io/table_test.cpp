#include "engine/io/table.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <functional>
#include <limits>
#include <random>
#include <stdexcept>
#include <string>
#include <tuple>
#include <vector>

#include "engine/io/ball_set.h"
#include "engine/models/model_registry.h"
#include "engine/sim/shot_simulator.h"
#include "tests/engine/error_test_support.h"

namespace baize::engine {
namespace {

using Eigen::Vector2d;

// Table coordinates are sums and products of a few metre-sized numbers: rounding stays far below.
constexpr double kRoundingDistance_m = 1e-12;
// Angles from atan2 and acos of such coordinates (acos loses accuracy near 0 and pi: sqrt(eps)).
constexpr double kRoundingAngle_rad = 1e-7;
// Positions divided by a rail length, compared with whole multiples: rounding only, relative.
constexpr double kRoundingRelative = 1e-12;
// The pockets' channels add a little area beyond the rectangle; 5 % is far more than they add.
constexpr double kPocketAreaAllowance = 0.05;

constexpr double kPi = 3.14159265358979323846;

double cross(const Vector2d& a, const Vector2d& b) { return a.x() * b.y() - a.y() * b.x(); }

// Intersection of the lines through (a0, a1) and (b0, b1).
Vector2d lineIntersection(const Vector2d& a0, const Vector2d& a1, const Vector2d& b0,
                          const Vector2d& b1) {
  const Vector2d da = a1 - a0, db = b1 - b0;
  return a0 + cross(b0 - a0, db) / cross(da, db) * da;
}

double distanceToLine(const Vector2d& point, const CushionSegment& segment) {
  const Vector2d direction = (segment.end_m - segment.start_m).normalized();
  return std::abs(cross(direction, point - segment.start_m));
}

double angleBetween(const Vector2d& a, const Vector2d& b) {
  return std::acos(std::clamp(a.normalized().dot(b.normalized()), -1.0, 1.0));
}

const PocketSpec& specOf(const Table& table, const Pocket& pocket) {
  return pocket.kind == PocketKind::Corner ? table.corner_pocket : table.side_pocket;
}

// The pieces of the outline around pocket k, in counterclockwise order.
struct PocketOutline {
  const CushionSegment& rail_in;
  const JawArc& entry_arc;
  const CushionSegment& entry_facing;
  const CushionSegment& exit_facing;
  const JawArc& exit_arc;
  const CushionSegment& rail_out;
};

PocketOutline outlineAround(const Table& table, std::size_t k) {
  const std::size_t previous = (k + table.pockets.size() - 1) % table.pockets.size();
  return {table.cushions[3 * previous + 2], table.jaw_arcs[2 * k],     table.cushions[3 * k],
          table.cushions[3 * k + 1],        table.jaw_arcs[2 * k + 1], table.cushions[3 * k + 2]};
}

bool near(const Vector2d& a, const Vector2d& b) { return (a - b).norm() <= kRoundingDistance_m; }

// The two ends of the arc are the two given points, in either order.
bool arcJoins(const JawArc& arc, const Vector2d& p, const Vector2d& q) {
  const Vector2d a = arc.pointAt(arc.start_angle_rad), b = arc.pointAt(arc.end_angle_rad);
  return (near(a, p) && near(b, q)) || (near(a, q) && near(b, p));
}

// Points sampled along each line of the independent capture check below.
constexpr int kClosingLineSamples = 100000;

// Whether p lies beyond the line through a facing's deep end along its inward normal, on the far
// side from the facing: there the facing no longer holds a ball.
bool pastDeepEnd(const Vector2d& deep_end, const Vector2d& jaw_end, const Vector2d& p) {
  return (p - deep_end).dot(deep_end - jaw_end) > 0;
}

// Whether a facing holds a ball centre at p: beside it (between its ends) and less than R in front.
bool holds(const CushionSegment& facing, const Vector2d& p, double R) {
  const Vector2d along = facing.end_m - facing.start_m;
  const double beside = along.dot(p - facing.start_m);
  return beside >= 0 && beside <= along.squaredNorm() &&
         facing.inward_normal.dot(p - facing.start_m) < R;
}

// The radius pocket k's capture circle needs (at its offset) to keep every ball in, by sampling;
// -1 when no ball gets past the facings. Converging facings (the closing line lies past both deep
// ends): the gates are the points on the line through one facing's deep end along its inward
// normal, R or more in front of it, past the other facing's deep end and in front of the closing
// line; the circle must hold either all of them or the part of the triangle they bound next to the
// closing line (its samples: the closing line and the segment between the gates' inner ends),
// whichever needs less. Otherwise: the points of the closing line (from deep end to deep end) that
// neither facing holds. The exact value exceeds this by at most the sample spacing (distance is
// 1-Lipschitz).
double sampledReach(const Table& table, std::size_t k, double R) {
  const CushionSegment& entry = table.cushions[3 * k];
  const CushionSegment& exit = table.cushions[3 * k + 1];
  const Vector2d a = entry.end_m, b = exit.start_m, centre = table.pockets[k].capture.centre_m;
  const Vector2d outward = table.pockets[k].axis;
  const Vector2d a_gate = a + R * entry.inward_normal, b_gate = b + R * exit.inward_normal;
  // Farther than any gate reaches on the tables tested here (their facings' deep-end lines meet
  // within 0.15 m; a side facing nearly along its rail would need more).
  const double span_m = 4 * (b - a).norm() + 4 * R;
  double gates = -1, next_to_closing = -1, closing = -1;
  for (int i = 0; i <= kClosingLineSamples; ++i) {
    const double f = static_cast<double>(i) / kClosingLineSamples;
    const Vector2d on_line = a + f * (b - a);
    if (!holds(entry, on_line, R) && !holds(exit, on_line, R)) {
      closing = std::max(closing, (on_line - centre).norm());
    }
    next_to_closing = std::max({next_to_closing, (on_line - centre).norm(),
                                (a_gate + f * (b_gate - a_gate) - centre).norm()});
    const double s = R + f * span_m;
    for (const auto& [from, normal, other_deep, other_jaw] :
         {std::make_tuple(a, entry.inward_normal, b, exit.end_m),
          std::make_tuple(b, exit.inward_normal, a, entry.start_m)}) {
      const Vector2d q = from + s * normal;
      if (pastDeepEnd(other_deep, other_jaw, q) && (q - a).dot(outward) < 0) {
        gates = std::max(gates, (q - centre).norm());
      }
    }
  }
  // Converging facings: the closing line lies past both deep ends (then without gates no ball
  // gets in).
  const Vector2d middle = (a + b) / 2;
  if (pastDeepEnd(a, entry.start_m, middle) && pastDeepEnd(b, exit.end_m, middle)) {
    return gates >= 0 ? std::min(gates, next_to_closing) : -1;
  }
  return closing;
}

// The largest spacing of sampledReach's samples for pocket k, m: those along the gates.
double sampleSpacing(const Table& table, std::size_t k, double R) {
  const double closing = (table.cushions[3 * k + 1].start_m - table.cushions[3 * k].end_m).norm();
  return (4 * closing + 4 * R) / kClosingLineSamples;
}

// The number that follows `label` in `message` (a limit the message suggests); NaN if none.
double numberAfter(const std::string& message, const std::string& label) {
  const std::size_t at = message.find(label);
  if (at == std::string::npos) return std::numeric_limits<double>::quiet_NaN();
  return std::stod(message.substr(at + label.size()));
}

class BuiltinTableTest : public ::testing::TestWithParam<std::string> {
 protected:
  Table table = builtinTable(GetParam());
};

TEST_P(BuiltinTableTest, HasSixPocketsEighteenCushionsTwelveJawArcs) {
  EXPECT_EQ(table.name, GetParam());
  EXPECT_EQ(table.pockets.size(), 6u);
  EXPECT_EQ(table.cushions.size(), 18u);
  EXPECT_EQ(table.jaw_arcs.size(), 12u);
  EXPECT_EQ(table.pool_markings.has_value(), table.kind == TableKind::Pool);
  EXPECT_EQ(table.snooker_markings.has_value(), table.kind == TableKind::Snooker);
}

TEST_P(BuiltinTableTest, OutlineIsContinuousThroughJawArcs) {
  for (std::size_t k = 0; k < table.pockets.size(); ++k) {
    SCOPED_TRACE("pocket " + std::to_string(k));
    const PocketOutline outline = outlineAround(table, k);
    EXPECT_TRUE(arcJoins(outline.entry_arc, outline.rail_in.end_m, outline.entry_facing.start_m));
    EXPECT_TRUE(arcJoins(outline.exit_arc, outline.exit_facing.end_m, outline.rail_out.start_m));
    EXPECT_EQ(outline.entry_facing.pocket, static_cast<int>(k));
    EXPECT_EQ(outline.exit_facing.pocket, static_cast<int>(k));
    EXPECT_EQ(outline.rail_out.pocket, -1);
  }
}

TEST_P(BuiltinTableTest, JawArcsAreTangentToRailAndFacingAndTurnByPiMinusFacingAngle) {
  for (std::size_t k = 0; k < table.pockets.size(); ++k) {
    SCOPED_TRACE("pocket " + std::to_string(k));
    const PocketOutline outline = outlineAround(table, k);
    const PocketSpec& spec = specOf(table, table.pockets[k]);
    for (const auto& [arc, rail, facing] :
         {std::make_tuple(&outline.entry_arc, &outline.rail_in, &outline.entry_facing),
          std::make_tuple(&outline.exit_arc, &outline.rail_out, &outline.exit_facing)}) {
      EXPECT_DOUBLE_EQ(arc->radius_m, spec.jaw_radius_m);
      EXPECT_NEAR(distanceToLine(arc->centre_m, *rail), arc->radius_m, kRoundingDistance_m);
      EXPECT_NEAR(distanceToLine(arc->centre_m, *facing), arc->radius_m, kRoundingDistance_m);
      // The centre lies inside the cushion, behind both noses.
      EXPECT_LT(rail->inward_normal.dot(arc->centre_m - rail->start_m), 0);
      EXPECT_LT(facing->inward_normal.dot(arc->centre_m - facing->start_m), 0);
      EXPECT_NEAR(arc->end_angle_rad - arc->start_angle_rad, kPi - spec.facing_angle_rad,
                  kRoundingAngle_rad);
    }
  }
}

TEST_P(BuiltinTableTest, NormalsAreUnitLeftOfTravelAndPointIntoTheTable) {
  for (const CushionSegment& cushion : table.cushions) {
    const Vector2d direction = (cushion.end_m - cushion.start_m).normalized();
    EXPECT_NEAR(cushion.inward_normal.norm(), 1, kRoundingDistance_m);
    EXPECT_NEAR(cushion.inward_normal.dot(direction), 0, kRoundingDistance_m);
    EXPECT_GT(cross(direction, cushion.inward_normal), 0);  // left of the counterclockwise travel
    if (cushion.pocket < 0) {
      // Rails lie on the rectangle's edges and face the centre of the table.
      EXPECT_GT(cushion.inward_normal.dot(-cushion.start_m), 0);
      const bool on_long_edge =
          std::abs(std::abs(cushion.start_m.y()) - table.width_m / 2) <= kRoundingDistance_m &&
          std::abs(std::abs(cushion.end_m.y()) - table.width_m / 2) <= kRoundingDistance_m;
      const bool on_short_edge =
          std::abs(std::abs(cushion.start_m.x()) - table.length_m / 2) <= kRoundingDistance_m &&
          std::abs(std::abs(cushion.end_m.x()) - table.length_m / 2) <= kRoundingDistance_m;
      EXPECT_TRUE(on_long_edge || on_short_edge);
    } else {
      // Facings face the pocket's channel.
      const Pocket& pocket = table.pockets[cushion.pocket];
      EXPECT_GT(cushion.inward_normal.dot(pocket.mouth_centre_m - cushion.start_m), 0);
    }
  }
}

TEST_P(BuiltinTableTest, OutlineIsCounterclockwiseAndEnclosesAboutThePlayingArea) {
  std::vector<Vector2d> corners;
  for (const CushionSegment& cushion : table.cushions) {
    corners.push_back(cushion.start_m);
    corners.push_back(cushion.end_m);
  }
  double twice_area = 0;
  for (std::size_t i = 0; i < corners.size(); ++i) {
    twice_area += cross(corners[i], corners[(i + 1) % corners.size()]);
  }
  // The pockets add a little area beyond the rectangle; none is lost.
  EXPECT_GT(twice_area / 2, table.length_m * table.width_m);
  EXPECT_LT(twice_area / 2, (1 + kPocketAreaAllowance) * table.length_m * table.width_m);
}

TEST_P(BuiltinTableTest, MouthBetweenJawTipsIsTheStatedWidthAndFacingsMeetRailsAtTheFacingAngle) {
  for (std::size_t k = 0; k < table.pockets.size(); ++k) {
    SCOPED_TRACE("pocket " + std::to_string(k));
    const PocketOutline outline = outlineAround(table, k);
    const PocketSpec& spec = specOf(table, table.pockets[k]);
    const Vector2d entry_tip =
        lineIntersection(outline.rail_in.start_m, outline.rail_in.end_m,
                         outline.entry_facing.start_m, outline.entry_facing.end_m);
    const Vector2d exit_tip =
        lineIntersection(outline.rail_out.start_m, outline.rail_out.end_m,
                         outline.exit_facing.start_m, outline.exit_facing.end_m);
    EXPECT_NEAR((entry_tip - exit_tip).norm(), spec.mouth_width_m, kRoundingDistance_m);
    EXPECT_TRUE(near(entry_tip, table.pockets[k].jaw_tips_m[0]));
    EXPECT_TRUE(near(exit_tip, table.pockets[k].jaw_tips_m[1]));
    // Inside the cushion, between the rail nose running back and the facing running out.
    const Vector2d rail_back_in = outline.rail_in.start_m - outline.rail_in.end_m;
    const Vector2d facing_out_in = outline.entry_facing.end_m - outline.entry_facing.start_m;
    EXPECT_NEAR(angleBetween(rail_back_in, facing_out_in), spec.facing_angle_rad,
                kRoundingAngle_rad);
    const Vector2d rail_back_out = outline.rail_out.end_m - outline.rail_out.start_m;
    const Vector2d facing_out_out = outline.exit_facing.start_m - outline.exit_facing.end_m;
    EXPECT_NEAR(angleBetween(rail_back_out, facing_out_out), spec.facing_angle_rad,
                kRoundingAngle_rad);
    EXPECT_NEAR(facing_out_in.norm() + (outline.entry_facing.start_m - entry_tip).norm(),
                spec.facing_length_m, kRoundingDistance_m);
  }
}

TEST_P(BuiltinTableTest, CaptureCircleLiesBehindTheMouthOnThePocketAxis) {
  for (const Pocket& pocket : table.pockets) {
    const PocketSpec& spec = specOf(table, pocket);
    const Vector2d behind = pocket.capture.centre_m - pocket.mouth_centre_m;
    EXPECT_NEAR(behind.dot(pocket.axis), spec.capture_offset_m, kRoundingDistance_m);
    EXPECT_NEAR(cross(pocket.axis, behind), 0, kRoundingDistance_m);
    EXPECT_DOUBLE_EQ(pocket.capture.radius_m, spec.capture_radius_m);
    // The axis points out of the table: the mouth centre moves away from the table centre along it.
    EXPECT_GT(pocket.axis.dot(pocket.mouth_centre_m), 0);
  }
}

// Each piece has its mirror image among the pieces.
void expectMirrorSymmetric(const Table& table,
                           const std::function<Vector2d(const Vector2d&)>& mirror) {
  for (const CushionSegment& a : table.cushions) {
    int matches = 0;
    for (const CushionSegment& b : table.cushions) {
      const bool same = (near(mirror(a.start_m), b.start_m) && near(mirror(a.end_m), b.end_m)) ||
                        (near(mirror(a.start_m), b.end_m) && near(mirror(a.end_m), b.start_m));
      if (same && near(mirror(a.inward_normal), b.inward_normal)) ++matches;
    }
    EXPECT_EQ(matches, 1);
  }
  for (const JawArc& a : table.jaw_arcs) {
    int matches = 0;
    for (const JawArc& b : table.jaw_arcs) {
      if (near(mirror(a.centre_m), b.centre_m) && a.radius_m == b.radius_m &&
          arcJoins(b, mirror(a.pointAt(a.start_angle_rad)), mirror(a.pointAt(a.end_angle_rad)))) {
        ++matches;
      }
    }
    EXPECT_EQ(matches, 1);
  }
  for (const Pocket& a : table.pockets) {
    int matches = 0;
    for (const Pocket& b : table.pockets) {
      if (near(mirror(a.capture.centre_m), b.capture.centre_m) && near(mirror(a.axis), b.axis)) {
        ++matches;
      }
    }
    EXPECT_EQ(matches, 1);
  }
}

// Every shipped table holds both shipped ball sets: a ball passing the facings is caught. Checked
// by the engine and, independently, by sampling the closing lines.
TEST_P(BuiltinTableTest, CaptureCirclesCoverThePocketOpeningsForBothShippedBallSets) {
  for (const char* set : {"pool", "snooker"}) {
    const double R = builtinBallSet(set).radius_m;
    EXPECT_NO_THROW(checkCapturesCoverOpenings(table, R)) << set;
    for (std::size_t k = 0; k < table.pockets.size(); ++k) {
      const double reach = sampledReach(table, k, R);
      EXPECT_GT(reach, 0) << set << ", pocket " << k << ": a ball passes the facings";
      EXPECT_LT(reach + sampleSpacing(table, k, R), table.pockets[k].capture.radius_m)
          << set << ", pocket " << k;
    }
  }
}

// The box of the rails lies inside the outline and spans the playing surface between the noses:
// every point sampled in it is inside by the polygon test too.
TEST_P(BuiltinTableTest, RailBoxIsTheNoseRectangleAndLiesInsideTheOutline) {
  const std::vector<Vector2d> outline = cushionOutline(table.cushions);
  const Eigen::AlignedBox2d box = railBoxInsideOutline(outline);
  ASSERT_FALSE(box.isEmpty());
  EXPECT_NEAR(box.max().x(), table.length_m / 2, 1e-8);
  EXPECT_NEAR(box.min().y(), -table.width_m / 2, 1e-8);
  std::mt19937_64 random(5);
  std::uniform_real_distribution<double> unit(0, 1);
  for (int i = 0; i < 20000; ++i) {
    const Vector2d p = box.min() + Vector2d(unit(random), unit(random)).cwiseProduct(box.sizes());
    ASSERT_TRUE(insideOutline(outline, p)) << p.transpose();
  }
}

// The cushion outline holds the table's centre and every place a ball rests on the playing
// surface, and not a point just beyond a pocket's closing line or behind a rail.
TEST_P(BuiltinTableTest, CushionOutlineHoldsThePlayingSurfaceAndEndsAtTheClosingLines) {
  const std::vector<Vector2d> outline = cushionOutline(table.cushions);
  ASSERT_EQ(outline.size(), 2 * table.cushions.size());
  const double R = builtinBallSet(table.kind == TableKind::Pool ? "pool" : "snooker").radius_m;
  const double x = table.length_m / 2 - R, y = table.width_m / 2 - R;
  for (const Vector2d& p : {Vector2d(0, 0), Vector2d(x, y), Vector2d(-x, y), Vector2d(x, -y),
                            Vector2d(-x, -y), Vector2d(0, y), Vector2d(0, -y)}) {
    EXPECT_TRUE(insideOutline(outline, p)) << p.transpose();
  }
  // Behind a long rail (between the corner and side pockets) and behind a short one.
  EXPECT_FALSE(insideOutline(outline, Vector2d(table.length_m / 4, table.width_m / 2 + 1e-3)));
  EXPECT_FALSE(insideOutline(outline, Vector2d(table.length_m / 2 + 1e-3, 0)));
  for (std::size_t k = 0; k < table.pockets.size(); ++k) {
    const Pocket& pocket = table.pockets[k];
    const Vector2d closing_middle =
        (table.cushions[3 * k].end_m + table.cushions[3 * k + 1].start_m) / 2;
    EXPECT_TRUE(insideOutline(outline, closing_middle - 1e-3 * pocket.axis)) << "pocket " << k;
    EXPECT_FALSE(insideOutline(outline, closing_middle + 1e-3 * pocket.axis)) << "pocket " << k;
  }
}

TEST_P(BuiltinTableTest, GeometryIsMirrorSymmetricAboutBothAxes) {
  {
    SCOPED_TRACE("x -> -x");
    expectMirrorSymmetric(table, [](const Vector2d& p) { return Vector2d(-p.x(), p.y()); });
  }
  {
    SCOPED_TRACE("y -> -y");
    expectMirrorSymmetric(table, [](const Vector2d& p) { return Vector2d(p.x(), -p.y()); });
  }
}

INSTANTIATE_TEST_SUITE_P(Shipped, BuiltinTableTest, ::testing::ValuesIn(builtinTableNames()),
                         [](const auto& info) {
                           std::string name = info.param;
                           for (char& c : name) {
                             if (c == '-') c = '_';
                           }
                           return name;
                         });

TEST(BuiltinTables, PlayingSurfacesAreTheStatedSizes) {
  EXPECT_DOUBLE_EQ(builtinTable("pool-7ft").length_m, 1.981);
  EXPECT_DOUBLE_EQ(builtinTable("pool-7ft").width_m, 0.991);
  EXPECT_DOUBLE_EQ(builtinTable("pool-8ft").length_m, 2.3368);
  EXPECT_DOUBLE_EQ(builtinTable("pool-8ft").width_m, 1.1684);
  EXPECT_DOUBLE_EQ(builtinTable("pool-9ft").length_m, 2.540);
  EXPECT_DOUBLE_EQ(builtinTable("pool-9ft").width_m, 1.270);
  EXPECT_DOUBLE_EQ(builtinTable("snooker-12ft").length_m, 3.569);
  EXPECT_DOUBLE_EQ(builtinTable("snooker-12ft").width_m, 1.778);
}

TEST(BuiltinTables, PoolPocketsAndCushionsAreWithinWpaRanges) {
  constexpr double kBallDiameter_m = 0.05715;
  for (const std::string name : {"pool-7ft", "pool-8ft", "pool-9ft"}) {
    const Table table = builtinTable(name);
    EXPECT_GE(table.corner_pocket.mouth_width_m, 0.1143);
    EXPECT_LE(table.corner_pocket.mouth_width_m, 0.1175);
    EXPECT_GE(table.side_pocket.mouth_width_m, 0.127);
    EXPECT_LE(table.side_pocket.mouth_width_m, 0.1302);
    EXPECT_NEAR(table.corner_pocket.facing_angle_rad, 142 * kPi / 180, kRoundingAngle_rad);
    EXPECT_NEAR(table.side_pocket.facing_angle_rad, 104 * kPi / 180, kRoundingAngle_rad);
    EXPECT_GE(table.cushion_contact_height_m, 0.625 * kBallDiameter_m);
    EXPECT_LE(table.cushion_contact_height_m, 0.645 * kBallDiameter_m);
  }
}

TEST(BuiltinTables, PoolDiamondsSitAtQuartersOfEachRailSegmentBehindTheNose) {
  const Table table = builtinTable("pool-9ft");
  const PoolMarkings& markings = *table.pool_markings;
  ASSERT_EQ(markings.diamonds_m.size(), 18u);  // 3 on each of 6 rail segments
  const double half_length = table.length_m / 2, half_width = table.width_m / 2;
  int on_long = 0, on_short = 0;
  for (const Vector2d& diamond : markings.diamonds_m) {
    if (std::abs(std::abs(diamond.y()) - (half_width + markings.diamond_setback_m)) <=
        kRoundingDistance_m) {
      ++on_long;
      // Multiples of length / 8, never at a pocket (0, +-4 eighths).
      const double eighths = diamond.x() / (table.length_m / 8);
      EXPECT_NEAR(eighths, std::round(eighths), kRoundingRelative);
      EXPECT_NE(std::lround(eighths) % 4, 0);
    } else {
      ++on_short;
      EXPECT_NEAR(std::abs(diamond.x()), half_length + markings.diamond_setback_m,
                  kRoundingDistance_m);
      const double quarters = diamond.y() / (table.width_m / 4);
      EXPECT_NEAR(quarters, std::round(quarters), kRoundingRelative);
      EXPECT_LE(std::abs(std::lround(quarters)), 1);
    }
  }
  EXPECT_EQ(on_long, 12);
  EXPECT_EQ(on_short, 6);
  EXPECT_TRUE(near(markings.foot_spot_m, Vector2d(table.length_m / 4, 0)));
  EXPECT_DOUBLE_EQ(markings.head_string_x_m, -table.length_m / 4);
}

TEST(BuiltinTables, SnookerSpotsFollowTheRules) {
  const Table table = builtinTable("snooker-12ft");
  const SnookerMarkings& m = *table.snooker_markings;
  const double bottom = -table.length_m / 2, top = table.length_m / 2;
  EXPECT_NEAR(m.baulk_line_x_m - bottom, 0.737, kRoundingDistance_m);
  EXPECT_DOUBLE_EQ(m.d_radius_m, 0.292);
  EXPECT_TRUE(near(m.brown_spot_m, Vector2d(bottom + 0.737, 0)));
  EXPECT_TRUE(near(m.yellow_spot_m, Vector2d(bottom + 0.737, -0.292)));  // right seen from baulk
  EXPECT_TRUE(near(m.green_spot_m, Vector2d(bottom + 0.737, 0.292)));
  EXPECT_TRUE(near(m.blue_spot_m, Vector2d(0, 0)));
  EXPECT_TRUE(near(m.pink_spot_m, Vector2d((0 + top) / 2, 0)));
  EXPECT_TRUE(near(m.black_spot_m, Vector2d(top - 0.324, 0)));
  EXPECT_DOUBLE_EQ(table.cushion_contact_height_m, 0.036);
}

TEST(BuiltinTables, UnknownNameIsRejectedWithTheKnownNames) {
  const std::string message = invalidArgumentMessage([] { builtinTable("pool-6ft"); });
  EXPECT_MENTIONS(message, "pool-6ft");
  EXPECT_MENTIONS(message, "snooker-12ft");
}

// Bad files: a shipped table changed in one place, written to a temporary file.
class BadTableFileTest : public ::testing::Test {
 protected:
  nlohmann::json document =
      nlohmann::json::parse(std::ifstream(assetsDirectory() + "/tables/pool-9ft.json"));
  // One file per test: ctest runs tests in parallel processes.
  std::string path = ::testing::TempDir() + "bad_table_" +
                     ::testing::UnitTest::GetInstance()->current_test_info()->name() + ".json";

  std::string loadError(const std::string& text) {
    std::ofstream(path) << text;
    return invalidArgumentMessage([&] { loadTable(path); });
  }
  std::string loadError() { return loadError(document.dump(2)); }
};

TEST_F(BadTableFileTest, TheUnchangedFileLoads) {
  std::ofstream(path) << document.dump(2);
  EXPECT_NO_THROW(loadTable(path));
}

TEST_F(BadTableFileTest, UnknownKeyIsNamed) {
  document["corner_pocket"]["depth_m"] = 0.1;
  const std::string message = loadError();
  EXPECT_MENTIONS(message, path);
  EXPECT_MENTIONS(message, "corner_pocket.depth_m = 0.1");
  EXPECT_MENTIONS(message, "unknown key");
  EXPECT_MENTIONS(message, "mouth_width_m");  // the allowed keys are listed
}

TEST_F(BadTableFileTest, MissingKeyIsNamed) {
  document["side_pocket"].erase("jaw_radius_m");
  const std::string message = loadError();
  EXPECT_MENTIONS(message, path);
  EXPECT_MENTIONS(message, "side_pocket.jaw_radius_m is missing");
}

TEST_F(BadTableFileTest, NegativeSizeIsNamedWithItsValue) {
  document["playing_surface"]["length_m"] = -2.54;
  const std::string message = loadError();
  EXPECT_MENTIONS(message, path);
  EXPECT_MENTIONS(message, "playing_surface.length_m = -2.54");
  EXPECT_MENTIONS(message, "> 0");
}

TEST_F(BadTableFileTest, CushionDefaultsAreReadAndChecked) {
  document["cushion"] = {{"restitution", 0.8}, {"friction", 0.2}};
  std::ofstream(path) << document.dump(2);
  const Table table = loadTable(path);
  EXPECT_EQ(table.cushion_restitution, 0.8);
  EXPECT_EQ(table.cushion_friction, 0.2);
  document["cushion"]["restitution"] = 1.5;
  EXPECT_MENTIONS(loadError(), "cushion.restitution = 1.5");
  document["cushion"] = {{"restitution", 0.8}, {"friction", -0.1}};
  EXPECT_MENTIONS(loadError(), "cushion.friction = -0.1");
  document["cushion"] = {{"restitution", 0.8}};
  EXPECT_MENTIONS(loadError(), "cushion.friction is missing");
  // The model's range: the rigid model's stated 2.5 m/s unless the file gives its own.
  EXPECT_EQ(table.cushion_valid_normal_speed_mps, kRigidCushionValidNormalSpeedMps);
  document["cushion"] = {{"restitution", 0.8}, {"friction", 0.2}, {"valid_normal_speed_mps", 1.8}};
  std::ofstream(path) << document.dump(2);
  EXPECT_EQ(loadTable(path).cushion_valid_normal_speed_mps, 1.8);
  document["cushion"]["valid_normal_speed_mps"] = 0;
  EXPECT_MENTIONS(loadError(), "cushion.valid_normal_speed_mps = 0");
}

TEST_F(BadTableFileTest, ZeroJawRadiusIsRejected) {
  document["corner_pocket"]["jaw_radius_m"] = 0;
  EXPECT_MENTIONS(loadError(), "corner_pocket.jaw_radius_m = 0");
}

TEST_F(BadTableFileTest, WrongTypeIsNamed) {
  document["playing_surface"]["width_m"] = "1.27";
  const std::string message = loadError();
  EXPECT_MENTIONS(message, "playing_surface.width_m = \"1.27\"");
  EXPECT_MENTIONS(message, "must be a number");
}

TEST_F(BadTableFileTest, NanInTheFileIsReportedWhereItStands) {
  std::string text = document.dump(2);
  const std::string key = "\"mouth_width_m\": 0.116";
  text.replace(text.find(key), key.size(), "\"mouth_width_m\": NaN");
  const std::string message = loadError(text);
  EXPECT_MENTIONS(message, path);
  EXPECT_MENTIONS(message, "\"mouth_width_m\": N");  // the parser's last read text
  EXPECT_MENTIONS(message, "line");
}

TEST_F(BadTableFileTest, NumberTooLargeForADoubleIsRejected) {
  std::string text = document.dump(2);
  const std::string key = "\"mouth_width_m\": 0.116";
  text.replace(text.find(key), key.size(), "\"mouth_width_m\": 1e999");
  const std::string message = loadError(text);
  EXPECT_MENTIONS(message, path);
  EXPECT_MENTIONS(message, "1e999");
}

TEST_F(BadTableFileTest, NonFiniteValueInADocumentIsNamed) {
  document["corner_pocket"]["mouth_width_m"] = std::numeric_limits<double>::quiet_NaN();
  const std::string message =
      invalidArgumentMessage([&] { tableFromJson(document, "scene.json"); });
  EXPECT_MENTIONS(message, "scene.json: corner_pocket.mouth_width_m = nan");
  EXPECT_MENTIONS(message, "finite");
}

TEST_F(BadTableFileTest, MissingFileIsNamed) {
  const std::string message = invalidArgumentMessage([&] { loadTable(path + ".absent"); });
  EXPECT_MENTIONS(message, path + ".absent");
  EXPECT_MENTIONS(message, "cannot be opened");
}

TEST_F(BadTableFileTest, CornerMouthsWiderThanTheShortRailAreRejected) {
  document["corner_pocket"]["mouth_width_m"] = 0.9;
  const std::string message = loadError();
  EXPECT_MENTIONS(message, "corner_pocket.mouth_width_m = 0.9");
  EXPECT_MENTIONS(message, "short rail");
}

TEST_F(BadTableFileTest, SideMouthsWiderThanTheLongRailAreRejected) {
  document["side_pocket"]["mouth_width_m"] = 2.5;
  const std::string message = loadError();
  EXPECT_MENTIONS(message, "side_pocket.mouth_width_m = 2.5");
  EXPECT_MENTIONS(message, "long rail");
}

TEST_F(BadTableFileTest, FacingAngleOutsideItsRangeIsRejected) {
  document["side_pocket"]["facing_angle_deg"] = 80;
  const std::string message = loadError();
  EXPECT_MENTIONS(message, "side_pocket.facing_angle_deg = 80");
  EXPECT_MENTIONS(message, "(90, 170]");
  document["side_pocket"]["facing_angle_deg"] = 170.5;  // folding back along the rail
  EXPECT_MENTIONS(loadError(), "side_pocket.facing_angle_deg = 170.5");
  document["side_pocket"]["facing_angle_deg"] = 170;
  std::ofstream(path) << document.dump(2);
  EXPECT_NO_THROW(loadTable(path));
}

TEST_F(BadTableFileTest, FacingsLongEnoughToCrossAreRejected) {
  document["side_pocket"]["facing_length_m"] = 0.5;
  EXPECT_MENTIONS(loadError(), "side_pocket.facing_length_m = 0.5");
}

TEST_F(BadTableFileTest, UnknownKindIsRejected) {
  document["kind"] = "carom";
  EXPECT_MENTIONS(loadError(), "kind = \"carom\"");
}

TEST_F(BadTableFileTest, MarkingsMustMatchTheKind) {
  document["kind"] = "snooker";
  const std::string message = loadError();
  EXPECT_MENTIONS(message, "markings.diamond");  // one of the pool keys, whichever comes first
  EXPECT_MENTIONS(message, "unknown key");
}

// A table that loads but whose capture circles miss part of the openings a pool ball reaches.
class CaptureCircleTest : public BadTableFileTest {
 protected:
  const double R = builtinBallSet("pool").radius_m;

  Table written() {
    std::ofstream(path) << document.dump(2);
    return loadTable(path);
  }
  // The refusal for pool balls, or "" when the table is accepted.
  std::string refusal() {
    const Table table = written();
    try {
      checkCapturesCoverOpenings(table, R);
    } catch (const std::invalid_argument& error) {
      return error.what();
    }
    return "";
  }
  // The largest sampled reach over the corner pockets (their geometry is mirror images).
  double cornerReach(double* spacing) {
    const Table table = written();
    double reach = -1;
    for (std::size_t k : {0, 2, 3, 5}) {
      reach = std::max(reach, sampledReach(table, k, R));
      *spacing = sampleSpacing(table, k, R);
    }
    return reach;
  }
};

TEST_F(CaptureCircleTest, ACaptureCircleFarBehindTheMouthIsRefusedNamingKeyValueAndLimits) {
  document["corner_pocket"]["capture_offset_m"] = 0.5;
  const std::string message = refusal();
  EXPECT_MENTIONS(message, path + ": corner_pocket.capture_offset_m = 0.5 is not allowed");
  EXPECT_MENTIONS(message, "pocket 0 (bottom-left)");
  EXPECT_MENTIONS(message, "capture_radius_m = 0.04 and balls of radius 0.028575 m");
  EXPECT_MENTIONS(message, "leave the table");
  // The limits it suggests work as written: either end of the offsets, or the radius.
  const double lowest = numberAfter(message, "capture_offset_m must lie in [");
  const double radius = numberAfter(message, "capture_radius_m must be at least ");
  ASSERT_TRUE(std::isfinite(lowest) && std::isfinite(radius)) << message;
  const std::size_t comma = message.find(", ", message.find("must lie in ["));
  const double upper = std::stod(message.substr(comma + 2));
  EXPECT_LT(lowest, 0.045);  // the shipped offset is among them
  EXPECT_GT(upper, 0.045);
  for (const double offset : {lowest, upper}) {
    document["corner_pocket"]["capture_offset_m"] = offset;
    EXPECT_EQ(refusal(), "") << "offset " << offset;
  }
  document["corner_pocket"]["capture_offset_m"] = 0.5;
  document["corner_pocket"]["capture_radius_m"] = radius;
  EXPECT_EQ(refusal(), "") << "radius " << radius;
  // The suggested radius is the reach at this offset, rounded up to a few micrometres.
  double spacing = 0;
  const double reach = cornerReach(&spacing);
  EXPECT_GE(radius, reach);
  EXPECT_LE(radius, reach + spacing + 1e-5 * reach);
}

TEST_F(CaptureCircleTest, ATooSmallCaptureRadiusIsRefusedNamingKeyValueAndTheRadiusNeeded) {
  document["corner_pocket"]["capture_radius_m"] = 0.02;
  const std::string message = refusal();
  EXPECT_MENTIONS(message, path + ": corner_pocket.capture_radius_m = 0.02 is not allowed");
  EXPECT_MENTIONS(message, "capture_offset_m = 0.045");
  // No offset lets a 0.02 m circle cover an opening 0.044 m across: only the radius is suggested.
  EXPECT_EQ(message.find("must lie in"), std::string::npos) << message;
  const double radius = numberAfter(message, "capture_radius_m must be at least ");
  double spacing = 0;
  const double reach = cornerReach(&spacing);
  EXPECT_GE(radius, reach);
  EXPECT_LE(radius, reach + spacing + 1e-5 * reach);
}

TEST_F(CaptureCircleTest, ASidePocketIsNamedByItsOwnKey) {
  document["side_pocket"]["capture_offset_m"] = 0;
  const std::string message = refusal();
  EXPECT_MENTIONS(message, "side_pocket.capture_offset_m = 0 is not allowed");
  EXPECT_MENTIONS(message, "pocket 1 (bottom-middle)");
}

// The boundary, found independently by sampling: a circle just reaching past the farthest point a
// ball centre reaches is accepted, one just short of it refused.
TEST_F(CaptureCircleTest, ACircleJustCoveringTheReachablePartIsAcceptedAndJustShortRefused) {
  double spacing = 0;
  const double reach = cornerReach(&spacing);
  ASSERT_GT(reach, 0);
  document["corner_pocket"]["capture_radius_m"] = reach + 2 * spacing;
  EXPECT_EQ(refusal(), "");
  // Just short, a slightly deeper circle would still do: the refusal may name either key.
  document["corner_pocket"]["capture_radius_m"] = reach * (1 - 1e-9);
  const std::string message = refusal();
  EXPECT_MENTIONS(message, path + ": corner_pocket.capture_");
  EXPECT_MENTIONS(message, "capture_radius_m must be at least");
}

// Only what a ball centre reaches needs covering: balls too big to pass the facings' deep ends
// need no capture circle there, and a smaller ball needs more than a bigger one.
TEST_F(CaptureCircleTest, WhatNeedsCoveringDependsOnTheBallRadius) {
  document["corner_pocket"]["capture_radius_m"] = 0.02;
  document["side_pocket"]["capture_radius_m"] = 0.02;
  const Table table = written();
  EXPECT_THROW(checkCapturesCoverOpenings(table, R), std::invalid_argument);
  const double too_big_to_pass_m = 0.06;  // the closing lines are about 0.1 m long
  for (std::size_t k = 0; k < table.pockets.size(); ++k)
    ASSERT_LT(sampledReach(table, k, too_big_to_pass_m), 0) << "pocket " << k;
  EXPECT_NO_THROW(checkCapturesCoverOpenings(table, too_big_to_pass_m));
  const Table shipped = builtinTable("pool-9ft");
  EXPECT_GT(sampledReach(shipped, 0, 0.5 * R), sampledReach(shipped, 0, R));
}

TEST_F(CaptureCircleTest, ABallRadiusThatIsNotPositiveIsRefused) {
  const Table table = written();
  EXPECT_MENTIONS(invalidArgumentMessage([&] { checkCapturesCoverOpenings(table, 0); }),
                  "ball radius (m) = 0");
  EXPECT_MENTIONS(invalidArgumentMessage([&] {
                    checkCapturesCoverOpenings(table, std::numeric_limits<double>::infinity());
                  }),
                  "ball radius (m) = inf");
}

// The check's promise, by simulation: on tables with random pocket shapes (facing angles 95-175
// deg, facings 4 to 60 mm, mouths, capture offsets up to 0.12 m) whose capture radius is cut down
// to just above the smallest the check accepts, no ball sent at a pocket (anywhere across 1.5
// times its mouth, any speed to 4.3 m/s and spin) leaves the table. (The check that covered only
// the closing line let about 2 % of such shots out; the one that then missed short diverging
// facings, about 0.15 %.)
TEST(CaptureCircle, AtTheSmallestAcceptedRadiusNoBallLeavesTheTable) {
  std::ifstream file(assetsDirectory() + "/tables/pool-9ft.json");
  const nlohmann::json base = nlohmann::json::parse(file);
  const double R = builtinBallSet("pool").radius_m;
  const auto accepted = [&](const nlohmann::json& document) {
    try {
      checkCapturesCoverOpenings(tableFromJson(document, "random table"), R);
      return true;
    } catch (const std::invalid_argument&) {
      return false;
    }
  };
  std::mt19937_64 random(20261121);
  std::uniform_real_distribution<double> unit(0, 1);
  const SimulationParams params = poolSimulationParams();
  int tables = 0, shots = 0, pocketed = 0;
  for (int attempt = 0; attempt < 30; ++attempt) {
    nlohmann::json document = base;
    for (const char* kind : {"corner_pocket", "side_pocket"}) {
      document[kind]["facing_angle_deg"] = 95 + 80 * unit(random);
      document[kind]["capture_offset_m"] = 0.12 * unit(random);
      document[kind]["facing_length_m"] = 0.004 + 0.056 * unit(random);
      document[kind]["mouth_width_m"] = (kind[0] == 'c' ? 0.09 : 0.10) + 0.06 * unit(random);
      document[kind]["capture_radius_m"] = 1.0;
    }
    try {
      tableFromJson(document, "random table");
    } catch (const std::invalid_argument&) {
      continue;  // mouths too wide for the rails, or facings that meet
    }
    for (const char* kind : {"corner_pocket", "side_pocket"}) {
      double refused = 1e-3, enough = 1.0;
      for (int step = 0; step < 50; ++step) {
        document[kind]["capture_radius_m"] = 0.5 * (refused + enough);
        (accepted(document) ? enough : refused) = 0.5 * (refused + enough);
      }
      document[kind]["capture_radius_m"] = enough;
    }
    ASSERT_TRUE(accepted(document));
    const Table table = tableFromJson(document, "random table");
    const TableGeometry geometry = geometryOf(table);
    ++tables;
    for (int shot = 0; shot < 150; ++shot) {
      const Pocket& pocket = table.pockets[random() % table.pockets.size()];
      const Vector2d across(-pocket.axis.y(), pocket.axis.x());
      const double half_mouth = 0.5 * (pocket.jaw_tips_m[1] - pocket.jaw_tips_m[0]).norm();
      const Vector2d target = pocket.mouth_centre_m +
                              (3 * unit(random) - 1.5) * half_mouth * across +
                              0.03 * unit(random) * pocket.axis;
      physics::BallState ball;
      ball.position = Vector2d((2 * unit(random) - 1) * 1.1, (2 * unit(random) - 1) * 0.5);
      const Vector2d aim = (target - ball.position).normalized();
      const double speed = 0.3 + 4 * unit(random), spin = 2 * speed / R;
      ball.velocity = {speed * aim.x(), speed * aim.y(), 0};
      ball.angular_velocity = {spin * (2 * unit(random) - 1), spin * (2 * unit(random) - 1),
                               spin * (2 * unit(random) - 1)};
      ++shots;
      try {
        pocketed += simulate(params, geometry, {ball}).final_balls[0].pocketed;
      } catch (const BallLeftTableError& escape) {
        ADD_FAILURE() << "table " << attempt << ", shot " << shot << ": " << escape.what();
      }
    }
  }
  EXPECT_GE(tables, 20);
  EXPECT_GT(pocketed, shots / 10) << "the shots must reach the pockets";
}

}  // namespace
}  // namespace baize::engine
