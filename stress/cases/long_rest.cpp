// Long rest: a 2D tank of water at rest under gravity, run for 50 s of simulated time (thousands
// of acoustic periods). A scheme that leaks energy into particle noise, loses particles through a
// wall or lets its density drift shows it here, where a short validation run would not.

#include <algorithm>

#include "case_support.hpp"

namespace tide::stress {
namespace {

constexpr double depth = 0.1;  // H, m
constexpr int rows_over_depth = 10;

std::vector<Row> run_tank(Length length) {
  const double end_time = length == Length::full ? 50 : 5;
  const std::string settings = "H = " + format_number(depth) + " m, " + std::to_string(rows_over_depth) +
                               " rows, summation density, alpha = 0.1, t = " + format_number(end_time) + " s";
  const double free_fall_energy = standard_gravity * depth;  // g H, J/kg
  // At rest means speeds below 1e-3 sqrt(g H), the bound of the hydrostatic tests: a kinetic
  // energy per unit mass of at most ½ 1e-6 g H.
  std::vector<Row> rows{
      {"long_rest", settings, "kinetic_energy_over_mgH", below(0.5e-6)},
      {"long_rest", settings, "escaped_particles", below(0.5)},
      {"long_rest", settings, "max_density_error", below(0.01)},
  };
  return measured(std::move(rows), [&](std::vector<Row>& out) {
    scene::Scene s = container_scene("long rest tank", depth / rows_over_depth, depth, 1.5 * depth,
                                     std::sqrt(2 * standard_gravity * depth));
    s.fluid.push_back({0, scene::Box{{0, 0, 0}, {depth, depth, 0}}});
    s.solver.alpha = 0.1;  // damps the start-up oscillation, as in the hydrostatic validation case
    Wcsph<2> simulation(s);
    double mass = 0;
    for (const Real m : simulation.fluid()[simulation.fluid_fields().mass]) mass += m;
    double density_error = 0;
    const RunStats stats = run_until(simulation, end_time, [&](const Wcsph<2>& state) {
      if (state.step_count() % 100 == 0)
        density_error = std::max(density_error, max_density_error(state, s.solver.density));
    });
    // A particle has escaped when it left the domain or stands above the water (more than a
    // spacing over H: the surface layer may rise by a fraction of a spacing as the column settles).
    std::size_t escaped = simulation.removed_total();
    const auto x = simulation.fluid()[simulation.fluid_fields().position];
    for (std::size_t i = 0; i < simulation.fluid().size(); ++i)
      if (x[i][1] > depth + s.particle_spacing) ++escaped;
    out[0].value = kinetic_energy(simulation) / (mass * free_fall_energy);
    out[1].value = static_cast<double>(escaped);
    out[2].value = std::max(density_error, max_density_error(simulation, s.solver.density));
    out[0].note = "max speed " + format_number(simulation.max_speed()) + " m/s at the end";
    record_run(out, stats);
  });
}

}  // namespace

Case long_rest_case() {
  Case c;
  c.name = "long_rest";
  c.title = "2D hydrostatic tank at rest for 50 s";
  c.metric_note =
      "kinetic_energy_over_mgH: Σ ½ m v² / (M g H) at the end (at rest: speeds below 1e-3 sqrt(gH)); "
      "escaped_particles: particles removed from the domain or standing more than a spacing above the water; "
      "max_density_error: max |ρ/ρ0 − 1| over the run (sampled every 100 steps)";
  c.run = run_tank;
  return c;
}

}  // namespace tide::stress
