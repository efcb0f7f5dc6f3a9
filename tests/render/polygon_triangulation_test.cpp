#include "render/polygon_triangulation.h"

#include <gtest/gtest.h>

#include <stdexcept>

#include "engine/io/table.h"
#include "render/table_picture.h"

namespace baize::render {
namespace {

// Areas are sums of a few hundred products of metre-sized coordinates: rounding is ~1e-15 m^2.
constexpr double kAreaTolerance_m2 = 1e-12;

// Twice the signed area of triangle abc, from edge vectors (accurate for slivers far from 0).
double twiceArea(const Eigen::Vector2d& a, const Eigen::Vector2d& b, const Eigen::Vector2d& c) {
  return (b - a).x() * (c - a).y() - (b - a).y() * (c - a).x();
}

double trianglesArea(const std::vector<Eigen::Vector2d>& triangles) {
  double area = 0;
  for (std::size_t i = 0; i < triangles.size(); i += 3) {
    area += 0.5 * twiceArea(triangles[i], triangles[i + 1], triangles[i + 2]);
  }
  return area;
}

void expectAllCounterclockwise(const std::vector<Eigen::Vector2d>& triangles) {
  ASSERT_EQ(triangles.size() % 3, 0u);
  for (std::size_t i = 0; i < triangles.size(); i += 3) {
    EXPECT_GT(twiceArea(triangles[i], triangles[i + 1], triangles[i + 2]), 0)
        << "triangle " << i / 3;
  }
}

TEST(PolygonTriangulation, SignedAreaOfAUnitSquareByOrientation) {
  const std::vector<Eigen::Vector2d> square = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
  EXPECT_DOUBLE_EQ(signedArea(square), 1.0);
  EXPECT_DOUBLE_EQ(signedArea({square.rbegin(), square.rend()}), -1.0);
}

TEST(PolygonTriangulation, NonConvexLShapeIsCoveredExactly) {
  // An L of area 3: a 2 x 2 square missing its top-right unit square; clockwise on purpose.
  const std::vector<Eigen::Vector2d> l_shape = {{0, 0}, {0, 2}, {1, 2}, {1, 1}, {2, 1}, {2, 0}};
  const std::vector<Eigen::Vector2d> triangles = triangulate(l_shape);
  EXPECT_EQ(triangles.size(), 3u * (l_shape.size() - 2));
  expectAllCounterclockwise(triangles);
  EXPECT_NEAR(trianglesArea(triangles), 3.0, kAreaTolerance_m2);
  // No triangle covers the missing square's centre.
  for (std::size_t i = 0; i < triangles.size(); i += 3) {
    const Eigen::Vector2d p(1.5, 1.5);
    const auto side = [&](const Eigen::Vector2d& a, const Eigen::Vector2d& b) {
      return (b - a).x() * (p - a).y() - (b - a).y() * (p - a).x();
    };
    const bool inside = side(triangles[i], triangles[i + 1]) > 0 &&
                        side(triangles[i + 1], triangles[i + 2]) > 0 &&
                        side(triangles[i + 2], triangles[i]) > 0;
    EXPECT_FALSE(inside) << "triangle " << i / 3;
  }
}

TEST(PolygonTriangulation, EveryShippedClothOutlineIsCoveredExactly) {
  for (const std::string& name : engine::builtinTableNames()) {
    const engine::Table table = engine::builtinTable(name);
    const std::vector<Eigen::Vector2d> outline = clothOutline(table);
    const std::vector<Eigen::Vector2d> triangles = triangulate(outline);
    expectAllCounterclockwise(triangles);
    EXPECT_NEAR(trianglesArea(triangles), signedArea(outline), kAreaTolerance_m2) << name;
  }
}

TEST(PolygonTriangulation, FewerThanThreePointsAreRefused) {
  EXPECT_THROW(triangulate({{0, 0}, {1, 0}}), std::invalid_argument);
}

}  // namespace
}  // namespace baize::render
