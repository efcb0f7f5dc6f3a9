#include "render/png_writer.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <iterator>
#include <stdexcept>

#include "render/gl_renderer.h"

namespace baize::render {
namespace {

std::filesystem::path freshFolder(const std::string& name) {
  const std::filesystem::path folder =
      std::filesystem::temp_directory_path() /
      ("baize-png-test-" + name + "-" + std::to_string(::getpid()));
  std::filesystem::remove_all(folder);
  std::filesystem::create_directories(folder);
  return folder;
}

std::string bytesOf(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

Image gradient(int w, int h) {
  Image image{w, h, std::vector<std::uint8_t>(static_cast<std::size_t>(w) * h * 4)};
  for (int y = 0; y < h; ++y) {
    for (int x = 0; x < w; ++x) {
      std::uint8_t* p = image.rgba.data() + (static_cast<std::size_t>(y) * w + x) * 4;
      p[0] = static_cast<std::uint8_t>(x * 7);
      p[1] = static_cast<std::uint8_t>(y * 13);
      p[2] = static_cast<std::uint8_t>(x ^ y);
      p[3] = 255;
    }
  }
  return image;
}

TEST(PngWriter, WritesWhatItReadsBackTopRowFirstAndLeavesNoTemporary) {
  const std::filesystem::path folder = freshFolder("roundtrip");
  const Image image = gradient(37, 23);
  writePng(image, (folder / "a.png").string());
  const Image back = readPng((folder / "a.png").string());
  EXPECT_EQ(back.width_px, 37);
  EXPECT_EQ(back.height_px, 23);
  EXPECT_TRUE(back.rgba == image.rgba);
  EXPECT_EQ(back.pixel(0, 22)[1], static_cast<std::uint8_t>(22 * 13));  // last row stays last
  EXPECT_FALSE(std::filesystem::exists(folder / "a.png.tmp"));
  std::filesystem::remove_all(folder);
}

TEST(PngWriter, SameImageGivesTheSameBytes) {
  const std::filesystem::path folder = freshFolder("bytes");
  writePng(gradient(50, 40), (folder / "a.png").string());
  writePng(gradient(50, 40), (folder / "b.png").string());
  EXPECT_EQ(bytesOf(folder / "a.png"), bytesOf(folder / "b.png"));
  std::filesystem::remove_all(folder);
}

TEST(PngWriter, UnwritablePathThrowsAndLeavesNothing) {
  const std::filesystem::path folder = freshFolder("unwritable");
  const std::filesystem::path path = folder / "no-such-folder" / "a.png";
  EXPECT_THROW(writePng(gradient(8, 8), path.string()), std::runtime_error);
  EXPECT_FALSE(std::filesystem::exists(path));
  EXPECT_FALSE(std::filesystem::exists(folder / "no-such-folder"));
  std::filesystem::remove_all(folder);
}

TEST(PngWriter, ImageWhoseBytesDoNotMatchItsSizeIsRefusedBeforeWriting) {
  const std::filesystem::path folder = freshFolder("mismatch");
  Image image = gradient(8, 8);
  image.rgba.pop_back();
  EXPECT_THROW(writePng(image, (folder / "a.png").string()), std::invalid_argument);
  EXPECT_TRUE(std::filesystem::is_empty(folder));
  std::filesystem::remove_all(folder);
}

}  // namespace
}  // namespace baize::render
