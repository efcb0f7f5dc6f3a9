// What to draw, as plain data in table coordinates (metres, z up): built from engine types by
// render/table_picture.h and render/shot_picture.h, drawn by render/gl_renderer.h. No OpenGL here,
// so tests can check a picture's content without pixels.
#pragma once

#include <Eigen/Core>
#include <string>
#include <variant>
#include <vector>

namespace baize::render {

struct Rgba {
  float r = 0, g = 0, b = 0, a = 1;  // each in [0, 1]
  bool operator==(const Rgba& o) const { return r == o.r && g == o.g && b == o.b && a == o.a; }
};

// "#rrggbb" as a colour; throws std::invalid_argument naming the text otherwise.
Rgba colourFromHex(const std::string& hex);

// Filled triangles lying flat at height z_m: three points per triangle.
struct Mesh {
  std::vector<Eigen::Vector2d> triangles_m;
  double z_m = 0;
  Rgba colour;
};

// A polyline of constant width lying flat at height z_m.
struct Stroke {
  std::vector<Eigen::Vector2d> points_m;
  double width_m = 0;
  double z_m = 0;
  Rgba colour;
};

enum class DiscStyle {
  Flat,         // a filled disc lying on the cloth
  Ring,         // a ring lying on the cloth: from inner_fraction * radius to radius
  Ball,         // a shaded sphere of this radius centred at centre_m
  StripedBall,  // a white shaded sphere with a band of `colour` (pool 9-15)
};

struct Disc {
  Eigen::Vector3d centre_m = Eigen::Vector3d::Zero();
  double radius_m = 0;
  Rgba colour;
  DiscStyle style = DiscStyle::Flat;
  double inner_fraction = 0;  // Ring only, in [0, 1)
  std::string label;          // Ball, StripedBall: the printed number (printable ASCII), or none
};

// A vertical face standing on the segment from -> to, between two heights (a cushion's nose, the
// table's side). Seen from straight above it has no area, so it shows only in the angled view.
struct Wall {
  Eigen::Vector2d from_m = Eigen::Vector2d::Zero();
  Eigen::Vector2d to_m = Eigen::Vector2d::Zero();
  double bottom_m = 0;
  double top_m = 0;
  Rgba colour;
};

using DrawItem = std::variant<Mesh, Stroke, Disc, Wall>;

// One row of the legend the renderer lays out in an image corner: a ball swatch (when
// `swatch`) and a line of text (printable ASCII).
struct LegendRow {
  bool swatch = false;
  Rgba colour;
  bool striped = false;
  std::string text;
};

// Everything to draw, in painter's order (balls, which stand up from the cloth, are drawn last by
// the renderer, far to near).
struct Picture {
  Eigen::Vector2d min_corner_m = Eigen::Vector2d::Zero();  // the table's outer edge: what to frame
  Eigen::Vector2d max_corner_m = Eigen::Vector2d::Zero();
  Rgba background{0.12f, 0.12f, 0.13f, 1};
  std::vector<DrawItem> items;
  // Drawn after the balls: what stands between the camera of the angled view and the cloth (the
  // raised near cushion), laid where nothing else is drawn in the top view.
  std::vector<DrawItem> foreground;
  double lowest_m = 0;  // the lowest point drawn (the table's side), m: the angled view frames it
  std::vector<LegendRow> legend;  // empty: no legend
};

}  // namespace baize::render
