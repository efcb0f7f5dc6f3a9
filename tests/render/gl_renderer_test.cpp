#include "render/gl_renderer.h"

#include <gtest/gtest.h>

#include <cmath>
#include <set>

#include "engine/io/scene.h"
#include "render/camera.h"
#include "render/shot_picture.h"
#include "render/table_picture.h"
#include "tests/render/render_test_support.h"

namespace baize::render {
namespace {

const Rgba kDark{0.1f, 0.1f, 0.1f, 1};
const Rgba kRed{0.9f, 0.1f, 0.1f, 1};
const Rgba kYellow{0.95f, 0.85f, 0.1f, 1};

Picture emptyFrame() {
  Picture picture;
  picture.min_corner_m = {-1, -0.5};
  picture.max_corner_m = {1, 0.5};
  picture.background = kDark;
  return picture;
}

Disc flat(const Eigen::Vector2d& at, double radius_m, const Rgba& colour) {
  return Disc{Eigen::Vector3d(at.x(), at.y(), 0), radius_m, colour, DiscStyle::Flat, 0, {}};
}

const std::uint8_t* pixelAt(const Image& image, const Eigen::Vector2d& p) {
  return image.pixel(static_cast<int>(std::floor(p.x())), static_cast<int>(std::floor(p.y())));
}

TEST(GlRenderer, ImageHasTheRequestedSize) {
  GlRenderer& renderer = testRenderer();
  for (const auto& [w, h] : {std::pair{320, 200}, std::pair{97, 61}, std::pair{16, 16}}) {
    const Picture picture = emptyFrame();
    renderer.draw(picture, cameraFor(picture, View::Top, w, h));
    const Image image = renderer.readImage();
    EXPECT_EQ(image.width_px, w);
    EXPECT_EQ(image.height_px, h);
    ASSERT_EQ(image.rgba.size(), static_cast<std::size_t>(w) * h * 4);
    EXPECT_LE(colourDistance(image.pixel(w / 2, h / 2), kDark), kChannelTolerance);
  }
}

TEST(GlRenderer, DiscShowsItsColourAtItsPixelAndNotBeyondIt) {
  Picture picture = emptyFrame();
  const Eigen::Vector2d centre(0.45, -0.2);
  picture.items.push_back(flat(centre, 0.05, kRed));
  const Camera camera = cameraFor(picture, View::Top, 400, 200);  // 200 px per m: radius 10 px
  GlRenderer& renderer = testRenderer();
  renderer.draw(picture, camera);
  const Image image = renderer.readImage();
  const Eigen::Vector2d at = camera.pixelOf({centre.x(), centre.y(), 0});
  EXPECT_NEAR(at.x(), 290, 1e-9);  // (0.45 + 1) * 200
  EXPECT_NEAR(at.y(), 140, 1e-9);  // (0.5 + 0.2) * 200, rows from the top
  EXPECT_LE(colourDistance(image.pixel(290, 140), kRed), kChannelTolerance);
  EXPECT_LE(colourDistance(image.pixel(297, 140), kRed), kChannelTolerance);   // 7 px in
  EXPECT_LE(colourDistance(image.pixel(303, 140), kDark), kChannelTolerance);  // 13 px out
  EXPECT_LE(colourDistance(image.pixel(290, 127), kDark), kChannelTolerance);
}

TEST(GlRenderer, StraightTracePassesThroughTheExpectedPixels) {
  Picture picture = emptyFrame();
  // A horizontal line at y = 0.1 m, 0.015 m (3 px) wide, and a diagonal one.
  picture.items.push_back(Stroke{{{-0.8, 0.1}, {0.8, 0.1}}, 0.015, 0, kYellow});
  picture.items.push_back(Stroke{{{-0.4, -0.4}, {0.4, 0.4}}, 0.015, 0, kRed});
  const Camera camera = cameraFor(picture, View::Top, 400, 200);
  GlRenderer& renderer = testRenderer();
  renderer.draw(picture, camera);
  const Image image = renderer.readImage();
  for (double x = -0.7; x <= 0.7; x += 0.05) {
    if (std::abs(x - 0.1) < 0.03) continue;  // where the lines cross
    const Eigen::Vector2d on = camera.pixelOf({x, 0.1, 0});
    EXPECT_LE(colourDistance(pixelAt(image, on), kYellow), kChannelTolerance) << "x = " << x;
    EXPECT_LE(colourDistance(pixelAt(image, on + Eigen::Vector2d(0, 5)), kDark), kChannelTolerance);
    EXPECT_LE(colourDistance(pixelAt(image, on - Eigen::Vector2d(0, 5)), kDark), kChannelTolerance);
  }
  for (double t = -0.35; t <= 0.35; t += 0.05) {
    if (std::abs(t - 0.1) < 0.03) continue;
    const Eigen::Vector2d on = camera.pixelOf({t, t, 0});
    EXPECT_LE(colourDistance(pixelAt(image, on), kRed), kChannelTolerance) << "t = " << t;
  }
}

TEST(GlRenderer, RowsAreNotFlippedABallNearThePlusYCushionIsNearTheTop) {
  // Found without the camera: the red ball's pixels, wherever they are, must be in the top part.
  ShotRecord shot;
  shot.table = engine::builtinTable("pool-9ft");
  shot.ball_set = engine::builtinBallSet("pool");
  shot.cloth = physics::poolCloth();
  shot.ball_ids = {"3"};
  physics::BallState at_rest;
  at_rest.position = {0.3, shot.table.width_m / 2 - 0.05};
  shot.trajectories = {{engine::TrajectoryPiece{0, at_rest, false}}};
  const Picture picture = buildShotPicture(shot, PictureOptions{});
  GlRenderer& renderer = testRenderer();
  renderer.draw(picture, cameraFor(picture, View::Top, 800, 400));
  const Image image = renderer.readImage();
  double row_sum = 0, column_sum = 0, count = 0;
  for (int y = 0; y < image.height_px; ++y) {
    for (int x = 0; x < image.width_px; ++x) {
      const std::uint8_t* p = image.pixel(x, y);
      if (p[0] > 100 && p[1] < 40 && p[2] < 40) {  // reddish: only the shaded 3 ball
        row_sum += y;
        column_sum += x;
        ++count;
      }
    }
  }
  ASSERT_GT(count, 50);
  EXPECT_LT(row_sum / count, image.height_px / 4.0);
  EXPECT_GT(column_sum / count, image.width_px / 2.0);  // and right of centre (x = +0.3 m)
}

TEST(GlRenderer, ShadedBallIsLitInItsColourAndDarkerTowardsItsEdge) {
  Picture picture = emptyFrame();
  picture.items.push_back(Disc{Eigen::Vector3d(0, 0, 0.05), 0.05, kRed, DiscStyle::Ball, 0, {}});
  const Camera camera = cameraFor(picture, View::Top, 400, 200);
  GlRenderer& renderer = testRenderer();
  renderer.draw(picture, camera);
  const Image image = renderer.readImage();
  const std::uint8_t* middle = image.pixel(200, 100);
  EXPECT_GT(middle[0], 150);  // red dominates where the ball faces the camera
  EXPECT_LT(middle[1], 80);
  EXPECT_LT(middle[2], 80);
  const std::uint8_t* lower_right = image.pixel(207, 107);  // away from the light (upper left)
  EXPECT_LT(lower_right[0], middle[0]);
}

TEST(GlRenderer, LegendPanelHoldsTheSwatchColourAndLightText) {
  Picture picture = emptyFrame();
  picture.background = Rgba{0.2f, 0.5f, 0.8f, 1};  // light enough for the dark panel to show
  picture.legend = {LegendRow{true, kRed, false, "MMMM"}, LegendRow{false, {}, false, "key"}};
  GlRenderer& renderer = testRenderer();
  constexpr int kWidth = 400, kHeight = 400;
  renderer.draw(picture, cameraFor(picture, View::Top, kWidth, kHeight));
  const Image image = renderer.readImage();
  const int text_size = legendTextSize(kHeight);
  // The panel darkens the corner; outside it the background is untouched.
  const std::uint8_t* corner = image.pixel(kLegendMargin_px + 2, kLegendMargin_px + 2);
  EXPECT_LT(corner[2], channel(0.8f) - 60);
  EXPECT_LE(colourDistance(image.pixel(kWidth - 5, kHeight - 5), picture.background),
            kChannelTolerance);
  // Red swatch somewhere in the first row's left part; near-white text ink right of it.
  bool red = false, ink = false;
  for (int y = kLegendMargin_px; y < kLegendMargin_px + 2 * text_size; ++y) {
    for (int x = kLegendMargin_px; x < kLegendMargin_px + 8 * text_size; ++x) {
      const std::uint8_t* p = image.pixel(x, y);
      red = red || (p[0] > 150 && p[1] < 60 && p[2] < 60);
      ink = ink || (p[0] > 200 && p[1] > 200 && p[2] > 200);
    }
  }
  EXPECT_TRUE(red);
  EXPECT_TRUE(ink);
}

TEST(GlRenderer, NumberedBallShowsAWhiteCircleWithDarkDigitsWhenLargeEnough) {
  const Rgba black{0.0f, 0.0f, 0.0f, 1};
  GlRenderer& renderer = testRenderer();
  const auto draw = [&](double radius_m) {
    Picture picture = emptyFrame();
    picture.items.push_back(
        Disc{Eigen::Vector3d(0, 0, radius_m), radius_m, black, DiscStyle::Ball, 0, "8"});
    renderer.draw(picture, cameraFor(picture, View::Top, 400, 200));  // 200 px per m
    return renderer.readImage();
  };
  const auto count = [](const Image& image, bool white) {
    int n = 0;
    for (int y = 0; y < image.height_px; ++y) {
      for (int x = 0; x < image.width_px; ++x) {
        const std::uint8_t* p = image.pixel(x, y);
        n += white ? (p[0] > 230 && p[1] > 230 && p[2] > 230)
                   : (p[0] < 40 && p[1] < 40 && p[2] < 40);
      }
    }
    return n;
  };
  // A 20 px ball: the circle (radius 10 px, about 300 px) minus the digit's ink is white.
  const Image large = draw(0.1);
  EXPECT_GT(count(large, true), 150);
  EXPECT_LT(count(large, true), 330);
  // The digit's dark ink sits inside the circle: the centre row crosses it.
  int dark_in_centre = 0;
  for (int x = 195; x <= 205; ++x) {
    const std::uint8_t* p = large.pixel(x, 100);
    dark_in_centre += p[0] < 100;
  }
  EXPECT_GT(dark_in_centre, 0);
  // A 4 px ball is too small for a number.
  EXPECT_EQ(count(draw(0.02), true), 0);
}

TEST(GlRenderer, WallShowsInTheAngledViewOnlyBelowItsTopEdge) {
  Picture picture = emptyFrame();
  picture.lowest_m = -0.2;
  // The frame's near side, standing from 0.2 m below the cloth to the cloth.
  picture.items.push_back(Wall{{-1, -0.5}, {1, -0.5}, -0.2, 0.0, kYellow});
  GlRenderer& renderer = testRenderer();
  renderer.draw(picture, cameraFor(picture, View::Top, 400, 200));
  const Image top = renderer.readImage();
  for (int y = 0; y < top.height_px; y += 7) {  // seen from straight above it has no area
    for (int x = 0; x < top.width_px; x += 7) {
      ASSERT_LE(colourDistance(top.pixel(x, y), kDark), kChannelTolerance) << x << ", " << y;
    }
  }
  const Camera angled = cameraFor(picture, View::Angled, 400, 200);
  renderer.draw(picture, angled);
  const Image image = renderer.readImage();
  EXPECT_LE(colourDistance(pixelAt(image, angled.pixelOf({0, -0.5, -0.1})), kYellow),
            kChannelTolerance);
  EXPECT_LE(colourDistance(pixelAt(image, angled.pixelOf({0, -0.5, 0.1})), kDark),
            kChannelTolerance);
}

TEST(GlRenderer, SameInputGivesTheSameBytes) {
  const engine::Scene scene =
      engine::loadScene(engine::assetsDirectory() + "/scenes/draw-shot.json");
  const ShotRecord shot = shotRecordOf(scene, engine::runScene(scene, true));
  PictureOptions options;
  options.pixel_size_m = pixelSizeFor(shot.table, 600, 300);
  const Picture picture = buildShotPicture(shot, options);
  GlRenderer& renderer = testRenderer();
  renderer.draw(picture, cameraFor(picture, View::Angled, 600, 300));
  const Image first = renderer.readImage();
  renderer.draw(emptyFrame(), cameraFor(emptyFrame(), View::Top, 200, 100));  // something else
  renderer.draw(picture, cameraFor(picture, View::Angled, 600, 300));
  EXPECT_TRUE(first.rgba == renderer.readImage().rgba);
}

// The shipped break, drawn without traces: every ball left on the table is a blob of its own colour
// at its final position, and there are as many blobs as balls left.
TEST(GlRenderer, NineBallBreakShowsOneBlobPerBallLeftAtItsFinalPosition) {
  const engine::Scene scene =
      engine::loadScene(engine::assetsDirectory() + "/scenes/9-ball-break.json");
  const engine::SceneRun run = engine::runScene(scene, true);
  const ShotRecord shot = shotRecordOf(scene, run);
  constexpr int kWidth = 1600, kHeight = 800;
  PictureOptions options;
  options.traces = false;
  options.pixel_size_m = pixelSizeFor(shot.table, kWidth, kHeight);
  const Picture picture = buildShotPicture(shot, options);
  const Camera camera = cameraFor(picture, View::Top, kWidth, kHeight);
  GlRenderer& renderer = testRenderer();
  renderer.draw(picture, camera);
  const Image image = renderer.readImage();

  const double R = shot.ball_set.radius_m;
  const double radius_px = R / options.pixel_size_m;
  std::vector<std::pair<std::string, Eigen::Vector2d>> left;
  for (std::size_t i = 0; i < run.ball_ids.size(); ++i) {
    if (!run.result.final_balls[i].pocketed) {
      left.push_back({run.ball_ids[i], run.result.final_balls[i].state.position});
    }
  }
  // Precondition of the blob count: no two balls left touch (they would make one blob).
  for (std::size_t i = 0; i < left.size(); ++i) {
    for (std::size_t j = i + 1; j < left.size(); ++j) {
      ASSERT_GT((left[i].second - left[j].second).norm(), 2 * R + 4 * options.pixel_size_m);
    }
  }
  // Each ball's body is nearer its own colour than any other ball's or the cloth's.
  const Rgba cloth = tableColours(shot.table.kind).cloth;
  for (const auto& [id, p] : left) {
    // Three quarters of a radius left of the centre: beside the number's white circle (half a
    // radius), on a striped ball's band, well lit.
    const std::uint8_t* centre = pixelAt(image, camera.pixelOf({p.x() - 0.75 * R, p.y(), 0}));
    const Rgba own = ballColour(shot.ball_set, id);
    const int own_distance = colourDistance(centre, own);
    EXPECT_LT(own_distance, colourDistance(centre, cloth)) << "ball " << id;
    for (const engine::BallSpec& other : shot.ball_set.balls) {
      if (colourFromHex(other.colour) == own) continue;  // 1 and 9 share a colour
      EXPECT_LT(own_distance, colourDistance(centre, colourFromHex(other.colour))) << "ball " << id;
    }
  }
  // Blobs: connected regions of non-cloth pixels inside the cushion noses, at least half a ball.
  const Eigen::Vector2d lo = camera.pixelOf({-shot.table.length_m / 2, shot.table.width_m / 2, 0});
  const Eigen::Vector2d hi = camera.pixelOf({shot.table.length_m / 2, -shot.table.width_m / 2, 0});
  const int x0 = static_cast<int>(lo.x()) + 2, x1 = static_cast<int>(hi.x()) - 2;
  const int y0 = static_cast<int>(lo.y()) + 2, y1 = static_cast<int>(hi.y()) - 2;
  // A pixel more than this from the cloth colour (0-255, any channel) is not cloth: above the
  // cloth's own antialiasing noise, below the gap to any ball colour.
  constexpr int kNotClothDistance = 40;
  std::vector<int> label(static_cast<std::size_t>(kWidth) * kHeight, 0);
  std::vector<Eigen::Vector2d> blob_centres;
  const double min_blob_px = 0.5 * M_PI * radius_px * radius_px;
  for (int y = y0; y < y1; ++y) {
    for (int x = x0; x < x1; ++x) {
      if (label[y * kWidth + x] != 0 ||
          colourDistance(image.pixel(x, y), cloth) <= kNotClothDistance) {
        continue;
      }
      std::vector<std::pair<int, int>> stack{{x, y}};
      label[y * kWidth + x] = 1;
      double sx = 0, sy = 0, n = 0;
      while (!stack.empty()) {
        const auto [cx, cy] = stack.back();
        stack.pop_back();
        sx += cx + 0.5;
        sy += cy + 0.5;
        ++n;
        for (const auto& [dx, dy] :
             {std::pair{1, 0}, std::pair{-1, 0}, std::pair{0, 1}, std::pair{0, -1}}) {
          const int nx = cx + dx, ny = cy + dy;
          if (nx < x0 || nx >= x1 || ny < y0 || ny >= y1 || label[ny * kWidth + nx] != 0) continue;
          if (colourDistance(image.pixel(nx, ny), cloth) <= kNotClothDistance) continue;
          label[ny * kWidth + nx] = 1;
          stack.push_back({nx, ny});
        }
      }
      if (n >= min_blob_px) blob_centres.push_back({sx / n, sy / n});
    }
  }
  EXPECT_EQ(blob_centres.size(), left.size());
  for (const auto& [id, p] : left) {
    const Eigen::Vector2d expected = camera.pixelOf({p.x(), p.y(), 0});
    double nearest = 1e9;
    for (const Eigen::Vector2d& c : blob_centres)
      nearest = std::min(nearest, (c - expected).norm());
    EXPECT_LT(nearest, 1.0) << "ball " << id;  // the blob is centred on the ball, within a pixel
  }
}

}  // namespace
}  // namespace baize::render
