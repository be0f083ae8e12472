#pragma once

// Reads a PNG back as 8-bit RGB through libpng's simplified API, for the tests of rendering.

#include <png.h>

#include <filesystem>
#include <stdexcept>

#include "tide/render/image.hpp"

namespace tide::testing_support {

inline render::Image read_png(const std::filesystem::path& path) {
  png_image png{};
  png.version = PNG_IMAGE_VERSION;
  if (png_image_begin_read_from_file(&png, path.c_str()) == 0)
    throw std::runtime_error(path.string() + ": " + png.message);
  png.format = PNG_FORMAT_RGB;
  render::Image image(static_cast<int>(png.width), static_cast<int>(png.height), {0, 0, 0});
  if (png_image_finish_read(&png, nullptr, image.pixels.data(), 0, nullptr) == 0)
    throw std::runtime_error(path.string() + ": " + png.message);
  return image;
}

}  // namespace tide::testing_support
