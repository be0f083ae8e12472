#pragma once

// Colour maps from a value in [0, 1] to a colour, for particles coloured by a field.

#include <string>
#include <string_view>
#include <vector>

#include "tide/render/image.hpp"

namespace tide::render {

class Colormap {
 public:
  /// "viridis" or "inferno" (matplotlib's perceptually uniform maps, van der Walt & Smith 2015,
  /// sampled at nine evenly spaced points and interpolated linearly between them) or "gray";
  /// std::invalid_argument listing the names for any other.
  explicit Colormap(std::string_view name);

  /// The colour at t, clamped to [0, 1].
  Colour at(double t) const;

  static std::vector<std::string> names();

 private:
  std::vector<Colour> anchors_;
};

}  // namespace tide::render
