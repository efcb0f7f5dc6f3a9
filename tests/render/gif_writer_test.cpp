// The GIF writer: its palette, its checks, and a file that giflib reads back with the frames,
// size, delays and colours written.
#include "render/gif_writer.h"

#include <gif_lib.h>
#include <gtest/gtest.h>

#include <unistd.h>

#include <cstdlib>
#include <filesystem>
#include <string>

#include "render/gl_renderer.h"

namespace baize::render {
namespace {

Image filled(int width_px, int height_px, std::uint8_t r, std::uint8_t g, std::uint8_t b) {
  Image image;
  image.width_px = width_px;
  image.height_px = height_px;
  for (int i = 0; i < width_px * height_px; ++i) image.rgba.insert(image.rgba.end(), {r, g, b, 255});
  return image;
}

std::string temporaryPath(const std::string& name) {
  return (std::filesystem::temp_directory_path() /
          (name + "-" + std::to_string(::getpid()) + ".gif"))
      .string();
}

TEST(GifPalette, MapsTheCubeCornersToTheirOwnEntriesAndNearColoursTogether) {
  EXPECT_EQ(gifPaletteIndex(0, 0, 0), 0);
  EXPECT_EQ(gifPaletteIndex(255, 255, 255), 6 * 7 * 6 - 1);
  EXPECT_EQ(gifPaletteIndex(10, 120, 60), gifPaletteIndex(12, 118, 61));
  EXPECT_NE(gifPaletteIndex(0, 0, 0), gifPaletteIndex(0, 60, 0));
}

TEST(GifWriter, RefusesBadSizesRatesAndFrames) {
  EXPECT_THROW(GifWriter(0, 10, 30), std::invalid_argument);
  EXPECT_THROW(GifWriter(10, 10, 0), std::invalid_argument);
  EXPECT_THROW(GifWriter(10, 10, kMaxGifFps * 2), std::invalid_argument);
  GifWriter gif(10, 10, 30);
  EXPECT_THROW(gif.addFrame(filled(11, 10, 0, 0, 0)), std::invalid_argument);
  EXPECT_THROW(gif.finish(temporaryPath("empty")), std::logic_error);
}

TEST(GifWriter, GiflibReadsBackTheFramesSizeDelaysAndColours) {
  const std::string path = temporaryPath("three-frames");
  {
    GifWriter gif(8, 4, 30);
    gif.addFrame(filled(8, 4, 0, 102, 51));
    gif.addFrame(filled(8, 4, 255, 255, 255));
    gif.addFrame(filled(8, 4, 0, 0, 0));
    EXPECT_EQ(gif.frameCount(), 3);
    gif.finish(path);
  }
  int error = 0;
  GifFileType* gif = DGifOpenFileName(path.c_str(), &error);
  ASSERT_NE(gif, nullptr) << GifErrorString(error);
  ASSERT_EQ(DGifSlurp(gif), GIF_OK);
  EXPECT_EQ(gif->SWidth, 8);
  EXPECT_EQ(gif->SHeight, 4);
  ASSERT_EQ(gif->ImageCount, 3);
  int total_delay_cs = 0;
  for (int k = 0; k < 3; ++k) {
    GraphicsControlBlock control;
    ASSERT_EQ(DGifSavedExtensionToGCB(gif, k, &control), GIF_OK);
    total_delay_cs += control.DelayTime;
  }
  EXPECT_EQ(total_delay_cs, 10);  // three frames at 30 per second: 0.1 s, kept in real time
  // The white frame is white; the cloth-green frame's colour within one palette step.
  const GifColorType white = gif->SColorMap->Colors[gif->SavedImages[1].RasterBits[0]];
  EXPECT_EQ(white.Red + white.Green + white.Blue, 3 * 255);
  const GifColorType green = gif->SColorMap->Colors[gif->SavedImages[0].RasterBits[0]];
  EXPECT_LE(std::abs(green.Green - 102), 255 / 6 / 2 + 1);
  EXPECT_LE(std::abs(green.Blue - 51), 255 / 5 / 2 + 1);
  DGifCloseFile(gif, &error);
  std::filesystem::remove(path);
}

}  // namespace
}  // namespace baize::render
