#include "render/table_picture.h"

#include <gtest/gtest.h>

#include "render/polygon_triangulation.h"

namespace baize::render {
namespace {

// Table coordinates are computed from millimetre inputs in a few operations: rounding ~1e-15 m.
constexpr double kGeometryTolerance_m = 1e-12;

double distanceToSegment(const Eigen::Vector2d& p, const Eigen::Vector2d& a,
                         const Eigen::Vector2d& b) {
  const double f = std::clamp((p - a).dot(b - a) / (b - a).squaredNorm(), 0.0, 1.0);
  return (a + f * (b - a) - p).norm();
}

bool segmentsCross(const Eigen::Vector2d& a, const Eigen::Vector2d& b, const Eigen::Vector2d& c,
                   const Eigen::Vector2d& d) {
  const auto side = [](const Eigen::Vector2d& p, const Eigen::Vector2d& q,
                       const Eigen::Vector2d& r) {
    return (q - p).x() * (r - p).y() - (q - p).y() * (r - p).x();
  };
  return side(a, b, c) * side(a, b, d) < 0 && side(c, d, a) * side(c, d, b) < 0;
}

class EveryTable : public ::testing::TestWithParam<std::string> {};

TEST_P(EveryTable, ClothOutlineIsASimpleCounterclockwisePolygonThroughEveryCushion) {
  const engine::Table table = engine::builtinTable(GetParam());
  const std::vector<Eigen::Vector2d> outline = clothOutline(table);
  EXPECT_GT(signedArea(outline), 0);
  // Every cushion's ends are corners of the outline (the outline follows the real cushions).
  for (const engine::CushionSegment& c : table.cushions) {
    for (const Eigen::Vector2d& end : {c.start_m, c.end_m}) {
      double nearest = 1e9;
      for (const Eigen::Vector2d& p : outline) nearest = std::min(nearest, (p - end).norm());
      EXPECT_LT(nearest, kGeometryTolerance_m);
    }
  }
  // No two edges that do not share a corner cross.
  const std::size_t n = outline.size();
  for (std::size_t i = 0; i < n; ++i) {
    for (std::size_t j = i + 2; j < n; ++j) {
      if (i == 0 && j == n - 1) continue;
      EXPECT_FALSE(
          segmentsCross(outline[i], outline[(i + 1) % n], outline[j], outline[(j + 1) % n]))
          << "edges " << i << " and " << j;
    }
  }
  // The playing rectangle's middle is inside and the cloth reaches past it only at the pockets:
  // every outline point is on a cushion or jaw, within the table's outer frame.
  for (const Eigen::Vector2d& p : outline) {
    EXPECT_LT(std::abs(p.x()), table.length_m / 2 + kRailOuterEdge_m);
    EXPECT_LT(std::abs(p.y()), table.width_m / 2 + kRailOuterEdge_m);
    double nearest = 1e9;
    for (const engine::CushionSegment& c : table.cushions) {
      nearest = std::min(nearest, distanceToSegment(p, c.start_m, c.end_m));
    }
    for (const engine::JawArc& arc : table.jaw_arcs) {
      nearest = std::min(nearest, std::abs((p - arc.centre_m).norm() - arc.radius_m));
    }
    // Points on the closing edge across a pocket are facing ends, so they lie on a cushion too.
    EXPECT_LT(nearest, kGeometryTolerance_m) << p.transpose();
  }
}

TEST_P(EveryTable, PictureIsFramedByTheRailAndHoldsTheMarkings) {
  const engine::Table table = engine::builtinTable(GetParam());
  Picture picture;
  addTable(table, picture);
  EXPECT_DOUBLE_EQ(picture.max_corner_m.x(), table.length_m / 2 + kRailOuterEdge_m);
  EXPECT_DOUBLE_EQ(picture.max_corner_m.y(), table.width_m / 2 + kRailOuterEdge_m);
  EXPECT_EQ(picture.min_corner_m, -picture.max_corner_m);
  const Rgba marking = tableColours(table.kind).marking;
  const Rgba pocket = tableColours(table.kind).pocket;
  std::size_t marking_discs = 0, pocket_discs = 0, marking_strokes = 0;
  for (const DrawItem& item : picture.items) {
    if (const Disc* d = std::get_if<Disc>(&item)) {
      marking_discs += d->colour == marking;
      pocket_discs += d->colour == pocket;
    }
    if (const Stroke* s = std::get_if<Stroke>(&item)) marking_strokes += s->colour == marking;
  }
  EXPECT_EQ(pocket_discs, table.pockets.size());
  if (table.kind == engine::TableKind::Pool) {
    EXPECT_EQ(marking_discs, table.pool_markings->diamonds_m.size() + 2);  // and two spots
    EXPECT_EQ(marking_strokes, 0u);
  } else {
    EXPECT_EQ(marking_discs, 6u);    // yellow, green, brown, blue, pink, black spots
    EXPECT_EQ(marking_strokes, 2u);  // the baulk line and the D
  }
}

TEST_P(EveryTable, NearCushionsStandInTheForegroundAndTheOthersShowTheirNoses) {
  const engine::Table table = engine::builtinTable(GetParam());
  Picture picture;
  addTable(table, picture);
  std::size_t near_rails = 0;
  for (std::size_t k = 0; k < table.pockets.size(); ++k) {
    near_rails += table.cushions[3 * k + 2].inward_normal.y() > 0.5;
  }
  EXPECT_EQ(near_rails, 2u);  // the -y side, split by its middle pocket
  ASSERT_EQ(picture.foreground.size(), near_rails);
  for (const DrawItem& item : picture.foreground) {
    const Mesh& top = std::get<Mesh>(item);
    EXPECT_DOUBLE_EQ(top.z_m, table.cushion_contact_height_m);
    for (const Eigen::Vector2d& p : top.triangles_m) {  // between the nose and the cushion's back
      EXPECT_LE(p.y(), -table.width_m / 2 + kGeometryTolerance_m);
      EXPECT_GE(p.y(), -table.width_m / 2 - kCushionWidth_m - kGeometryTolerance_m);
    }
  }
  std::size_t walls = 0;
  for (const DrawItem& item : picture.items) walls += std::holds_alternative<Wall>(item);
  // The table's near side and the noses of the other rail cushions.
  EXPECT_EQ(walls, 1 + table.pockets.size() - near_rails);
  EXPECT_DOUBLE_EQ(picture.lowest_m, -kTableSideDepth_m);
}

INSTANTIATE_TEST_SUITE_P(Shipped, EveryTable, ::testing::ValuesIn(engine::builtinTableNames()),
                         [](const auto& info) {
                           std::string name = info.param;
                           std::replace(name.begin(), name.end(), '-', '_');
                           return name;
                         });

TEST(TablePicture, SnookerBaulkLineAndDSitWhereTheMarkingsSay) {
  const engine::Table table = engine::builtinTable("snooker-12ft");
  Picture picture;
  addTable(table, picture);
  const engine::SnookerMarkings& m = *table.snooker_markings;
  std::vector<const Stroke*> strokes;
  for (const DrawItem& item : picture.items) {
    if (const Stroke* s = std::get_if<Stroke>(&item)) strokes.push_back(s);
  }
  ASSERT_EQ(strokes.size(), 2u);
  for (const Eigen::Vector2d& p : strokes[0]->points_m) {
    EXPECT_DOUBLE_EQ(p.x(), m.baulk_line_x_m);
  }
  for (const Eigen::Vector2d& p : strokes[1]->points_m) {  // the D: baulk side of the line
    EXPECT_NEAR((p - m.brown_spot_m).norm(), m.d_radius_m, kGeometryTolerance_m);
    EXPECT_LE(p.x(), m.baulk_line_x_m + kGeometryTolerance_m);
  }
}

}  // namespace
}  // namespace baize::render
