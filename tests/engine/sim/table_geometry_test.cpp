#include "engine/sim/table_geometry.h"

#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>
#include <vector>

namespace baize::engine {
namespace {

using Eigen::Vector2d;

// Coordinates of a few operations on metre-sized values: rounding.
constexpr double kRounding_m = 1e-15;

// A rectangle's four cushions run counterclockwise with unit inward normals, and its outline is
// the rectangle: a point inside is inside, one just outside is not.
TEST(TableGeometry, ARectangularTableIsItsFourCushionsCounterclockwise) {
  const TableGeometry table = rectangularTable(2.0, 1.0);
  ASSERT_EQ(table.cushions.size(), 4u);
  for (const CushionSegment& c : table.cushions) {
    EXPECT_NEAR(c.inward_normal.norm(), 1, kRounding_m);
    const Vector2d along = c.end_m - c.start_m;
    // The inward normal is the direction of travel turned +90 degrees.
    EXPECT_NEAR(c.inward_normal.dot(Vector2d(-along.y(), along.x()).normalized()), 1, kRounding_m);
    EXPECT_GT(c.inward_normal.dot(-c.start_m), 0);  // towards the centre
  }
  ASSERT_EQ(table.outline.size(), 8u);  // each cushion's two ends
  EXPECT_TRUE(insideOutline(table.outline, Vector2d(0.99, 0.49)));
  EXPECT_FALSE(insideOutline(table.outline, Vector2d(1.01, 0)));
  EXPECT_FALSE(insideOutline(table.outline, Vector2d(0, -0.51)));
  EXPECT_TRUE(table.rail_box.contains(Vector2d(0.9, 0.4)));
  EXPECT_TRUE(table.jaws.empty());
  EXPECT_TRUE(table.pockets.empty());
}

TEST(TableGeometry, ARectangleOfNoSizeIsRefusedWithTheValue) {
  EXPECT_THROW(rectangularTable(0, 1), std::invalid_argument);
  EXPECT_THROW(rectangularTable(2, -1), std::invalid_argument);
  EXPECT_THROW(rectangularTable(std::nan(""), 1), std::invalid_argument);
  try {
    rectangularTable(2, -1);
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("-1"), std::string::npos) << e.what();
  }
}

// A jaw's points lie on its circle at the angles asked.
TEST(TableGeometry, AJawArcsPointsLieOnItsCircle) {
  JawArc jaw;
  jaw.centre_m = Vector2d(0.3, -0.2);
  jaw.radius_m = 0.01;
  for (double a : {-3.0, -1.0, 0.0, 0.5, 2.0}) {
    const Vector2d p = jaw.pointAt(a);
    EXPECT_NEAR((p - jaw.centre_m).norm(), jaw.radius_m, kRounding_m);
    EXPECT_NEAR(std::atan2(p.y() - jaw.centre_m.y(), p.x() - jaw.centre_m.x()), a, 1e-12);
  }
}

// An outline with a notch reaching into its rail box, or a vertex inside it, gives no box.
TEST(RailBox, AnEdgeOrVertexReachingIntoTheRailBoxEmptiesIt) {
  const std::vector<Vector2d> square = {{-1, -1}, {1, -1}, {1, 1}, {-1, 1}};
  EXPECT_TRUE(railBoxInsideOutline(square).isApprox(
      Eigen::AlignedBox2d(Vector2d(-1 + 1e-9, -1 + 1e-9), Vector2d(1 - 1e-9, 1 - 1e-9))));
  // A V-shaped notch from the bottom rail up to (0, -0.5).
  const std::vector<Vector2d> notched = {{-1, -1}, {-0.2, -1}, {0, -0.5}, {0.2, -1},
                                         {1, -1},  {1, 1},     {-1, 1}};
  EXPECT_TRUE(railBoxInsideOutline(notched).isEmpty());
  // A slanted edge cutting a corner off.
  const std::vector<Vector2d> cut = {{-1, -1}, {0.5, -1}, {1, -0.5}, {1, 1}, {-1, 1}};
  EXPECT_TRUE(railBoxInsideOutline(cut).isEmpty());
}

}  // namespace
}  // namespace baize::engine
