#pragma once

// Small 2D multiphase scenes for the tests (multiphase_test.cpp, thread_determinism_test.cpp).

#include <cmath>
#include <numbers>
#include <optional>
#include <string>
#include <utility>

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

/// Two fluids (materials 0 and 1, given) filling a closed 1 × 2 box of walls, the whole box first
/// with `ambient`; linear equation of state, laminar viscosity, tension allowed (no clamp).
inline scene::Scene closed_box_scene(const char* source, double spacing, scene::Material first, scene::Material second,
                                     std::size_t ambient, double end) {
  scene::Scene s;
  s.source = source;
  s.particle_spacing = spacing;
  s.kernel = KernelType::wendland_c2;
  s.smoothing_ratio = 1.5;
  s.materials = {std::move(first), std::move(second)};
  s.walls.layers = 3;
  s.walls.container = scene::Container{scene::Box{{0, 0, 0}, {1, 2, 0}}, false};
  s.domain = scene::domain_around(*s.walls.container, s.walls.layers * spacing, 2);
  s.fluid.push_back({ambient, scene::Box{{0, 0, 0}, {1, 2, 0}}});
  s.solver.equation_of_state = scene::EquationOfState::linear;
  s.solver.viscosity = scene::ViscosityModel::laminar;
  s.solver.clamp_negative_pressure = false;
  s.time.end = end;
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
  const double viscosity = 2.0 / 420;
  scene::Scene s =
      closed_box_scene("rayleigh_taylor", spacing, {"heavy", 1.8, viscosity, 10 / std::sqrt(1.8), std::nullopt},
                       {"light", 1, viscosity, 10.0, std::nullopt}, 1, 2);
  const int columns = static_cast<int>(std::lround(1 / spacing));
  for (int k = 0; k < columns; ++k) {
    const double x = (k + 0.5) * spacing;
    const double interface = 1 - 0.15 * std::sin(2 * std::numbers::pi * x);
    s.fluid.push_back({0, scene::Box{{k * spacing, interface, 0}, {(k + 1) * spacing, 2, 0}}});
  }
  s.gravity = {0, -1, 0};
  s.solver.background_pressure = 1;
  return s;
}

/// The second rising-bubble case of Hysing et al. 2009 (Int. J. Numer. Meth. Fluids 60:1259): a
/// bubble of air (ρ = 1, μ = 0.1) of radius 0.25 at (0.5, 0.5) in water (ρ = 1000, μ = 10) in a
/// closed 1 × 2 box, g = 0.98, σ = 1.96 (csf). Sound speeds give both phases ρc² = 25000
/// (water at c = 5, 20 times the expected rise speed 0.25), with a background pressure of 1000
/// and gravity ramped over 0.1 s, so the column settles without a pressure wave.
inline scene::Scene rising_bubble_scene(double spacing) {
  scene::Scene s = closed_box_scene("rising_bubble", spacing, {"water", 1000, 0.01, 5.0, std::nullopt},
                                    {"air", 1, 0.1, 5.0 * std::sqrt(1000.0), std::nullopt}, 0, 1);
  s.fluid.push_back({1, scene::Ball{{0.5, 0.5, 0}, 0.25}});
  s.gravity = {0, -0.98, 0};
  s.solver.background_pressure = 1000;
  s.solver.gravity_ramp_time = 0.1;
  s.solver.surface_tension = {scene::SurfaceTensionModel::csf, 1.96, 90, 0};
  return s;
}

}  // namespace tide::test
