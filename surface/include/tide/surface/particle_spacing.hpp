#pragma once

// The particle spacing Δx of a frame, which the frame files do not store: the median distance
// from a particle to its nearest neighbour, exactly Δx on the lattice a run starts from and
// within the compression of a weakly compressible fluid (about 1%) later.

#include <span>

namespace tide::surface {

/// Median nearest-neighbour distance of the particles at `positions` (D coordinates each);
/// std::invalid_argument for fewer than two particles or all particles at one place.
template <int D>
double median_neighbour_distance(std::span<const double> positions);

}  // namespace tide::surface
