// Time step: a 2D tank of water at rest (0.2 m deep, 20 rows, summation density) run with the
// acoustic CFL number from its default (0.25) to past the limit where kick-drift-kick steps of
// the stiff pressure waves become unstable. Unstable steps make acoustic noise grow until the
// force limit, which shrinks the step as accelerations grow, holds it at a noisy level (density
// errors of 7–20% instead of 1%): the run does not blow up into NaNs, it quietly goes wrong.
// The density band catches it: at rest, Mach 0.1 WCSPH keeps |ρ/ρ0 − 1| near 1%, so these runs
// set solver.max_density_ratio = 1.05, and an unstable time step must stop the run with a report
// that names solver.cfl and the time step as the likely cause; a stable one must not.

#include <algorithm>
#include <chrono>

#include "case_support.hpp"

namespace tide::stress {
namespace {

constexpr double depth = 0.2;
constexpr double spacing = 0.01;
constexpr double density_band = 1.05;

// Measured: the tank stays at rest up to cfl = 1.5 and is reported from cfl = 2 on.
constexpr double stable_in_this_tank = 1.5;

Row run_cfl(double cfl, double end_time) {
  const bool stable = cfl <= stable_in_this_tank;
  Row row{"time_step",
          "cfl = " + format_number(cfl) + ", tank at rest H = 0.2 m, density band " + format_number(density_band) +
              ", t = " + format_number(end_time) + " s",
          "reported_naming_time_step", stable ? below(0.5) : above(0.5)};
  scene::Scene s = container_scene("cfl stress", spacing, depth, 1.5 * depth, std::sqrt(2 * standard_gravity * depth));
  s.fluid.push_back({0, scene::Box{{0, 0, 0}, {depth, depth, 0}}});
  s.solver.cfl = cfl;
  s.solver.max_density_ratio = density_band;
  Wcsph<2> simulation(s);
  double density = 0;
  const auto start = std::chrono::steady_clock::now();
  try {
    const RunStats stats = run_until(simulation, end_time, [&](const Wcsph<2>& state) {
      density = std::max(density, max_density_error(state, s.solver.density));
    });
    row.note = "no report; max density error " + format_number(density) + ", time step: " + stats.limits_text();
  } catch (const InstabilityError& error) {
    // Above max_stable_cfl the report must name the cfl and the time step as the likely cause.
    const std::string message = error.what();
    const bool names_cfl = message.find("solver.cfl = " + format_number(cfl)) != std::string::npos;
    const bool names_cause = message.find("the time step is the likely cause") != std::string::npos;
    row.value = names_cfl && (cfl <= max_stable_cfl || names_cause) ? 1 : 0;
    row.note = message;
  }
  row.simulated_seconds = simulation.time();
  row.wall_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return row;
}

}  // namespace

Case time_step_case() {
  Case c;
  c.name = "time_step";
  c.title = "tank at rest with the acoustic CFL number from 0.25 to past the stable limit";
  c.metric_note =
      "reported_naming_time_step: 1 when the run stopped with an InstabilityError naming solver.cfl (and, above "
      "cfl " +
      format_number(max_stable_cfl) +
      ", the time step as the likely cause), 0 when it ran to its end; stable up to cfl 1.5, reported from 2";
  c.run = [](Length length) {
    const double end_time = length == Length::full ? 2.0 : 0.5;
    std::vector<Row> rows;
    for (const double cfl : {0.25, 1.0, 1.5, 2.0, 3.0, 4.0}) rows.push_back(run_cfl(cfl, end_time));
    return rows;
  };
  return c;
}

}  // namespace tide::stress
