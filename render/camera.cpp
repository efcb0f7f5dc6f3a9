#include "render/camera.h"

#include <Eigen/Geometry>
#include <Eigen/LU>
#include <cmath>
#include <stdexcept>

namespace baize::render {
namespace {

// Bisection steps for the angled view's distance: halves the bracket 60 times, to rounding.
constexpr int kFitIterations = 60;

Eigen::Matrix4d orthographic(double half_width_m, double half_height_m, double depth_m) {
  Eigen::Matrix4d m = Eigen::Matrix4d::Identity();
  m(0, 0) = 1 / half_width_m;
  m(1, 1) = 1 / half_height_m;
  m(2, 2) = -1 / depth_m;
  return m;
}

Eigen::Matrix4d perspective(double fovy_rad, double aspect, double near_m, double far_m) {
  const double f = 1 / std::tan(fovy_rad / 2);
  Eigen::Matrix4d m = Eigen::Matrix4d::Zero();
  m(0, 0) = f / aspect;
  m(1, 1) = f;
  m(2, 2) = (far_m + near_m) / (near_m - far_m);
  m(2, 3) = 2 * far_m * near_m / (near_m - far_m);
  m(3, 2) = -1;
  return m;
}

Eigen::Matrix4d lookAt(const Eigen::Vector3d& eye, const Eigen::Vector3d& target,
                       const Eigen::Vector3d& up) {
  const Eigen::Vector3d forward = (target - eye).normalized();
  const Eigen::Vector3d right = forward.cross(up).normalized();
  const Eigen::Vector3d true_up = right.cross(forward);
  Eigen::Matrix4d m = Eigen::Matrix4d::Identity();
  m.block<1, 3>(0, 0) = right.transpose();
  m.block<1, 3>(1, 0) = true_up.transpose();
  m.block<1, 3>(2, 0) = -forward.transpose();
  m(0, 3) = -right.dot(eye);
  m(1, 3) = -true_up.dot(eye);
  m(2, 3) = forward.dot(eye);
  return m;
}

Eigen::Vector3d ndcOf(const Camera& camera, const Eigen::Vector3d& p) {
  const Eigen::Vector4d clip = camera.projection * camera.view * p.homogeneous();
  return clip.head<3>() / clip.w();
}

}  // namespace

View viewNamed(const std::string& name) {
  if (name == "top") return View::Top;
  if (name == "angled") return View::Angled;
  throw std::invalid_argument("view '" + name + "' is not allowed: it must be top or angled");
}

void validateImageSize(int width_px, int height_px) {
  for (const auto& [what, value] : {std::pair<const char*, int>{"width", width_px},
                                    std::pair<const char*, int>{"height", height_px}}) {
    if (value < kMinImageSide_px || value > kMaxImageSide_px) {
      throw std::invalid_argument(std::string("image ") + what + " = " + std::to_string(value) +
                                  " px is not allowed: it must lie in [" +
                                  std::to_string(kMinImageSide_px) + ", " +
                                  std::to_string(kMaxImageSide_px) + "]");
    }
  }
}

Eigen::Vector2d Camera::pixelOf(const Eigen::Vector3d& point_m) const {
  const Eigen::Vector3d ndc = ndcOf(*this, point_m);
  return {(ndc.x() + 1) / 2 * width_px, (1 - ndc.y()) / 2 * height_px};
}

std::optional<Eigen::Vector2d> Camera::tablePointAt(const Eigen::Vector2d& pixel,
                                                    double z_m) const {
  const double ndc_x = 2 * pixel.x() / width_px - 1;
  const double ndc_y = 1 - 2 * pixel.y() / height_px;
  const Eigen::Matrix4d inverse = (projection * view).inverse();
  const auto unproject = [&](double ndc_z) {
    const Eigen::Vector4d p = inverse * Eigen::Vector4d(ndc_x, ndc_y, ndc_z, 1);
    return Eigen::Vector3d(p.head<3>() / p.w());
  };
  const Eigen::Vector3d near_point = unproject(-1), far_point = unproject(1);
  const double dz = far_point.z() - near_point.z();
  if (dz == 0) return std::nullopt;
  const double f = (z_m - near_point.z()) / dz;
  if (!(f >= 0)) return std::nullopt;
  const Eigen::Vector3d hit = near_point + f * (far_point - near_point);
  return hit.head<2>();
}

Camera cameraFor(const Picture& picture, View view, int width_px, int height_px) {
  validateImageSize(width_px, height_px);
  Camera camera;
  camera.width_px = width_px;
  camera.height_px = height_px;
  const Eigen::Vector2d centre = 0.5 * (picture.min_corner_m + picture.max_corner_m);
  const Eigen::Vector2d size = picture.max_corner_m - picture.min_corner_m;
  const double aspect = static_cast<double>(width_px) / height_px;
  const double depth_m = 10 * std::max(size.x(), size.y());
  if (view == View::Top) {
    // Metres per pixel: the larger of what the width and the height need.
    const double scale = std::max(size.x() / width_px, size.y() / height_px);
    camera.view = Eigen::Matrix4d::Identity();
    camera.view.block<2, 1>(0, 3) = -centre;
    camera.projection = orthographic(scale * width_px / 2, scale * height_px / 2, depth_m);
    return camera;
  }
  const double elevation = kAngledElevation_deg * M_PI / 180;
  const Eigen::Vector3d target(centre.x(), centre.y(), 0);
  const Eigen::Vector3d back(0, -std::cos(elevation), std::sin(elevation));
  camera.projection = perspective(kAngledFieldOfView_deg * M_PI / 180, aspect, 0.05, depth_m * 4);
  const auto fits = [&](double distance_m) {
    camera.view = lookAt(target + distance_m * back, target, Eigen::Vector3d::UnitZ());
    for (double x : {picture.min_corner_m.x(), picture.max_corner_m.x()}) {
      for (double y : {picture.min_corner_m.y(), picture.max_corner_m.y()}) {
        for (double z : {0.0, picture.lowest_m}) {
          const Eigen::Vector3d ndc = ndcOf(camera, Eigen::Vector3d(x, y, z));
          if (std::abs(ndc.x()) > kAngledFill || std::abs(ndc.y()) > kAngledFill) return false;
        }
      }
    }
    return true;
  };
  double near = 0.1 * std::max(size.x(), size.y()), far = depth_m;
  for (int i = 0; i < kFitIterations; ++i) {
    const double mid = 0.5 * (near + far);
    (fits(mid) ? far : near) = mid;
  }
  fits(far);
  return camera;
}

}  // namespace baize::render
