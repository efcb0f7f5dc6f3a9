// Filling a simple polygon (the cloth with its pocket throats is not convex) with triangles.
#pragma once

#include <Eigen/Core>
#include <vector>

namespace baize::render {

// Signed area, m^2: positive when the points run counterclockwise.
double signedArea(const std::vector<Eigen::Vector2d>& polygon);

// Triangles (three points each) covering a simple polygon of at least 3 points, in either
// orientation, by ear clipping; the triangles' areas add up to the polygon's. Throws
// std::invalid_argument for fewer than 3 points or a polygon that cannot be clipped (it crosses
// itself).
std::vector<Eigen::Vector2d> triangulate(const std::vector<Eigen::Vector2d>& polygon);

}  // namespace baize::render
