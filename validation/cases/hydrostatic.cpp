// Hydrostatic tank: water at rest under gravity against p = ρ0 g (H − y).

#include <algorithm>
#include <cmath>

#include "case_support.hpp"

namespace tide::validation {
namespace {

constexpr double gravity = 9.81;
constexpr double rest_density = 1000;

// 2D: 0.5 m deep in a 0.5 m wide tank, settled for 7 s. 3D: 0.2 m deep in a 0.2 m square tank,
// gravity raised over 0.5 s (Adami, Hu & Adams 2012), settled for 2 s. `rows` particles over H.
struct Tank {
  double height;
  double settle_time;
};

Tank tank(int dimension) { return dimension == 2 ? Tank{0.5, 7.0} : Tank{0.2, 2.0}; }

scene::Scene tank_scene(int dimension, int rows, const Variant& variant) {
  const Tank t = tank(dimension);
  const double width = t.height;
  scene::Scene s = water_tank(dimension, width, t.height, 1.5 * t.height, t.height / rows,
                              {"water", rest_density, 1e-6, std::nullopt, std::sqrt(2 * gravity * t.height)}, variant);
  s.source = "hydrostatic tank";
  const int up = dimension - 1;
  const double margin = s.walls.layers * s.particle_spacing;
  s.domain.box = {{-margin, -margin, -margin}, {width + margin, width + margin, width + margin}};
  s.domain.box.max[up] = 3 * t.height;
  if (dimension == 2) s.domain.box.min[2] = s.domain.box.max[2] = 0;
  if (dimension == 3) s.solver.gravity_ramp_time = 0.5;
  return s;
}

template <int D>
RunRecord run_tank(const std::string& name, int rows, const Variant& variant) {
  const Tank t = tank(D);
  const scene::Scene s = tank_scene(D, rows, variant);
  const auto simulation_owner = make_simulation<D>(s);
  Simulation<D>& simulation = *simulation_owner;
  SweepCount sweeps;
  const double wall_seconds = run_until(
      simulation, t.settle_time, [](const Simulation<D>&) {}, &sweeps);

  // Compared where the kernel is complete: deeper than one support below the free surface.
  const double support = kernel_support_factor(s.kernel) * simulation.smoothing_length();
  const auto& fluid = simulation.fluid();
  const auto x = fluid[simulation.fluid_fields().position];
  const auto p = fluid[simulation.fluid_fields().pressure];
  const auto rho = fluid[simulation.fluid_fields().density];
  RelativeL2 pressure_error;
  double density_error = 0;
  for (std::size_t i = 0; i < fluid.size(); ++i) {
    density_error = std::max(density_error, std::abs(rho[i] / rest_density - 1));
    const double depth = t.height - x[i][D - 1];
    if (depth > support) pressure_error.add(p[i], rest_density * gravity * depth);
  }
  return make_record(name, variant, rows, simulation, wall_seconds,
                     {{"pressure_l2_error", pressure_error.value()},
                      {"max_density_error", density_error},
                      {"max_speed_over_sqrt_gH", simulation.max_speed() / std::sqrt(gravity * t.height)},
                      {"sweeps_per_step", sweeps.per_step()}});
}

}  // namespace

Case hydrostatic_case(int dimension) {
  Case c;
  c.name = dimension == 2 ? "hydrostatic_2d" : "hydrostatic_3d";
  c.title = dimension == 2 ? "Hydrostatic tank, 2D" : "Hydrostatic tank, 3D";
  c.reference = "p = ρ0 g (H − y), the hydrostatic pressure of water at rest";
  c.resolution_meaning = "particle rows over the depth H";
  c.metric_notes = {
      "pressure_l2_error: ‖p − ρ0 g (H − y)‖₂ / ‖ρ0 g (H − y)‖₂ over the particles deeper than one kernel support",
      "max_density_error: max |ρ/ρ0 − 1|",
      "max_speed_over_sqrt_gH: the largest particle speed after settling, over sqrt(gH) (at rest: 0)",
      "sweeps_per_step: DFSPH and IISPH: pressure-solve sweeps per step (evaluations of the pressure's velocity and "
      "density error), density and divergence solves together; WCSPH: 0"};
  if (dimension == 2) {
    c.resolutions = {10, 20, 40};
    c.test_resolution = 10;
    c.run = [](int rows, const Variant& variant) { return run_tank<2>("hydrostatic_2d", rows, variant); };
  } else {
    // 16 rows take 4 minutes per variant (2 s of 0.2 m tank, walls 2.4× the fluid): 12 keeps the
    // study within its hour.
    c.resolutions = {8, 12};
    c.test_resolution = 8;
    c.run = [](int rows, const Variant& variant) { return run_tank<3>("hydrostatic_3d", rows, variant); };
  }
  return c;
}

}  // namespace tide::validation
