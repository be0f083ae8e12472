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

/// Sampled particles: positions and, index for index, velocities, (fluid only) the material of
/// the block each came from and (walls only) what made it: 0 the container, k + 1 obstacle k.
template <int D>
struct ParticleSamples {
  std::vector<Vector<D>> positions;
  std::vector<Vector<D>> velocities;
  std::vector<std::size_t> materials;
  std::vector<std::size_t> makers;
  std::size_t size() const { return positions.size(); }
};

/// Fluid particles: lattice points inside the fluid blocks, leaving out points inside solid
/// obstacles or outside the container's inner box, with their block's initial velocity and
/// material. Where blocks overlap, the later block takes the point (a droplet listed after the
/// fluid around it replaces that fluid).
template <int D>
ParticleSamples<D> sample_fluid(const scene::Scene& scene);

/// Wall particles: `walls.layers` layers behind each face of the container (up to its rim when
/// the top is open) and inside each obstacle's surface, with the surface velocity of the wall
/// they belong to (zero for the container).
template <int D>
ParticleSamples<D> sample_walls(const scene::Scene& scene);

/// The initial velocity a fluid block gives a particle at x.
template <int D>
Vector<D> initial_velocity(const scene::FluidBlock& block, const Vector<D>& x);

}  // namespace tide
