#pragma once

// Small 2D multiphase scenes for the tests (multiphase_test.cpp, thread_determinism_test.cpp).

#include <cmath>
#include <optional>
#include <string>

#include "tide/core/scene.hpp"

namespace tide::test {

/// A periodic 1 × 1 box of ambient fluid (density `ambient_density`) holding a drop of fluid of
/// density 1: a ball of `radius`, or with `square` a square of side `radius` · 2, centred.
/// Equal kinematic viscosity ν = 0.05 and sound speed 20 (the PySPH circular and square droplet
/// set-ups of refdata/analytic.md, sections 5–6, at Δx = 1/40); csf tension σ = 1.
inline scene::Scene droplet_scene(double radius, bool square = false, double ambient_density = 1,
                                  double spacing = 1.0 / 40) {
  scene::Scene s;
  s.source = "droplet";
  s.particle_spacing = spacing;
  s.kernel = KernelType::wendland_c2;
  s.smoothing_ratio = 1.5;
  s.materials.push_back({"drop", 1, 0.05, 20.0, std::nullopt});
  s.materials.push_back({"ambient", ambient_density, 0.05, 20.0 * std::sqrt(1 / ambient_density), std::nullopt});
  s.domain.box = {{0, 0, 0}, {1, 1, 0}};
  s.domain.periodic = {true, true, false};
  s.fluid.push_back({1, scene::Box{{0, 0, 0}, {1, 1, 0}}});
  if (square) {
    s.fluid.push_back({0, scene::Box{{0.5 - radius, 0.5 - radius, 0}, {0.5 + radius, 0.5 + radius, 0}}});
  } else {
    s.fluid.push_back({0, scene::Ball{{0.5, 0.5, 0}, radius}});
  }
  s.gravity = {0, 0, 0};
  s.solver.equation_of_state = scene::EquationOfState::linear;
  s.solver.viscosity = scene::ViscosityModel::laminar;
  s.solver.clamp_negative_pressure = false;
  s.solver.background_pressure = 20;
  s.solver.surface_tension = {scene::SurfaceTensionModel::csf, 1.0, 90, 0};
  s.time.end = 1;
  return s;
}

}  // namespace tide::test
