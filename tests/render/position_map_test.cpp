#include "render/position_map.h"

#include <gtest/gtest.h>

#include <cmath>

#include "render/camera.h"
#include "render/overlay_items.h"
#include "render/shot_picture.h"
#include "render/table_picture.h"
#include "tests/render/render_test_support.h"

namespace baize::render {
namespace {

constexpr int kWidth_px = 1000;
constexpr int kHeight_px = 500;
// Ellipse outlines are 2 px wide and antialiased: a pixel on one is a blend of the line and the
// cloth, so it is compared looser than a marker's fill (0-255 per channel).
constexpr int kOutlineTolerance = 60;
// A pixel this far (0-255, largest channel) from a marker's colour is not that marker: the cloth
// and the dark edge are further than this from every scale colour used here.
constexpr int kNotThisColour = 40;
// The cloth is further than this from the ellipse's yellow in some channel (0-255).
constexpr int kNotTheEllipse = 100;

struct Drawn {
  Picture picture;
  Camera camera;
  Image image;
  double pixel_m = 0;
  Eigen::Vector2i pixelAt(const Eigen::Vector2d& point_m) const {
    const Eigen::Vector2d p = camera.pixelOf({point_m.x(), point_m.y(), 0});
    return {static_cast<int>(std::floor(p.x())), static_cast<int>(std::floor(p.y()))};
  }
  const std::uint8_t* at(const Eigen::Vector2d& point_m) const {
    const Eigen::Vector2i p = pixelAt(point_m);
    return image.pixel(p.x(), p.y());
  }
};

const MapPoint kPotted{{0.6, 0.3}, MapOutcome::ObjectPocketed, 0.0, 1.0, std::nullopt};
const MapPoint kScratch{{-0.6, -0.3}, MapOutcome::CueBallPocketed, 1.0, 1.0, std::nullopt};
const MapPoint kMissed{{-0.6, 0.3}, MapOutcome::Missed, 0.5, 1.0, std::nullopt};

Drawn drawMap(const std::vector<MapPoint>& points) {
  const engine::Table table = engine::builtinTable("pool-9ft");
  Drawn d;
  d.pixel_m = pixelSizeFor(table, kWidth_px, kHeight_px);
  d.picture =
      buildPositionMap(table, points, {{"speed", 0.5, 4}, {"tip-height", -0.5, 0.5}}, d.pixel_m, 0);
  d.picture.legend.clear();  // the legend panel covers a corner; these checks look at the cloth
  d.camera = cameraFor(d.picture, View::Top, kWidth_px, kHeight_px);
  GlRenderer& renderer = testRenderer();
  renderer.draw(d.picture, d.camera);
  d.image = renderer.readImage();
  return d;
}

TEST(PositionMap, ImageHasTheAskedSizeAndEachMarkerSitsAtItsPixelInItsColour) {
  const Drawn d = drawMap({kPotted, kScratch, kMissed});
  EXPECT_EQ(d.image.width_px, kWidth_px);
  EXPECT_EQ(d.image.height_px, kHeight_px);
  for (const MapPoint& p : {kPotted, kScratch, kMissed}) {
    EXPECT_LE(colourDistance(d.at(p.position_m), scaleColour(p.colour_fraction)), kChannelTolerance)
        << p.position_m.transpose();
  }
}

TEST(PositionMap, RowsAreNotFlipped) {
  // +y is up: the marker at y = +0.3 m lands in the image's upper half (rows counted from the top),
  // the one at y = -0.3 m in the lower half; +x is to the right.
  const Drawn d = drawMap({kPotted, kScratch});
  EXPECT_LT(d.pixelAt(kPotted.position_m).y(), kHeight_px / 2);
  EXPECT_GT(d.pixelAt(kScratch.position_m).y(), kHeight_px / 2);
  EXPECT_GT(d.pixelAt(kPotted.position_m).x(), kWidth_px / 2);
  // And the pixel there really is the marker, not its mirror image's.
  const Eigen::Vector2d mirrored(kPotted.position_m.x(), -kPotted.position_m.y());
  EXPECT_GT(colourDistance(d.at(mirrored), scaleColour(kPotted.colour_fraction)), kNotThisColour);
}

TEST(PositionMap, OutcomesHaveTheirShapes) {
  const Drawn d = drawMap({kPotted, kScratch, kMissed});
  const double size_m = markerSize_px(1.0) * d.pixel_m;
  // 0.4 of the size diagonally off the centre: inside a square's fill, outside a disc (0.57 of the
  // size from the centre, the disc's radius is 0.5) and outside a point-up triangle.
  const Eigen::Vector2d corner(0.4 * size_m, 0.4 * size_m);
  EXPECT_LE(colourDistance(d.at(kScratch.position_m + corner), scaleColour(1.0)),
            kChannelTolerance);
  EXPECT_GT(colourDistance(d.at(kPotted.position_m + corner), scaleColour(0.0)), kNotThisColour);
  EXPECT_GT(colourDistance(d.at(kMissed.position_m + corner), scaleColour(0.5)), kNotThisColour);
  // The triangle points up: below the centre it is wide (its base), above it narrow.
  const Eigen::Vector2d low_side(0.25 * size_m, -0.15 * size_m);
  const Eigen::Vector2d high_side(0.25 * size_m, 0.3 * size_m);
  EXPECT_LE(colourDistance(d.at(kMissed.position_m + low_side), scaleColour(0.5)),
            kChannelTolerance);
  EXPECT_GT(colourDistance(d.at(kMissed.position_m + high_side), scaleColour(0.5)), kNotThisColour);
}

TEST(PositionMap, SpreadIsTheOneSigmaEllipseAroundTheMean) {
  MapPoint p{{0.2, -0.2}, MapOutcome::ObjectPocketed, 1.0, 0.0, std::nullopt};
  SpreadEllipse e;
  e.mean_m = {0.0, -0.15};
  e.sd_major_m = 0.2;
  e.sd_minor_m = 0.05;
  e.major_axis_rad = 0;  // along x
  p.spread = e;
  const Drawn d = drawMap({p});
  const Rgba line = scaleColour(1.0);
  EXPECT_LE(colourDistance(d.at(e.mean_m + Eigen::Vector2d(-0.2, 0)), line), kOutlineTolerance);
  EXPECT_LE(colourDistance(d.at(e.mean_m + Eigen::Vector2d(0, 0.05)), line), kOutlineTolerance);
  // Inside and outside it, the cloth.
  EXPECT_GT(colourDistance(d.at(e.mean_m + Eigen::Vector2d(-0.1, 0)), scaleColour(1.0)),
            kNotTheEllipse);
  EXPECT_GT(colourDistance(d.at(e.mean_m + Eigen::Vector2d(0, 0.1)), scaleColour(1.0)),
            kNotTheEllipse);
}

TEST(OverlayItems, EllipsePointsLieOnTheEllipse) {
  const double a = 0.3, b = 0.1, angle = 0.7;
  const Stroke s = ellipseOutline({0.1, -0.2}, a, b, angle, 0.01, Rgba{});
  ASSERT_EQ(s.points_m.size(), static_cast<std::size_t>(kOutlineSegments) + 1);  // closed
  EXPECT_EQ(s.points_m.front(), s.points_m.back());
  for (const Eigen::Vector2d& p : s.points_m) {
    const Eigen::Vector2d q = p - Eigen::Vector2d(0.1, -0.2);
    const double along = q.x() * std::cos(angle) + q.y() * std::sin(angle);
    const double across = -q.x() * std::sin(angle) + q.y() * std::cos(angle);
    EXPECT_NEAR(along * along / (a * a) + across * across / (b * b), 1.0, 1e-12);
  }
}

TEST(OverlayItems, ScaleColourGetsLighterAlongTheScale) {
  const auto luma = [](const Rgba& c) { return 0.2126 * c.r + 0.7152 * c.g + 0.0722 * c.b; };
  double previous = -1;
  for (int k = 0; k <= 20; ++k) {
    const double l = luma(scaleColour(k / 20.0));
    EXPECT_GT(l, previous) << k;
    previous = l;
  }
  EXPECT_EQ(scaleColour(-1), scaleColour(0));  // clamped
  EXPECT_EQ(scaleColour(2), scaleColour(1));
}

}  // namespace
}  // namespace baize::render
