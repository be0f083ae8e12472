#include "tide/serve/live_scene.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>

namespace tide::serve {

LiveSettings settings_of(const scene::Scene& scene, std::size_t particles) {
  if (scene.dimension != 2) throw std::invalid_argument(scene.source + ": tide serve shows 2D scenes only");
  if (scene.solver.scheme != scene::Scheme::wcsph && scene.solver.scheme != scene::Scheme::dfsph)
    throw std::invalid_argument(scene.source + ": tide serve runs the wcsph and dfsph schemes only");
  LiveSettings settings;
  settings.particles = particles;
  settings.scheme = scene.solver.scheme;
  settings.surface_tension = scene.solver.surface_tension.model != scene::SurfaceTensionModel::none;
  if (!scene.materials.empty()) settings.kinematic_viscosity = scene.materials.front().kinematic_viscosity;
  settings.gravity = std::hypot(scene.gravity[0], scene.gravity[1]);
  settings.tilt = settings.gravity > 0 ? std::atan2(scene.gravity[0], -scene.gravity[1]) * 180 / std::numbers::pi : 0;
  return settings;
}

scene::Vec gravity_vector(const LiveSettings& settings) {
  const double tilt = settings.tilt * std::numbers::pi / 180;
  return {settings.gravity * std::sin(tilt), -settings.gravity * std::cos(tilt), 0};
}

scene::Scene live_scene(const scene::Scene& base, std::size_t base_particles, const LiveSettings& settings) {
  scene::Scene scene = base;
  // In 2D the particle count goes as 1 / Δx².
  scene.particle_spacing =
      base.particle_spacing * std::sqrt(static_cast<double>(base_particles) / static_cast<double>(settings.particles));
  // Fewer particles make the container's walls thicker: its domain grows to hold them.
  if (scene.walls.container) {
    const scene::Domain needed =
        scene::domain_around(*scene.walls.container, scene.walls.layers * scene.particle_spacing, 2);
    for (int d = 0; d < 2; ++d) {
      scene.domain.box.min[d] = std::min(scene.domain.box.min[d], needed.box.min[d]);
      scene.domain.box.max[d] = std::max(scene.domain.box.max[d], needed.box.max[d]);
    }
  }
  scene.solver.scheme = settings.scheme;
  scene::SurfaceTension& tension = scene.solver.surface_tension;
  if (!settings.surface_tension) {
    tension = {};
  } else if (tension.model == scene::SurfaceTensionModel::none) {
    tension.model = scene::SurfaceTensionModel::akinci;
    tension.coefficient = default_cohesion;
  }
  if (scene.materials.size() == 1) scene.materials.front().kinematic_viscosity = settings.kinematic_viscosity;
  scene.gravity = gravity_vector(settings);
  return scene;
}

}  // namespace tide::serve
