// Writing Images (render/gl_renderer.h) as one animated GIF with giflib, frame by frame. Colours are
// mapped to one fixed palette (a 6 x 7 x 6 colour cube, green given the most levels for the
// cloth), each pixel to its nearest level: simple, and the same frames give the same bytes. The
// GIF is built in memory and written whole by finish() (engine/io/whole_file.h): no partial file.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

struct GifFileType;

namespace baize::render {

struct Image;

// The frame rates a GIF can show, frames per second: its delays are whole hundredths of a second.
constexpr double kMaxGifFps = 100;

class GifWriter {
 public:
  // Throws std::invalid_argument for a size that is not positive or fps outside (0, kMaxGifFps].
  GifWriter(int width_px, int height_px, double fps);
  ~GifWriter();
  GifWriter(const GifWriter&) = delete;
  GifWriter& operator=(const GifWriter&) = delete;

  // Throws std::invalid_argument for an image of another size, std::runtime_error when giflib fails.
  void addFrame(const Image& image);
  // Ends the GIF (it loops forever) and writes it to `path`; throws std::runtime_error naming the
  // path when it cannot be written, std::logic_error when no frame was added.
  void finish(const std::string& path);

  int frameCount() const { return frames_; }

 private:
  [[noreturn]] void fail(const std::string& what) const;

  int width_px_;
  int height_px_;
  double fps_;
  int frames_ = 0;
  std::vector<std::uint8_t> bytes_;  // the GIF encoded so far
  GifFileType* gif_ = nullptr;
};

// The palette index of a colour (exposed for tests): the nearest level of each channel.
std::uint8_t gifPaletteIndex(std::uint8_t red, std::uint8_t green, std::uint8_t blue);

}  // namespace baize::render
