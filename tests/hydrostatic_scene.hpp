#pragma once

// The hydrostatic tank the WCSPH and probe tests share.

#include <cmath>
#include <optional>

#include "tide/core/scene.hpp"

namespace tide {

inline constexpr double tank_gravity = 9.81;  // m/s²

// A tank of width W (and depth W in 3D) filled to height H, with n particle rows over H, Wendland
// C2 kernel. 2D: summation density, h = 1.7 Δx. 3D: continuity density, h = 1.5 Δx, gravity
// raised over 0.5 s (see Tank3DSettlesToHydrostaticPressure for why).
inline scene::Scene hydrostatic_scene(int dimension, double height, double width, int rows) {
  scene::Scene s;
  s.source = "hydrostatic test";
  s.dimension = dimension;
  s.particle_spacing = height / rows;
  s.kernel = KernelType::wendland_c2;
  s.smoothing_ratio = dimension == 2 ? 1.7 : 1.5;
  s.materials.push_back({"water", 1000, 1e-6, std::nullopt, std::sqrt(2 * tank_gravity * height)});
  const int up = dimension - 1;
  scene::Vec top{width, width, width};
  top[up] = height;
  s.fluid.push_back({0, scene::Box{{0, 0, 0}, top}});
  scene::Vec rim = top;
  rim[up] = 1.5 * height;
  s.walls.container = scene::Container{scene::Box{{0, 0, 0}, rim}, true};
  s.walls.layers = 4;  // cover the kernel support (3.4 and 3 spacings)
  const double margin = s.walls.layers * s.particle_spacing;
  s.domain.box = {{-margin, -margin, -margin}, {width + margin, width + margin, width + margin}};
  s.domain.box.max[up] = 3 * height;
  if (dimension == 2) s.domain.box.min[2] = s.domain.box.max[2] = 0;
  s.gravity = {0, 0, 0};
  s.gravity[up] = -tank_gravity;
  // Stronger artificial viscosity than for flows: it damps the acoustic oscillation of the
  // column started from a uniform lattice, so the tank comes to rest in a few seconds.
  s.solver.alpha = 0.1;
  if (dimension == 3) {
    s.solver.density = scene::DensityMethod::continuity;
    s.solver.delta_sph = 0;
    s.solver.gravity_ramp_time = 0.5;
  }
  return s;
}

}  // namespace tide
