#pragma once

#include <optional>

#include "tide/core/particle_set.hpp"

namespace tide {

/// Handles of the fluid fields the passes of every scheme use.
template <int D>
struct FluidFields {
  VectorField position;
  VectorField velocity;
  VectorField acceleration;  // WCSPH: total; incompressible schemes: the non-pressure part
  ScalarField mass;
  ScalarField density;
  ScalarField pressure;
  ScalarField density_rate;         // continuity density, and the incompressible solves (slot unused otherwise)
  VectorField shift;                // only with particle shifting (slot unused otherwise)
  ScalarField position_divergence;  // only with particle shifting: ∇·r, the free-surface marker
  IndexField phase;                 // only with several fluid materials: the particle's material index
  VectorField colour_gradient;      // only with surface tension csf (∇c) or akinci (the surface normal)
};

/// Handles of the wall-particle fields (Adami, Hu & Adams 2012).
template <int D>
struct WallFields {
  VectorField position;
  std::optional<VectorField> velocity;  // extrapolated fluid velocity mirrored for the no-slip condition:
                                        // only with no-slip walls, the only ones whose velocity a pass reads
  ScalarField mass;
  ScalarField density;
  ScalarField pressure;
  std::optional<VectorField> surface_velocity;  // the wall's own velocity; only when some wall moves
};

}  // namespace tide
