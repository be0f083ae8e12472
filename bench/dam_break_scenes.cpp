#include "dam_break_scenes.hpp"

#include <cmath>
#include <optional>
#include <string>

namespace tide::bench {

scene::Scene dam_break(int dimension, double k, double spacing_3d, scene::Scheme scheme) {
  scene::Scene s;
  s.source = "step_bench dam break " + std::to_string(dimension) + "D";
  s.dimension = dimension;
  s.walls.slip = scene::WallSlip::free_slip;
  s.solver.alpha = 0.02;
  s.solver.scheme = scheme;
  s.solver.max_density_error = 0.0005;
  scene::Vec tank{};
  if (dimension == 2) {
    const double a = 0.05715;
    s.particle_spacing = a / k;
    s.kernel = KernelType::wendland_c2;
    s.smoothing_ratio = 1.3;
    s.walls.layers = 3;
    s.materials.push_back({"water", 1000, 1e-6, std::nullopt, 1.5});
    s.fluid.push_back({0, scene::Box{{0, 0, 0}, {a, 2 * a, 0}}});
    tank = {5 * a, 3 * a, 0};
    s.gravity = {0, -9.81, 0};
  } else {
    s.particle_spacing = spacing_3d;
    s.kernel = KernelType::cubic_spline;
    s.smoothing_ratio = 1.0;
    s.walls.layers = 2;
    s.materials.push_back({"water", 1000, 1e-6, std::nullopt, 4.5});
    const double side = k * spacing_3d;
    s.fluid.push_back({0, scene::Box{{0, 0, 0}, {side, side, side}}});
    tank = {4, 1.5, 3};
    s.gravity = {0, 0, -9.81};
  }
  s.walls.container = scene::Container{scene::Box{{0, 0, 0}, tank}, true};
  const double wall = s.walls.layers * s.particle_spacing;
  for (int d = 0; d < dimension; ++d) {
    s.domain.box.min[d] = -wall;
    s.domain.box.max[d] = tank[d] + wall;
  }
  s.domain.box.max[dimension - 1] += tank[dimension - 1];
  return s;
}

scene::Scene sized_dam_break(int dimension, std::size_t n, scene::Scheme scheme) {
  if (dimension == 2) return dam_break(2, std::round(std::sqrt(double(n) / 2)), 0, scheme);
  const double k = std::round(std::cbrt(double(n)));
  return dam_break(3, k, 1.0 / k, scheme);
}

scene::Scene reference_3d(scene::Scheme scheme) { return dam_break(3, 39, 0.025, scheme); }

}  // namespace tide::bench
