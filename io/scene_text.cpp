#include "scene_text.hpp"

#include <array>
#include <cstdio>

namespace tide::io {

std::string format_number(double value) {
  std::array<char, 32> buffer{};
  std::snprintf(buffer.data(), buffer.size(), "%g", value);
  return buffer.data();
}

std::string format_vector(const scene::Vec& v, int dimension) {
  std::string text = "[";
  for (int d = 0; d < dimension; ++d) text += (d > 0 ? ", " : "") + format_number(v[d]);
  return text + "]";
}

std::string format_box(const scene::Box& box, int dimension) {
  std::string text;
  for (int d = 0; d < dimension; ++d) {
    text += (d > 0 ? " x [" : "[") + format_number(box.min[d]) + ", " + format_number(box.max[d]) + "]";
  }
  return text;
}

std::string format_shape(const std::variant<scene::Box, scene::Ball>& shape, int dimension) {
  if (const auto* box = std::get_if<scene::Box>(&shape)) return "the box " + format_box(*box, dimension);
  const auto& ball = std::get<scene::Ball>(shape);
  return "the ball of centre " + format_vector(ball.centre, dimension) + " and radius " + format_number(ball.radius);
}

// Built by appending: GCC 12 warns falsely (-Wrestrict) on "[" + std::to_string(d).
std::string axis_index(int d) {
  std::string text = "[";
  text += std::to_string(d);
  text += ']';
  return text;
}

}  // namespace tide::io
