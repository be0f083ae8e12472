#pragma once

// Numbers, vectors and shapes as the scene reader's messages write them.

#include <string>
#include <string_view>
#include <variant>

#include "tide/core/scene.hpp"

namespace tide::io {

/// A number the reader computed (a bound, a derived size): six significant digits are plenty.
std::string format_number(double value);

std::string format_vector(const scene::Vec& v, int dimension);

/// "[x0, x1] x [y0, y1]".
std::string format_box(const scene::Box& box, int dimension);

/// "the box ..." or "the ball of centre ... and radius ...".
std::string format_shape(const std::variant<scene::Box, scene::Ball>& shape, int dimension);

/// "[d]".
std::string axis_index(int d);

/// "\"a\", \"b\", \"c\"".
template <class Names>
std::string quoted_list(const Names& names) {
  std::string text;
  for (const std::string_view name : names) text += (text.empty() ? "\"" : ", \"") + std::string(name) + "\"";
  return text;
}

}  // namespace tide::io
