#pragma once

// The points over which a pressure sensor's sensing face is sampled.

#include <vector>

#include "tide/core/scene.hpp"
#include "tide/core/types.hpp"

namespace tide {

/// Midpoint-rule points of equal area covering the sensing face of `sensor` centred on `centre`:
/// in 2D, m points evenly along the segment of length d perpendicular to the normal; in 3D, the
/// centres of an m × m square lattice over the disc's bounding square that lie in the disc of
/// diameter d, in the plane perpendicular to the normal. m = ⌈d / (Δx/2)⌉: half a particle spacing or finer, well below
/// the kernel's width, over which the interpolated pressure varies.
template <int D>
std::vector<Vector<D>> sensor_footprint(const Vector<D>& centre, const scene::ProbeSensor& sensor, Real spacing);

extern template std::vector<Vector<2>> sensor_footprint<2>(const Vector<2>&, const scene::ProbeSensor&, Real);
extern template std::vector<Vector<3>> sensor_footprint<3>(const Vector<3>&, const scene::ProbeSensor&, Real);

}  // namespace tide
