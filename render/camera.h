// Where the table lands in the image: a top-down orthographic view (the default; x to the right,
// y up, the whole table fitted with its aspect kept) or an angled perspective view from above the
// -y side. Pure math, shared by the renderer and the tests.
#pragma once

#include <Eigen/Core>
#include <optional>
#include <string>

#include "render/draw_items.h"

namespace baize::render {

enum class View { Top, Angled };

// "top" or "angled"; throws std::invalid_argument naming the text otherwise.
View viewNamed(const std::string& name);

// The smallest and largest image side the renderer accepts, px.
constexpr int kMinImageSide_px = 16;
constexpr int kMaxImageSide_px = 8192;

// Throws std::invalid_argument naming the value unless both sides lie in
// [kMinImageSide_px, kMaxImageSide_px].
void validateImageSize(int width_px, int height_px);

struct Camera {
  Eigen::Matrix4d view = Eigen::Matrix4d::Identity();        // table frame -> eye frame
  Eigen::Matrix4d projection = Eigen::Matrix4d::Identity();  // eye frame -> clip space
  int width_px = 0;
  int height_px = 0;

  // The image position of a table point: x from the left edge, y from the top row, in pixels
  // (pixel (i, j) covers [i, i + 1) x [j, j + 1)).
  Eigen::Vector2d pixelOf(const Eigen::Vector3d& point_m) const;
  // The table point at height z_m seen at this image position (the inverse of pixelOf on that
  // plane); nothing when the line of sight does not meet the plane in front of the camera.
  std::optional<Eigen::Vector2d> tablePointAt(const Eigen::Vector2d& pixel, double z_m) const;
};

// Angled view: the camera looks down at this angle from the horizontal, with this vertical field of
// view, from the -y side of the table.
constexpr double kAngledElevation_deg = 40.0;
constexpr double kAngledFieldOfView_deg = 30.0;
// The picture's frame fills at most this fraction of the image (the rest is margin).
constexpr double kAngledFill = 0.96;

Camera cameraFor(const Picture& picture, View view, int width_px, int height_px);

}  // namespace baize::render
