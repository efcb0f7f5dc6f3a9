#include "render/camera.h"

#include <gtest/gtest.h>

#include <stdexcept>

namespace baize::render {
namespace {

// Pixel positions go through a 4x4 double transform: rounding ~1e-12 px.
constexpr double kPixelTolerance_px = 1e-9;

Picture framed(double half_length_m, double half_width_m) {
  Picture picture;
  picture.min_corner_m = {-half_length_m, -half_width_m};
  picture.max_corner_m = {half_length_m, half_width_m};
  return picture;
}

TEST(Camera, TopViewCentresTheFrameKeepsItsAspectAndPutsPlusYUp) {
  const Camera camera = cameraFor(framed(1.4, 0.7), View::Top, 1000, 400);
  const Eigen::Vector2d centre = camera.pixelOf({0, 0, 0});
  EXPECT_NEAR(centre.x(), 500, kPixelTolerance_px);
  EXPECT_NEAR(centre.y(), 200, kPixelTolerance_px);
  // The height limits: 1.4 m tall frame in 400 px, so 1 m is 400 / 1.4 px both ways.
  const double px_per_m = 400 / 1.4;
  EXPECT_NEAR(camera.pixelOf({1, 0, 0}).x() - centre.x(), px_per_m, kPixelTolerance_px);
  EXPECT_NEAR(camera.pixelOf({0, 1, 0}).y() - centre.y(), -px_per_m, kPixelTolerance_px);
  EXPECT_NEAR(camera.pixelOf({0, 0.7, 0}).y(), 0, kPixelTolerance_px);  // top edge: top row
  // Height above the cloth does not move a point in the top view.
  EXPECT_NEAR((camera.pixelOf({0.3, 0.2, 0.05}) - camera.pixelOf({0.3, 0.2, 0})).norm(), 0,
              kPixelTolerance_px);
}

TEST(Camera, AngledViewFitsTheFrameWithTheNearSideLowerAndWider) {
  const Picture picture = framed(1.42, 0.78);
  const Camera camera = cameraFor(picture, View::Angled, 1600, 800);
  for (double x : {-1.42, 1.42}) {
    for (double y : {-0.78, 0.78}) {
      const Eigen::Vector2d p = camera.pixelOf({x, y, 0});
      EXPECT_GT(p.x(), 0);
      EXPECT_LT(p.x(), 1600);
      EXPECT_GT(p.y(), 0);
      EXPECT_LT(p.y(), 800);
    }
  }
  const double near_width =
      camera.pixelOf({1.42, -0.78, 0}).x() - camera.pixelOf({-1.42, -0.78, 0}).x();
  const double far_width =
      camera.pixelOf({1.42, 0.78, 0}).x() - camera.pixelOf({-1.42, 0.78, 0}).x();
  EXPECT_GT(near_width, far_width);
  EXPECT_GT(camera.pixelOf({0, -0.78, 0}).y(), camera.pixelOf({0, 0.78, 0}).y());
  // Something above the cloth appears higher in the image.
  EXPECT_LT(camera.pixelOf({0, 0, 0.05}).y(), camera.pixelOf({0, 0, 0}).y());
}

TEST(Camera, TablePointAtUndoesPixelOfInBothViews) {
  // Unprojection inverts a 4x4 matrix: rounding ~1e-12 m on a metre-sized table.
  constexpr double kRoundTrip_m = 1e-9;
  const Picture picture = framed(1.42, 0.78);
  for (View view : {View::Top, View::Angled}) {
    const Camera camera = cameraFor(picture, view, 1200, 700);
    for (const Eigen::Vector3d& p :
         {Eigen::Vector3d(0.3, -0.2, 0.0), Eigen::Vector3d(-1.1, 0.6, 0.028),
          Eigen::Vector3d(1.2, 0.7, 0.0)}) {
      const std::optional<Eigen::Vector2d> back = camera.tablePointAt(camera.pixelOf(p), p.z());
      ASSERT_TRUE(back.has_value());
      EXPECT_NEAR((*back - p.head<2>()).norm(), 0, kRoundTrip_m);
    }
  }
}

TEST(Camera, ViewNamesAndImageSizesAreChecked) {
  EXPECT_EQ(viewNamed("top"), View::Top);
  EXPECT_EQ(viewNamed("angled"), View::Angled);
  EXPECT_THROW(viewNamed("side"), std::invalid_argument);
  EXPECT_THROW(validateImageSize(0, 100), std::invalid_argument);
  EXPECT_THROW(validateImageSize(100, 100000), std::invalid_argument);
  EXPECT_NO_THROW(validateImageSize(kMinImageSide_px, kMaxImageSide_px));
  EXPECT_THROW(cameraFor(framed(1, 1), View::Top, kMaxImageSide_px + 1, 100),
               std::invalid_argument);
}

}  // namespace
}  // namespace baize::render
