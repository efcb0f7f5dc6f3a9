#include "render/overlay_items.h"

#include <algorithm>
#include <array>
#include <cmath>

namespace baize::render {
namespace {

// The flat items lie on the cloth like the traces; painter's order puts them over it.
constexpr double kOverlayHeight_m = 0.0;

Mesh polygonMesh(const std::vector<Eigen::Vector2d>& convex_m, const Rgba& colour) {
  Mesh mesh;
  mesh.z_m = kOverlayHeight_m;
  mesh.colour = colour;
  for (std::size_t i = 1; i + 1 < convex_m.size(); ++i) {
    mesh.triangles_m.insert(mesh.triangles_m.end(), {convex_m[0], convex_m[i], convex_m[i + 1]});
  }
  return mesh;
}

// The convex outline of a marker of outer size size_m (see addMarker).
std::vector<Eigen::Vector2d> markerOutline(MarkerShape shape, const Eigen::Vector2d& c,
                                           double size_m) {
  const double h = size_m / 2;
  switch (shape) {
    case MarkerShape::Square:
      return {c + Eigen::Vector2d(-h, -h), c + Eigen::Vector2d(h, -h), c + Eigen::Vector2d(h, h),
              c + Eigen::Vector2d(-h, h)};
    case MarkerShape::Triangle: {
      std::vector<Eigen::Vector2d> points;
      for (int k = 0; k < 3; ++k) {
        const double angle = M_PI / 2 + k * 2 * M_PI / 3;
        points.push_back(c + h * Eigen::Vector2d(std::cos(angle), std::sin(angle)));
      }
      return points;
    }
    case MarkerShape::Disc:
      break;
  }
  return {};
}

Stroke closedStroke(std::vector<Eigen::Vector2d> points, double width_m, const Rgba& colour) {
  points.push_back(points.front());
  Stroke s;
  s.points_m = std::move(points);
  s.width_m = width_m;
  s.z_m = kOverlayHeight_m;
  s.colour = colour;
  return s;
}

}  // namespace

void addMarker(Picture& picture, MarkerShape shape, const Eigen::Vector2d& centre_m, double size_m,
               double edge_m, const Rgba& colour) {
  if (shape == MarkerShape::Disc) {
    Disc edge;
    edge.centre_m = Eigen::Vector3d(centre_m.x(), centre_m.y(), kOverlayHeight_m);
    edge.radius_m = size_m / 2;
    edge.colour = markerEdgeColour();
    Disc fill = edge;
    fill.radius_m = std::max(0.0, size_m / 2 - edge_m);
    fill.colour = colour;
    picture.items.push_back(edge);
    picture.items.push_back(fill);
    return;
  }
  const std::vector<Eigen::Vector2d> outline = markerOutline(shape, centre_m, size_m);
  picture.items.push_back(polygonMesh(outline, markerEdgeColour()));
  // The fill: the same shape shrunk towards its centre so that the edge is edge_m wide (for the
  // triangle the inscribed radius is half the circumscribed one, hence twice the shrink).
  const double inset_m = shape == MarkerShape::Triangle ? 2 * edge_m : edge_m;
  const double fill_size_m = std::max(0.0, size_m - 2 * inset_m);
  picture.items.push_back(polygonMesh(markerOutline(shape, centre_m, fill_size_m), colour));
}

Stroke circleOutline(const Eigen::Vector2d& centre_m, double radius_m, double width_m,
                     const Rgba& colour) {
  return ellipseOutline(centre_m, radius_m, radius_m, 0, width_m, colour);
}

Stroke rectangleOutline(const Eigen::Vector2d& min_m, const Eigen::Vector2d& max_m, double width_m,
                        const Rgba& colour) {
  return closedStroke({min_m, {max_m.x(), min_m.y()}, max_m, {min_m.x(), max_m.y()}}, width_m,
                      colour);
}

Stroke ellipseOutline(const Eigen::Vector2d& centre_m, double semi_major_m, double semi_minor_m,
                      double major_axis_rad, double width_m, const Rgba& colour) {
  const Eigen::Vector2d major(std::cos(major_axis_rad), std::sin(major_axis_rad));
  const Eigen::Vector2d minor(-major.y(), major.x());
  std::vector<Eigen::Vector2d> points;
  for (int k = 0; k < kOutlineSegments; ++k) {
    const double t = 2 * M_PI * k / kOutlineSegments;
    points.push_back(centre_m + semi_major_m * std::cos(t) * major +
                     semi_minor_m * std::sin(t) * minor);
  }
  return closedStroke(std::move(points), width_m, colour);
}

Stroke segment(const Eigen::Vector2d& from_m, const Eigen::Vector2d& to_m, double width_m,
               const Rgba& colour) {
  Stroke s;
  s.points_m = {from_m, to_m};
  s.width_m = width_m;
  s.z_m = kOverlayHeight_m;
  s.colour = colour;
  return s;
}

Rgba scaleColour(double t) {
  // plasma at t = 0, 0.25, 0.5, 0.75, 1 (sRGB): dark blue, purple, pink, orange, yellow. Unlike
  // viridis it has no teal or green in the middle, which would vanish on pool or snooker cloth.
  static const std::array<Rgba, 5> anchors = {
      Rgba{0.050f, 0.030f, 0.529f, 1}, Rgba{0.494f, 0.012f, 0.659f, 1},
      Rgba{0.798f, 0.280f, 0.470f, 1}, Rgba{0.973f, 0.585f, 0.253f, 1},
      Rgba{0.940f, 0.975f, 0.131f, 1}};
  const double x = std::clamp(std::isfinite(t) ? t : 0.0, 0.0, 1.0) * (anchors.size() - 1);
  const std::size_t i = std::min(static_cast<std::size_t>(x), anchors.size() - 2);
  const float f = static_cast<float>(x - i);
  const Rgba &a = anchors[i], &b = anchors[i + 1];
  return {a.r + (b.r - a.r) * f, a.g + (b.g - a.g) * f, a.b + (b.b - a.b) * f, 1};
}

Rgba markerEdgeColour() { return {0.05f, 0.05f, 0.05f, 1}; }

}  // namespace baize::render
