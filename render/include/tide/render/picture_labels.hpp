#pragma once

// What a rendered frame says besides its particles: the simulated time and a colour bar with the
// field's name and its range.

#include <string>

#include "tide/render/camera.hpp"
#include "tide/render/image.hpp"
#include "tide/render/particle_splats.hpp"

namespace tide::render {

/// "t = 0.25 s" in the top-left corner.
void draw_time_stamp(Image& image, double time);

/// A vertical bar filling `region` from scale.low (bottom) to scale.high (top), labelled with the
/// two ends and the middle value at its right and `label` above it.
void draw_colour_bar(Image& image, const PixelRegion& region, const ColourScale& scale, const std::string& label);

}  // namespace tide::render
