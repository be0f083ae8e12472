#pragma once

// Particles on a lattice filling simple shapes, D coordinates each in turn, for the tests of
// surface reconstruction.

#include <array>
#include <cmath>
#include <vector>

namespace tide::testing_support {

/// Lattice points (i + 1/2) Δx inside a ball of `radius` about the origin, D coordinates each.
template <int D>
std::vector<double> ball_of_particles(double radius, double spacing) {
  std::vector<double> positions;
  const int reach = static_cast<int>(std::ceil(radius / spacing));
  const int side = 2 * reach;
  int cells = 1;
  for (int d = 0; d < D; ++d) cells *= side;
  for (int n = 0; n < cells; ++n) {
    double x[D], squared = 0;
    int rest = n;
    for (int d = 0; d < D; ++d) {
      x[d] = (rest % side - reach + 0.5) * spacing;
      squared += x[d] * x[d];
      rest /= side;
    }
    if (squared < radius * radius) positions.insert(positions.end(), x, x + D);
  }
  return positions;
}

/// Lattice points (i + 1/2) Δx of a box of counts[d] particles along each axis from the origin.
inline std::vector<double> box_of_particles(const std::array<int, 3>& counts, double spacing) {
  std::vector<double> positions;
  for (int z = 0; z < counts[2]; ++z)
    for (int y = 0; y < counts[1]; ++y)
      for (int x = 0; x < counts[0]; ++x)
        positions.insert(positions.end(), {(x + 0.5) * spacing, (y + 0.5) * spacing, (z + 0.5) * spacing});
  return positions;
}

}  // namespace tide::testing_support
