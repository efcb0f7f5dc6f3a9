// Draw items laid over a table (render/draw_items.h) for maps and checks: markers of several
// shapes, outlines of circles, rectangles and ellipses, straight segments, and a colour scale.
// Built from the existing items (flat meshes and strokes), so the renderer needs nothing new.
#pragma once

#include <Eigen/Core>

#include "render/draw_items.h"

namespace baize::render {

enum class MarkerShape {
  Disc,      // a filled disc
  Square,    // a filled square, axis-aligned
  Triangle,  // a filled triangle, point up (+y)
};

// A filled marker of this shape whose outer size (the disc's diameter, the square's side, the
// triangle's circumscribed diameter) is size_m, with a dark edge of edge_m so that it shows on any
// colour of cloth or of another marker. Appended to `picture.items`.
void addMarker(Picture& picture, MarkerShape shape, const Eigen::Vector2d& centre_m, double size_m,
               double edge_m, const Rgba& colour);

// Closed outlines of width_m, sampled finely enough for any picture (kOutlineSegments).
constexpr int kOutlineSegments = 96;
Stroke circleOutline(const Eigen::Vector2d& centre_m, double radius_m, double width_m,
                     const Rgba& colour);
Stroke rectangleOutline(const Eigen::Vector2d& min_m, const Eigen::Vector2d& max_m, double width_m,
                        const Rgba& colour);
// The ellipse with these semi-axes, the major one at major_axis_rad from +x.
Stroke ellipseOutline(const Eigen::Vector2d& centre_m, double semi_major_m, double semi_minor_m,
                      double major_axis_rad, double width_m, const Rgba& colour);
Stroke segment(const Eigen::Vector2d& from_m, const Eigen::Vector2d& to_m, double width_m,
               const Rgba& colour);

// A colour scale for t in [0, 1] (clamped): dark blue, purple, pink, orange, yellow (the plasma
// anchors, linearly between them). Lightness rises along it, so it reads in grey too, and no part
// of it is a cloth's blue-green.
Rgba scaleColour(double t);

// The marker edge: near-black, seen on cloth, rail and every scale colour.
Rgba markerEdgeColour();

}  // namespace baize::render
