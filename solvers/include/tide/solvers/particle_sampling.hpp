#pragma once

#include <vector>

#include "tide/core/scene.hpp"
#include "tide/core/types.hpp"

namespace tide {

/// Converts a scene vector to a D-dimensional one (2D scenes use the first two numbers).
template <int D>
Vector<D> to_vector(const scene::Vec& v) {
  Vector<D> result;
  for (int d = 0; d < D; ++d) result[d] = static_cast<Real>(v[d]);
  return result;
}

/// Every particle sits at the centre of a lattice cell of side `particle_spacing` anchored at
/// the container's inner corner (or the domain's corner without container), so fluid and wall
/// particles are one spacing apart across a wall.
template <int D>
Vector<D> lattice_anchor(const scene::Scene& scene);

/// Fluid particle positions: lattice points inside the fluid blocks, leaving out points inside
/// solid obstacles or outside the container's inner box.
template <int D>
std::vector<Vector<D>> sample_fluid(const scene::Scene& scene);

/// Wall particle positions: `walls.layers` layers behind each face of the container (up to its
/// rim when the top is open) and inside each obstacle's surface.
template <int D>
std::vector<Vector<D>> sample_walls(const scene::Scene& scene);

}  // namespace tide
