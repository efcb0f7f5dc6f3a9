#include "render/polygon_triangulation.h"

#include <cmath>
#include <stdexcept>
#include <string>

namespace baize::render {
namespace {

// A corner whose turn (the sine of the angle between its edges) is below this is straight: it is
// dropped rather than clipped into a sliver of no area. Dropping it changes the area by at most
// half this times the product of the edges, 1e-13 m^2 for metre-long edges.
constexpr double kStraightTurn = 1e-13;

double cross(const Eigen::Vector2d& a, const Eigen::Vector2d& b, const Eigen::Vector2d& c) {
  return (b - a).x() * (c - a).y() - (b - a).y() * (c - a).x();
}

// Inside or on the edge of the counterclockwise triangle abc.
bool inTriangle(const Eigen::Vector2d& p, const Eigen::Vector2d& a, const Eigen::Vector2d& b,
                const Eigen::Vector2d& c) {
  return cross(a, b, p) >= 0 && cross(b, c, p) >= 0 && cross(c, a, p) >= 0;
}

}  // namespace

double signedArea(const std::vector<Eigen::Vector2d>& polygon) {
  double twice = 0;
  for (std::size_t i = 0; i < polygon.size(); ++i) {
    const Eigen::Vector2d& p = polygon[i];
    const Eigen::Vector2d& q = polygon[(i + 1) % polygon.size()];
    twice += p.x() * q.y() - q.x() * p.y();
  }
  return 0.5 * twice;
}

std::vector<Eigen::Vector2d> triangulate(const std::vector<Eigen::Vector2d>& polygon) {
  if (polygon.size() < 3) {
    throw std::invalid_argument("polygon with " + std::to_string(polygon.size()) +
                                " points cannot be filled: it needs at least 3");
  }
  std::vector<Eigen::Vector2d> ring = polygon;
  if (signedArea(ring) < 0) ring.assign(polygon.rbegin(), polygon.rend());
  std::vector<Eigen::Vector2d> triangles;
  triangles.reserve(3 * (ring.size() - 2));
  while (ring.size() > 3) {
    bool clipped = false;
    for (std::size_t i = 0; i < ring.size() && !clipped; ++i) {
      const std::size_t prev = (i + ring.size() - 1) % ring.size();
      const std::size_t next = (i + 1) % ring.size();
      const Eigen::Vector2d &a = ring[prev], &b = ring[i], &c = ring[next];
      const double turn = cross(a, b, c);
      if (turn < 0 && -turn > kStraightTurn * (b - a).norm() * (c - b).norm()) {
        continue;  // a reflex corner is never an ear
      }
      if (std::abs(turn) <= kStraightTurn * (b - a).norm() * (c - b).norm()) {
        // a straight-through point adds nothing: drop it
        ring.erase(ring.begin() + static_cast<std::ptrdiff_t>(i));
        clipped = true;
        break;
      }
      bool empty = true;
      for (std::size_t j = 0; j < ring.size() && empty; ++j) {
        if (j == prev || j == i || j == next) continue;
        if (ring[j] == a || ring[j] == b || ring[j] == c) continue;
        empty = !inTriangle(ring[j], a, b, c);
      }
      if (!empty) continue;
      triangles.insert(triangles.end(), {a, b, c});
      ring.erase(ring.begin() + static_cast<std::ptrdiff_t>(i));
      clipped = true;
    }
    if (!clipped) {
      throw std::invalid_argument("polygon cannot be filled: it crosses itself");
    }
  }
  if (cross(ring[0], ring[1], ring[2]) > 0)
    triangles.insert(triangles.end(), ring.begin(), ring.end());
  return triangles;
}

}  // namespace baize::render
