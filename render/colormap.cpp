#include "tide/render/colormap.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <stdexcept>

namespace tide::render {
namespace {

const std::map<std::string, std::vector<Colour>, std::less<>>& anchor_tables() {
  static const std::map<std::string, std::vector<Colour>, std::less<>> tables = {
      {"viridis",
       {{{0x44, 0x01, 0x54}},
        {{0x47, 0x2d, 0x7b}},
        {{0x3b, 0x52, 0x8b}},
        {{0x2c, 0x72, 0x8e}},
        {{0x21, 0x91, 0x8c}},
        {{0x28, 0xae, 0x80}},
        {{0x5e, 0xc9, 0x62}},
        {{0xad, 0xdc, 0x30}},
        {{0xfd, 0xe7, 0x25}}}},
      {"inferno",
       {{{0x00, 0x00, 0x04}},
        {{0x1f, 0x0c, 0x48}},
        {{0x55, 0x0f, 0x6d}},
        {{0x88, 0x22, 0x6a}},
        {{0xba, 0x36, 0x55}},
        {{0xe3, 0x59, 0x33}},
        {{0xf9, 0x8e, 0x09}},
        {{0xf9, 0xcb, 0x35}},
        {{0xfc, 0xff, 0xa4}}}},
      {"gray", {{{0x00, 0x00, 0x00}}, {{0xff, 0xff, 0xff}}}},
  };
  return tables;
}

}  // namespace

Colormap::Colormap(std::string_view name) {
  const auto found = anchor_tables().find(name);
  if (found == anchor_tables().end()) {
    std::string known;
    for (const std::string& each : names()) known += (known.empty() ? "" : ", ") + each;
    throw std::invalid_argument("unknown colour map '" + std::string(name) + "' (known: " + known + ")");
  }
  anchors_ = found->second;
}

Colour Colormap::at(double t) const {
  const double position = std::clamp(std::isfinite(t) ? t : 0.0, 0.0, 1.0) * static_cast<double>(anchors_.size() - 1);
  const auto below = std::min(static_cast<std::size_t>(position), anchors_.size() - 2);
  const double fraction = position - static_cast<double>(below);
  Colour colour{};
  for (int c = 0; c < 3; ++c)
    colour[c] =
        static_cast<std::uint8_t>(std::lround((1 - fraction) * anchors_[below][c] + fraction * anchors_[below + 1][c]));
  return colour;
}

std::vector<std::string> Colormap::names() {
  std::vector<std::string> result;
  for (const auto& entry : anchor_tables()) result.push_back(entry.first);
  return result;
}

}  // namespace tide::render
