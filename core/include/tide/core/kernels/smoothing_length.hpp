#pragma once

#include <cmath>
#include <stdexcept>
#include <string>
#include <string_view>

#include "tide/core/types.hpp"

namespace tide::detail {

/// Returns h if it is a usable smoothing length. Kernels check it once at construction so that a
/// bad scene value fails there, by name, rather than as NaN or infinite forces many steps later.
inline Real checked_smoothing_length(Real h, std::string_view kernel) {
  if (!(h > 0) || !std::isfinite(h)) {
    throw std::invalid_argument(std::string(kernel) + ": smoothing length must be positive and finite, got " +
                                std::to_string(h));
  }
  return h;
}

/// coefficient / length^power, evaluated in double and rounded to Real once, so that a float build
/// gets the correctly rounded kernel constant instead of the accumulated error of a float pow().
inline Real coefficient_over_power(double coefficient, Real length, int power) {
  return static_cast<Real>(coefficient / std::pow(static_cast<double>(length), power));
}

}  // namespace tide::detail
