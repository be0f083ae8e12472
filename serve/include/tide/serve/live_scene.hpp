#pragma once

// What the page's controls set, and the scene a new simulation is built from for them: the
// particle count scales the scene's particle spacing, the scheme and surface tension replace the
// scene's, and gravity and viscosity, which a running simulation also takes (Simulation::
// set_gravity, set_kinematic_viscosity), are written into it too.

#include <cstddef>

#include "tide/core/scene.hpp"
#include "tide/serve/command.hpp"

namespace tide::serve {

struct LiveSettings {
  std::size_t particles = 0;  // the fluid particles asked for; the lattice gives about as many
  scene::Scheme scheme = scene::Scheme::dfsph;
  bool surface_tension = false;
  double kinematic_viscosity = 1e-6;  // m²/s
  double gravity = 9.81;              // m/s²
  double tilt = 0;                    // degrees counter-clockwise from straight down
  ColourField colour = ColourField::speed;
  bool paused = false;
};

/// The settings a 2D scene starts with: its particle count `particles`, its scheme, surface
/// tension, first material's kinematic viscosity and gravity. std::invalid_argument for a 3D scene
/// or a scheme other than wcsph and dfsph.
LiveSettings settings_of(const scene::Scene& scene, std::size_t particles);

/// Gravity of the settings as a scene vector.
scene::Vec gravity_vector(const LiveSettings& settings);

/// Akinci's cohesion the surface-tension switch adds to a scene that has none: γ (Akinci et al.
/// 2013) at this value keeps a 2D tank's drops round at the spacings the page offers.
inline constexpr double default_cohesion = 0.1;

/// `base`, which holds `base_particles` fluid particles, changed to `settings`.
scene::Scene live_scene(const scene::Scene& base, std::size_t base_particles, const LiveSettings& settings);

}  // namespace tide::serve
