#include "render/png_writer.h"

#include <png.h>

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <stdexcept>

#include "render/gl_renderer.h"
#include "engine/io/whole_file.h"

namespace baize::render {
namespace {

// libpng reports errors by longjmp; this turns them into a message the caller rethrows.
void onPngError(png_structp png, png_const_charp message) {
  auto* text = static_cast<std::string*>(png_get_error_ptr(png));
  *text = message;
  png_longjmp(png, 1);
}
void onPngWarning(png_structp, png_const_charp) {}

// zlib level: 1 (fastest). Pictures are mostly flat areas, which compress well even so.
constexpr int kCompressionLevel = 1;

void appendBytes(png_structp png, png_bytep data, png_size_t length) {
  auto* bytes = static_cast<std::vector<std::uint8_t>*>(png_get_io_ptr(png));
  bytes->insert(bytes->end(), data, data + length);
}
void flushNothing(png_structp) {}

// Encodes the PNG into `bytes`; returns an empty string on success, else libpng's message.
std::string encode(const Image& image, std::vector<std::uint8_t>* bytes) {
  std::string error;
  png_structp png =
      png_create_write_struct(PNG_LIBPNG_VER_STRING, &error, onPngError, onPngWarning);
  if (png == nullptr) return "libpng cannot start";
  png_infop info = png_create_info_struct(png);
  if (info == nullptr) {
    png_destroy_write_struct(&png, nullptr);
    return "libpng cannot start";
  }
  std::vector<png_bytep> rows(static_cast<std::size_t>(image.height_px));
  if (setjmp(png_jmpbuf(png))) {
    png_destroy_write_struct(&png, &info);
    return error.empty() ? "libpng failed" : error;
  }
  png_set_write_fn(png, bytes, appendBytes, flushNothing);
  png_set_compression_level(png, kCompressionLevel);
  png_set_filter(png, PNG_FILTER_TYPE_BASE, PNG_FILTER_UP);
  png_set_IHDR(png, info, static_cast<png_uint_32>(image.width_px),
               static_cast<png_uint_32>(image.height_px), 8, PNG_COLOR_TYPE_RGBA,
               PNG_INTERLACE_NONE, PNG_COMPRESSION_TYPE_DEFAULT, PNG_FILTER_TYPE_DEFAULT);
  for (int y = 0; y < image.height_px; ++y) {
    rows[y] = const_cast<png_bytep>(image.pixel(0, y));  // libpng's API is not const-correct
  }
  png_set_rows(png, info, rows.data());
  png_write_png(png, info, PNG_TRANSFORM_IDENTITY, nullptr);
  png_destroy_write_struct(&png, &info);
  return "";
}

}  // namespace

void writePng(const Image& image, const std::string& path) {
  if (image.width_px <= 0 || image.height_px <= 0 ||
      image.rgba.size() != static_cast<std::size_t>(image.width_px) * image.height_px * 4) {
    throw std::invalid_argument("image of " + std::to_string(image.width_px) + " x " +
                                std::to_string(image.height_px) + " px with " +
                                std::to_string(image.rgba.size()) +
                                " bytes cannot be written: it needs width * height * 4 bytes");
  }
  std::vector<std::uint8_t> bytes;
  const std::string error = encode(image, &bytes);
  if (!error.empty()) throw std::runtime_error("cannot encode '" + path + "': " + error);
  engine::writeWholeFile(bytes, path);
}

Image readPng(const std::string& path) {
  png_image png;
  std::memset(&png, 0, sizeof png);
  png.version = PNG_IMAGE_VERSION;
  if (!png_image_begin_read_from_file(&png, path.c_str())) {
    throw std::runtime_error("cannot read PNG '" + path + "': " + png.message);
  }
  png.format = PNG_FORMAT_RGBA;
  Image image;
  image.width_px = static_cast<int>(png.width);
  image.height_px = static_cast<int>(png.height);
  image.rgba.resize(PNG_IMAGE_SIZE(png));
  if (!png_image_finish_read(&png, nullptr, image.rgba.data(), 0, nullptr)) {
    png_image_free(&png);
    throw std::runtime_error("cannot read PNG '" + path + "': " + png.message);
  }
  return image;
}

}  // namespace baize::render
