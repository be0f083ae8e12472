#pragma once

#include <vector>

namespace tide {

/// A curve sampled at increasing abscissae (e.g. dam-break front Z against time T).
struct Curve {
  std::vector<double> x;
  std::vector<double> y;

  /// Linear interpolation; clamps outside the sampled range.
  double at(double position) const;
};

struct OffsetFit {
  double offset = 0;              // best start-time offset δT
  double raw_error = 0;           // mean relative error at δT = 0
  double error_after_offset = 0;  // mean relative error at the best δT
};

/// Fits one start-time offset δT between a simulation and an experiment whose clock started
/// late (a dam-break gate takes time to open): minimises the mean over the experimental points
/// with first ≤ T ≤ last of |Z_sim(T − δT) − Z_exp(T)| / Z_exp(T), for δT on a fine grid in
/// [0, max_offset].
OffsetFit fit_start_offset(const Curve& simulated, const Curve& experiment, double first, double last,
                           double max_offset = 0.6);

}  // namespace tide
