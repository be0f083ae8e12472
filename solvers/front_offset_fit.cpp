#include "tide/solvers/front_offset_fit.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace tide {

double Curve::at(double position) const {
  if (x.empty() || x.size() != y.size()) throw std::invalid_argument("curve: no samples, or x and y differ in length");
  if (position <= x.front()) return y.front();
  if (position >= x.back()) return y.back();
  const auto upper = std::upper_bound(x.begin(), x.end(), position);
  const std::size_t k = static_cast<std::size_t>(upper - x.begin());
  const double weight = (position - x[k - 1]) / (x[k] - x[k - 1]);
  return y[k - 1] + weight * (y[k] - y[k - 1]);
}

OffsetFit fit_start_offset(const Curve& simulated, const Curve& experiment, double first, double last,
                           double max_offset) {
  auto mean_error = [&](double offset) {
    double sum = 0;
    int count = 0;
    for (std::size_t k = 0; k < experiment.x.size(); ++k) {
      if (experiment.x[k] < first || experiment.x[k] > last) continue;
      sum += std::abs(simulated.at(experiment.x[k] - offset) - experiment.y[k]) / experiment.y[k];
      ++count;
    }
    if (count == 0) throw std::invalid_argument("offset fit: no experimental point in the compared range");
    return sum / count;
  };
  OffsetFit fit{0, mean_error(0), mean_error(0)};
  constexpr int samples = 600;
  for (int k = 1; k <= samples; ++k) {
    const double offset = max_offset * k / samples;
    const double error = mean_error(offset);
    if (error < fit.error_after_offset) {
      fit.offset = offset;
      fit.error_after_offset = error;
    }
  }
  return fit;
}

}  // namespace tide
