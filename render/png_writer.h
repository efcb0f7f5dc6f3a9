// Writing an Image (render/gl_renderer.h) as an 8-bit RGBA PNG with libpng. The file appears whole
// or not at all: the PNG goes to "<path>.tmp", renamed into place when complete, removed on error.
// No time stamp or other varying chunk is written, so the same image gives the same bytes.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

namespace baize::render {

struct Image;

// Throws std::invalid_argument for an image whose size does not match its bytes and
// std::runtime_error naming the path when the file cannot be written.
void writePng(const Image& image, const std::string& path);

// The image read back from a PNG written by writePng (8-bit RGBA), for tests and tools.
// Throws std::runtime_error naming the path when it cannot be read.
Image readPng(const std::string& path);

}  // namespace baize::render
