#include "render/gif_writer.h"

#include <gif_lib.h>

#include <cmath>
#include <stdexcept>

#include "render/gl_renderer.h"
#include "engine/io/whole_file.h"

namespace baize::render {
namespace {

// Levels per channel of the fixed palette: 6 * 7 * 6 = 252 of the 256 entries a GIF has.
constexpr int kRedLevels = 6;
constexpr int kGreenLevels = 7;
constexpr int kBlueLevels = 6;
constexpr int kPaletteSize = 256;
constexpr int kColourResolutionBits = 8;
constexpr int kCentisecondsPerSecond = 100;
// The Netscape application extension: loop count 0 plays the animation forever.
constexpr char kLoopExtensionId[] = "NETSCAPE2.0";
constexpr std::uint8_t kLoopForever[] = {1, 0, 0};

int nearestLevel(std::uint8_t value, int levels) {
  return static_cast<int>((value * (levels - 1) + 127) / 255);
}
std::uint8_t levelValue(int level, int levels) {
  return static_cast<std::uint8_t>((level * 255 + (levels - 1) / 2) / (levels - 1));
}

int appendBytes(GifFileType* gif, const GifByteType* data, int length) {
  auto* bytes = static_cast<std::vector<std::uint8_t>*>(gif->UserData);
  bytes->insert(bytes->end(), data, data + length);
  return length;
}

// The hundredths of a second frame k is shown: differences of rounded frame start times, so a rate
// that is no whole number of hundredths (30 fps) keeps real time over the animation.
int delayOfFrame(int k, double fps) {
  const auto start_cs = [fps](int frame) {
    return static_cast<int>(std::lround(frame * kCentisecondsPerSecond / fps));
  };
  return start_cs(k + 1) - start_cs(k);
}

}  // namespace

std::uint8_t gifPaletteIndex(std::uint8_t red, std::uint8_t green, std::uint8_t blue) {
  return static_cast<std::uint8_t>(
      (nearestLevel(red, kRedLevels) * kGreenLevels + nearestLevel(green, kGreenLevels)) *
          kBlueLevels +
      nearestLevel(blue, kBlueLevels));
}

GifWriter::GifWriter(int width_px, int height_px, double fps)
    : width_px_(width_px), height_px_(height_px), fps_(fps) {
  if (width_px <= 0 || height_px <= 0 || width_px > 65535 || height_px > 65535) {
    throw std::invalid_argument("a GIF of " + std::to_string(width_px) + " x " +
                                std::to_string(height_px) + " px cannot be written");
  }
  if (!(fps > 0 && fps <= kMaxGifFps)) {
    throw std::invalid_argument("a GIF cannot show " + std::to_string(fps) + " frames a second");
  }
  int error = 0;
  gif_ = EGifOpen(&bytes_, appendBytes, &error);
  if (gif_ == nullptr) throw std::runtime_error(std::string("giflib: ") + GifErrorString(error));
  EGifSetGifVersion(gif_, true);
  ColorMapObject* palette = GifMakeMapObject(kPaletteSize, nullptr);
  if (palette == nullptr) fail("no memory for the palette");
  for (int r = 0; r < kRedLevels; ++r) {
    for (int g = 0; g < kGreenLevels; ++g) {
      for (int b = 0; b < kBlueLevels; ++b) {
        GifColorType& colour = palette->Colors[(r * kGreenLevels + g) * kBlueLevels + b];
        colour = {levelValue(r, kRedLevels), levelValue(g, kGreenLevels),
                  levelValue(b, kBlueLevels)};
      }
    }
  }
  const int status =
      EGifPutScreenDesc(gif_, width_px, height_px, kColourResolutionBits, 0, palette);
  GifFreeMapObject(palette);
  if (status != GIF_OK) fail("cannot write the screen descriptor");
  if (EGifPutExtensionLeader(gif_, APPLICATION_EXT_FUNC_CODE) != GIF_OK ||
      EGifPutExtensionBlock(gif_, sizeof kLoopExtensionId - 1, kLoopExtensionId) != GIF_OK ||
      EGifPutExtensionBlock(gif_, sizeof kLoopForever, kLoopForever) != GIF_OK ||
      EGifPutExtensionTrailer(gif_) != GIF_OK) {
    fail("cannot write the loop extension");
  }
}

GifWriter::~GifWriter() {
  if (gif_ != nullptr) EGifCloseFile(gif_, nullptr);
}

void GifWriter::fail(const std::string& what) const {
  const int code = gif_ != nullptr ? gif_->Error : 0;
  throw std::runtime_error("GIF: " + what + (code != 0 ? std::string(": ") + GifErrorString(code)
                                                       : std::string()));
}

void GifWriter::addFrame(const Image& image) {
  if (image.width_px != width_px_ || image.height_px != height_px_) {
    throw std::invalid_argument("a frame of " + std::to_string(image.width_px) + " x " +
                                std::to_string(image.height_px) + " px in a GIF of " +
                                std::to_string(width_px_) + " x " + std::to_string(height_px_));
  }
  GraphicsControlBlock control{};
  control.DisposalMode = DISPOSE_DO_NOT;  // each frame covers the whole picture
  control.DelayTime = delayOfFrame(frames_, fps_);
  control.TransparentColor = NO_TRANSPARENT_COLOR;
  GifByteType extension[4];
  const size_t length = EGifGCBToExtension(&control, extension);
  if (EGifPutExtension(gif_, GRAPHICS_EXT_FUNC_CODE, static_cast<int>(length), extension) !=
          GIF_OK ||
      EGifPutImageDesc(gif_, 0, 0, width_px_, height_px_, false, nullptr) != GIF_OK) {
    fail("cannot start frame " + std::to_string(frames_));
  }
  std::vector<GifPixelType> row(static_cast<std::size_t>(width_px_));
  for (int y = 0; y < height_px_; ++y) {
    for (int x = 0; x < width_px_; ++x) {
      const std::uint8_t* p = image.pixel(x, y);
      row[x] = gifPaletteIndex(p[0], p[1], p[2]);
    }
    if (EGifPutLine(gif_, row.data(), width_px_) != GIF_OK) {
      fail("cannot write frame " + std::to_string(frames_));
    }
  }
  ++frames_;
}

void GifWriter::finish(const std::string& path) {
  if (frames_ == 0) throw std::logic_error("a GIF needs at least one frame");
  int error = 0;
  const int status = EGifCloseFile(gif_, &error);
  gif_ = nullptr;
  if (status != GIF_OK) throw std::runtime_error(std::string("GIF: ") + GifErrorString(error));
  engine::writeWholeFile(bytes_, path);
}

}  // namespace baize::render
