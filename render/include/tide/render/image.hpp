#pragma once

// An 8-bit RGB picture in memory, row 0 at the top: what the renderers draw into and png_file.hpp
// writes.

#include <array>
#include <cstddef>
#include <cstdint>
#include <vector>

namespace tide::render {

using Colour = std::array<std::uint8_t, 3>;

struct Image {
  Image(int width, int height, Colour background)
      : width(width),
        height(height),
        pixels(static_cast<std::size_t>(width) * static_cast<std::size_t>(height), background) {}

  bool contains(int x, int y) const { return x >= 0 && y >= 0 && x < width && y < height; }
  Colour& at(int x, int y) {
    return pixels[static_cast<std::size_t>(y) * static_cast<std::size_t>(width) + static_cast<std::size_t>(x)];
  }
  const Colour& at(int x, int y) const {
    return pixels[static_cast<std::size_t>(y) * static_cast<std::size_t>(width) + static_cast<std::size_t>(x)];
  }
  /// Sets the pixel if it lies in the picture.
  void set(int x, int y, Colour colour) {
    if (contains(x, y)) at(x, y) = colour;
  }

  int width;
  int height;
  std::vector<Colour> pixels;
};

}  // namespace tide::render
