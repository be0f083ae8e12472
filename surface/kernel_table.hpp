#pragma once

// V W(r) of the colour field's kernel tabulated against r², so that a grid point's share of a
// particle costs a multiply, two loads and an interpolation instead of a square root and the
// kernel's pieces (the colour field's inner loop, colour_field.cpp). Linear interpolation in r² on
// `intervals` equal steps of the support's square: the error is largest in the first step, where
// W's r³ term is (r²)^(3/2). Measured for the cubic spline with 2048 steps (2·10^7 points): at most
// 9.6e-6 of W(0), at r² = 2e-4 of the support's square, and 1.3e-6 of W(0) beyond its first 1%.

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <vector>

namespace tide::surface {

class KernelTable {
 public:
  /// `value(r)` is V W(r), zero from `support` on.
  template <class Value>
  KernelTable(const Value& value, double support, std::size_t intervals = 2048)
      : support_squared_(support * support),
        steps_per_unit_(static_cast<double>(intervals) / support_squared_),
        last_step_(static_cast<double>(intervals)) {
    // Every r² from the support's square on must reach the last step, where the table is zero.
    while (support_squared_ * steps_per_unit_ < last_step_)
      steps_per_unit_ = std::nextafter(steps_per_unit_, 2 * steps_per_unit_);
    // W at the support's end is zero, and one zero beyond it for the interpolation from there.
    values_.resize(intervals + 2, 0.0);
    for (std::size_t k = 0; k < intervals; ++k) values_[k] = value(std::sqrt(static_cast<double>(k) / steps_per_unit_));
  }

  double support_squared() const { return support_squared_; }
  double steps_per_unit() const { return steps_per_unit_; }
  double last_step() const { return last_step_; }
  const double* values() const { return values_.data(); }

  /// V W(r) for r² = `distance_squared` ≥ 0: exactly zero from the support on.
  double operator()(double distance_squared) const {
    const double step = std::min(distance_squared * steps_per_unit_, last_step_);
    const auto k = static_cast<int>(step);
    const double low = values_[static_cast<std::size_t>(k)];
    return low + (step - static_cast<double>(k)) * (values_[static_cast<std::size_t>(k) + 1] - low);
  }

 private:
  double support_squared_;
  double steps_per_unit_;
  double last_step_;
  std::vector<double> values_;
};

}  // namespace tide::surface
