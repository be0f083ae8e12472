#include "tide/render/picture_labels.hpp"

#include <cstdio>

#include "tide/render/bitmap_font.hpp"

namespace tide::render {
namespace {

constexpr Colour ink = {0x20, 0x20, 0x20};
constexpr int text_scale = 2;

std::string number_text(double value, const char* format) {
  char text[40];
  std::snprintf(text, sizeof text, format, value);
  return text;
}

}  // namespace

void draw_time_stamp(Image& image, double time) {
  draw_text(image, 12, 12, "t = " + number_text(time, "%.3f") + " s", ink, text_scale);
}

void draw_colour_bar(Image& image, const PixelRegion& region, const ColourScale& scale, const std::string& label) {
  for (int y = 0; y < region.height; ++y) {
    const double t = region.height > 1 ? 1.0 - static_cast<double>(y) / (region.height - 1) : 0.5;
    const Colour colour = scale.colormap.at(t);
    for (int x = 0; x < region.width; ++x) image.set(region.left + x, region.top + y, colour);
  }
  const int text_left = region.left + region.width + 6, half_line = text_height(text_scale) / 2;
  const double values[3] = {scale.high, (scale.low + scale.high) / 2, scale.low};
  const int rows[3] = {region.top, region.top + region.height / 2, region.top + region.height - 1};
  for (int k = 0; k < 3; ++k) {
    draw_text(image, text_left, rows[k] - half_line, number_text(values[k], "%.3g"), ink, text_scale);
    for (int x = region.left + region.width; x < text_left - 1; ++x) image.set(x, rows[k], ink);
  }
  draw_text(image, region.left, region.top - text_height(text_scale) - 10, label, ink, text_scale);
}

}  // namespace tide::render
