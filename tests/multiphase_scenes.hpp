#pragma once

// Small 2D multiphase scenes for the tests (multiphase_test.cpp, thread_determinism_test.cpp).

#include <cmath>
#include <numbers>
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

/// Rayleigh–Taylor instability after PySPH's rayleigh_taylor set-up (refdata/analytic.md,
/// section 8): a closed 1 × 2 box, gravity 1 down, heavy fluid (ρ = 1.8) above the interface
/// y = 1 − 0.15 sin(2πx) and light fluid (ρ = 1) below, ν = Vmax Ly/Re = 2/420 with Vmax = 1 and
/// Re = 420. The heavy fluid is one box per lattice column from the interface up, so the
/// interface is sampled at each column's centre. Sound speeds give both phases the stiffness
/// ρc² = 100 (c = 10 Vmax for the light fluid: Mach 0.1 instead of PySPH's 0.01, a time step ten
/// times longer).
inline scene::Scene rayleigh_taylor_scene(double spacing) {
  scene::Scene s;
  s.source = "rayleigh_taylor";
  s.particle_spacing = spacing;
  s.kernel = KernelType::wendland_c2;
  s.smoothing_ratio = 1.5;
  const double viscosity = 2.0 / 420;
  s.materials.push_back({"heavy", 1.8, viscosity, 10 / std::sqrt(1.8), std::nullopt});
  s.materials.push_back({"light", 1, viscosity, 10.0, std::nullopt});
  s.walls.layers = 3;
  s.walls.container = scene::Container{scene::Box{{0, 0, 0}, {1, 2, 0}}, false};
  s.domain = scene::domain_around(*s.walls.container, s.walls.layers * spacing, 2);
  s.fluid.push_back({1, scene::Box{{0, 0, 0}, {1, 2, 0}}});
  const int columns = static_cast<int>(std::lround(1 / spacing));
  for (int k = 0; k < columns; ++k) {
    const double x = (k + 0.5) * spacing;
    const double interface = 1 - 0.15 * std::sin(2 * std::numbers::pi * x);
    s.fluid.push_back({0, scene::Box{{k * spacing, interface, 0}, {(k + 1) * spacing, 2, 0}}});
  }
  s.gravity = {0, -1, 0};
  s.solver.equation_of_state = scene::EquationOfState::linear;
  s.solver.viscosity = scene::ViscosityModel::laminar;
  s.solver.clamp_negative_pressure = false;
  s.solver.background_pressure = 1;
  s.time.end = 2;
  return s;
}

}  // namespace tide::test
