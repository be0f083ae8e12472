#pragma once

// The geometry checks of a scene read in full: does it leave the solver something sensible to do,
// and can the machine hold it? Each throws a SceneError at the key path of the first offending
// shape; each is in its own file.

#include "tide/core/scene.hpp"
#include "tide/io/scene_reader.hpp"

namespace tide::io {

/// Slack for comparing coordinates the user wrote as decimals (0.1 + 0.2 is not 0.3).
inline double coordinate_slack(const scene::Scene& scene) { return 1e-9 * scene.particle_spacing; }

/// The container with its wall layers lies inside the domain (up to the rim, for an open top).
void check_container_in_domain(const scene::Scene& scene);

/// Every mesh obstacle's bounding box lies inside the domain.
void check_mesh_placement(const scene::Scene& scene);

/// Every fluid block lies inside the domain and inside the container's inner box.
void check_fluid_placement(const scene::Scene& scene);

/// Every fluid block holds at least one lattice point.
void check_fluid_lattice_points(const scene::Scene& scene);

/// The lattice points the particle sampling visits stay within largest_particle_count()
/// (scene_reader.hpp), per shape
/// and in all; each shape within largest_particle_count() spacings of the lattice anchor.
void check_particle_count(const scene::Scene& scene);

}  // namespace tide::io
