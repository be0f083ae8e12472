// A cylinder settling at low Reynolds number midway between two walls, against Faxén's
// wall-corrected Stokes drag.

#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>

#include "case_support.hpp"

namespace tide::validation {
namespace {

// A cylinder of radius a = 1 cm, twice the fluid's density, in a closed channel 2l = 16a wide
// (a/l = 1/8) and 0.4 m high, starting 0.1 m below the top; ν = 4e-3 m²/s, so that the flow spreads
// across the channel in l²/ν = 1.6 s, and the Reynolds number U 2a/ν is 0.04.
//
// Gravity is left out and the cylinder pulled down instead by its weight less its buoyancy,
// (ρ_b − ρ) g π a² with g = 1 m/s² (scene::Body::applied_force): in Stokes flow the hydrostatic
// pressure only gives the buoyancy, and without it the sound speed need only keep the flow's own
// pressure (about F/(2a) = 16 Pa across the cylinder) to 0.3% of ρ c0², not a 0.4 m column's
// (docs/bodies.md, "Validation so far"). The channel is closed and full, so the pressure may go
// below zero behind the cylinder (clamp_negative_pressure off).
constexpr double radius = 0.01, half_width = 8 * radius, height = 0.4, start_depth = 0.1;
constexpr double fluid_density = 1000, body_density = 2000, kinematic_viscosity = 4e-3, pull_gravity = 1;
constexpr double sound_speed = 2.5;
// The speed is averaged from 1.5 s, when the flow has spread across the channel and the speed has
// settled within the ±3% of the channel's acoustic sloshing (period 2 × 0.4 m / c0 = 0.32 s), to
// 3.5 s, when the cylinder is still 0.27 m (3.4 l) clear of the floor.
constexpr double average_from = 1.5, end = 3.5;

double pulling_force() { return (body_density - fluid_density) * pull_gravity * std::numbers::pi * radius * radius; }

// Faxén's drag per unit length on a cylinder moving along the centre line between two plane walls
// a distance l from it, in Stokes flow (Faxén 1946, as given by Happel & Brenner 1983, "Low
// Reynolds number hydrodynamics", ch. 7): F = 4π μ U / (ln(l/a) − 0.9157 + 1.7244 k² − 1.7302 k⁴
// + 2.4056 k⁶ − 4.5913 k⁸), k = a/l < 1/2. The channel's net flux is zero, as in a closed one.
double faxen_drag_coefficient(double k) {
  const double k2 = k * k;
  const double series = std::log(1 / k) - 0.9157 + k2 * (1.7244 + k2 * (-1.7302 + k2 * (2.4056 - 4.5913 * k2)));
  return 4 * std::numbers::pi / series;
}

double faxen_speed() {
  const double dynamic_viscosity = fluid_density * kinematic_viscosity;
  return pulling_force() / (faxen_drag_coefficient(radius / half_width) * dynamic_viscosity);
}

scene::Scene settling_cylinder_scene(int across, const Variant& variant) {
  scene::Scene s;
  s.source = "settling cylinder";
  s.dimension = 2;
  s.particle_spacing = 2 * radius / across;
  s.materials.push_back({"fluid", fluid_density, kinematic_viscosity, sound_speed, std::nullopt});
  const double width = 2 * half_width;
  s.fluid.push_back({0, scene::Box{{0, 0, 0}, {width, height, 0}}});
  s.walls.container = scene::Container{scene::Box{{0, 0, 0}, {width, height, 0}}, false};
  scene::Obstacle cylinder;
  cylinder.shape = scene::Ball{{half_width, height - start_depth, 0}, radius};
  cylinder.body = scene::Body{body_density, {}, 0, {0, -pulling_force(), 0}};
  s.walls.obstacles.push_back(cylinder);
  apply_variant(s, variant);
  s.domain = scene::domain_around(*s.walls.container, s.walls.layers * s.particle_spacing, 2);
  s.gravity = {0, 0, 0};
  s.solver.viscosity = scene::ViscosityModel::laminar;
  s.solver.clamp_negative_pressure = false;
  return s;
}

RunRecord run_settling_cylinder(int across, const Variant& variant) {
  const auto simulation_owner = make_simulation<2>(settling_cylinder_scene(across, variant));
  Simulation<2>& simulation = *simulation_owner;
  if (simulation.bodies() == nullptr || simulation.bodies()->size() != 1)
    throw std::runtime_error("settling_cylinder: the scheme did not take the cylinder as a body");
  const RigidBody& cylinder = simulation.bodies()->body(0);
  double previous_time = 0, weighted_speed = 0, averaged_time = 0, sideways = 0;
  const double wall_seconds = run_until(simulation, end, [&](const Simulation<2>& s) {
    const double dt = s.time() - previous_time;
    previous_time = s.time();
    if (s.time() <= average_from) return;
    weighted_speed += -cylinder.velocity().y() * dt;
    averaged_time += dt;
    sideways = std::max(sideways, std::abs(cylinder.centre().x() - half_width));
  });
  const double speed = weighted_speed / averaged_time, expected = faxen_speed();
  return make_record("settling_cylinder", variant, across, simulation, wall_seconds,
                     {{"speed_error", std::abs(speed - expected) / expected},
                      {"speed_over_faxen", speed / expected},
                      {"reynolds_number", speed * 2 * radius / kinematic_viscosity},
                      {"sideways_over_spacing", sideways / simulation.scene().particle_spacing}});
}

}  // namespace

Case settling_cylinder_case() {
  Case c;
  c.name = "settling_cylinder";
  c.title = "Cylinder settling between two walls at low Reynolds number, 2D";
  c.reference =
      "Faxén's Stokes drag on a cylinder midway between two plane walls (Faxén 1946; Happel & Brenner 1983), "
      "a/l = 1/8";
  c.resolution_meaning = "particles across the cylinder's diameter";
  c.metric_notes = {
      "speed_error: |U − U_F| / U_F, U the cylinder's mean settling speed over 1.5-3.5 s, U_F = F / (K μ) with "
      "Faxén's K = 10.56 at a/l = 1/8",
      "speed_over_faxen: U / U_F", "reynolds_number: U 2a / ν",
      "sideways_over_spacing: the centre's largest distance from the channel's middle over 1.5-3.5 s, over Δx"};
  c.schemes = {"wcsph", "wcsph_continuity"};
  c.resolutions = {8, 16};
  c.test_resolution = 8;
  c.run = run_settling_cylinder;
  return c;
}

}  // namespace tide::validation
