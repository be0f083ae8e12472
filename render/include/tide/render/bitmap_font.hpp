#pragma once

// A 5 x 7 pixel font for the labels of rendered frames (time stamp, colour bar): digits, letters
// (capitals drawn as small letters), space and . , - + = _ : / ( ) | %.

#include <string_view>

#include "tide/render/image.hpp"

namespace tide::render {

/// Width in pixels of `text` drawn at `scale` (each font pixel a scale x scale square).
int text_width(std::string_view text, int scale);

/// Height in pixels of a line at `scale`.
int text_height(int scale);

/// Draws `text` with its top-left corner at (x, y); a character the font lacks is drawn as a box.
void draw_text(Image& image, int x, int y, std::string_view text, Colour colour, int scale);

}  // namespace tide::render
