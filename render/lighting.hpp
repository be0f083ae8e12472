#pragma once

// The one light of rendered 3D frames: from the upper left, somewhat behind the viewer, in picture
// axes (right, up, towards the viewer), with an ambient term so that faces turned away stay seen.

#include <algorithm>
#include <cmath>

#include "tide/render/camera.hpp"
#include "tide/render/image.hpp"

namespace tide::render {

inline constexpr Point3 light_direction = {-0.4558, 0.5698, 0.6838};  // unit length
inline constexpr double ambient_light = 0.35;

/// `colour` lit by Lambert's cosine law: ambient + (1 − ambient) · max(0, cosine).
inline Colour lit(Colour colour, double cosine) {
  const double brightness = ambient_light + (1 - ambient_light) * std::max(0.0, cosine);
  Colour result{};
  for (int c = 0; c < 3; ++c)
    result[c] = static_cast<std::uint8_t>(std::lround(std::min(255.0, colour[c] * brightness)));
  return result;
}

}  // namespace tide::render
