#pragma once

// A pseudo-periodic inflow/outflow channel for the tests (inflow_test.cpp,
// thread_determinism_test.cpp).

#include <optional>

#include "tide/core/scene.hpp"

namespace tide::test {

/// A 2D channel of length 1 and gap 0.25 between two no-slip plates (plane obstacles), periodic
/// along x, filled with fluid of density 1, ν = 0.01 and sound speed 10 moving at the inflow
/// speed; domain.inflow = {velocity 1, length 0.15} (6Δx at Δx = 1/40, twice the kernel support).
/// Re = U gap / ν = 25; Mach 0.1.
inline scene::Scene inflow_channel_scene(double spacing) {
  scene::Scene s;
  s.source = "inflow_channel";
  s.particle_spacing = spacing;
  s.kernel = KernelType::wendland_c2;
  s.smoothing_ratio = 1.5;
  s.materials.push_back({"water", 1, 0.01, 10.0, std::nullopt});
  const double length = 1, gap = 0.25;
  s.fluid.push_back({0, scene::Box{{0, 0, 0}, {length, gap, 0}}, scene::Vec{1, 0, 0}});
  s.walls.obstacles.push_back({scene::Plane{{0, 0, 0}, {0, 1, 0}}, {}, std::nullopt, std::nullopt, std::nullopt});
  s.walls.obstacles.push_back({scene::Plane{{0, gap, 0}, {0, -1, 0}}, {}, std::nullopt, std::nullopt, std::nullopt});
  const double thickness = s.walls.layers * spacing;
  s.domain.box = {{0, -thickness, 0}, {length, gap + thickness, 0}};
  s.domain.periodic = {true, false, false};
  s.domain.inflow = scene::Inflow{1.0, 0.15, std::nullopt};
  s.gravity = {0, 0, 0};
  s.solver.equation_of_state = scene::EquationOfState::linear;
  s.solver.viscosity = scene::ViscosityModel::laminar;
  s.solver.clamp_negative_pressure = false;
  s.solver.background_pressure = 10;
  s.time.end = 2;
  return s;
}

}  // namespace tide::test
