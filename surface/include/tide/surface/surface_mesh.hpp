#pragma once

// A closed triangle mesh of a 3D fluid's surface from its particles: the colour field
// (colour_field.hpp) on a sparse grid, cut at half its interior value by marching cubes
// (marching_cases.hpp). For a flat free surface of a particle lattice, reflection about the plane
// halfway between the last particle layer and the first missing one makes the field there half the
// full lattice sum, so the surface lies where the particles' volume Δx^3 each ends.

#include <span>

#include "tide/core/triangle_mesh.hpp"
#include "tide/surface/colour_field.hpp"

namespace tide::surface {

/// The surface c = iso_level of `grid`, which must be zero outside its stored blocks: every edge is
/// shared by exactly two triangles walking it in opposite directions, and normals point out of the
/// region c > iso_level. Vertices are numbered by their grid edge, triangles listed block by block:
/// the mesh is the same for any thread count.
scene::TriangleMesh marching_cubes(const SparseGrid<3>& grid, double iso_level);

/// The fluid surface of particles at `positions` (x, y, z of each in turn): marching_cubes of the
/// colour field at iso_fraction of its interior value.
scene::TriangleMesh reconstruct_surface(std::span<const double> positions, const FieldSettings& settings,
                                        double iso_fraction = 0.5);

}  // namespace tide::surface
