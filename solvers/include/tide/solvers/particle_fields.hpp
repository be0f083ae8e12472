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
  std::optional<ScalarField> density_rate;         // continuity density, and the incompressible solves
  std::optional<VectorField> shift;                // particle shifting
  std::optional<ScalarField> position_divergence;  // particle shifting: ∇·r, the free-surface marker
  std::optional<IndexField> phase;                 // several fluid materials: the particle's material index
  std::optional<VectorField> colour_gradient;      // surface tension csf (∇c) or akinci (the surface normal)
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
  std::optional<VectorField> acceleration;      // only walls with a prescribed motion (MovingWalls)
};

}  // namespace tide
