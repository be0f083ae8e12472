// Extremes: one small dam break (a 0.1 x 0.2 m column) run with each parameter pushed to the
// ends of its range: laminar viscosity over six orders of magnitude (from water to where the
// viscous time-step limit binds), the speed of sound from 5 to 40 times the flow speed, and the
// particle spacing halved and doubled. Each run must stay stable, its compression below the
// water hammer's (see WaterHammer) at the fastest impact a dam break can make, its front at
// Ritter's speed: the laminar runs have no artificial viscosity, so nothing slows or spreads the
// front's impact on the far wall, and at nu <= 1e-3 m2/s their compression comes within 4% of the
// water hammer at the free-fall speed U, once above it (docs/stability.md).

#include <algorithm>

#include "case_support.hpp"

namespace tide::stress {
namespace {

constexpr double column_height = 0.2;
constexpr double base_spacing = 0.01;

double flow_speed() { return std::sqrt(2 * standard_gravity * column_height); }

struct Extreme {
  std::string settings;
  scene::Scene scene;
};

std::vector<Row> run_extreme(const Extreme& extreme, double end_time, bool viscous_limit_must_bind) {
  const double c0 = extreme.scene.materials[0].sound_speed.value_or(10 * flow_speed());
  const WaterHammer hammer =
      water_hammer(dam_break_front_speed(column_height), c0, extreme.scene.solver.tait_exponent, water_density);
  std::vector<Row> rows{{"extremes", extreme.settings, "max_density_error", below(hammer.density_error)}};
  if (viscous_limit_must_bind)
    rows.push_back({"extremes", extreme.settings, "viscous_limited_step_fraction", above(0.9)});
  return measured(std::move(rows), [&](std::vector<Row>& out) {
    Wcsph<2> simulation(extreme.scene);
    double density = 0;
    const RunStats stats = run_until(simulation, end_time, [&](const Wcsph<2>& state) {
      density = std::max(density, max_density_error(state, extreme.scene.solver.density));
    });
    out[0].value = density;
    if (viscous_limit_must_bind) {
      out[1].value = static_cast<double>(stats.limits.counts[static_cast<std::size_t>(TimeStepLimit::viscous)]) /
                     static_cast<double>(stats.limits.total());
    }
    record_run(out, stats);
  });
}

// The laminar model replaces artificial viscosity (solver.viscosity picks one), so at small ν
// nothing captures the water hammer at the far wall: the runs with ν ≤ 1e-4 m²/s are the
// impact without shock capturing, and come closest to its bound.
std::vector<Extreme> viscosities() {
  std::vector<Extreme> runs;
  for (const double nu : {1e-6, 1e-5, 1e-4, 1e-3, 1e-2, 1e-1, 1.0}) {
    scene::Scene s = dam_break_scene("extreme viscosity", base_spacing, column_height);
    s.materials[0].kinematic_viscosity = nu;
    s.solver.viscosity = scene::ViscosityModel::laminar;
    runs.push_back({"laminar viscosity nu = " + format_number(nu) + " m2/s", s});
  }
  return runs;
}

std::vector<Extreme> sound_speeds() {
  std::vector<Extreme> runs;
  for (const double ratio : {5.0, 10.0, 20.0, 40.0}) {
    scene::Scene s = dam_break_scene("extreme sound speed", base_spacing, column_height);
    s.materials[0].max_speed.reset();
    s.materials[0].sound_speed = ratio * flow_speed();
    runs.push_back({"c0 = " + format_number(ratio) + " U", s});
  }
  return runs;
}

std::vector<Extreme> spacings() {
  std::vector<Extreme> runs;
  for (const double factor : {2.0, 1.0, 0.5}) {
    const double spacing = factor * base_spacing;
    runs.push_back(
        {"dx = " + format_number(spacing) + " m", dam_break_scene("extreme spacing", spacing, column_height)});
  }
  return runs;
}

std::vector<Row> run_all(Length length) {
  const double end_time = length == Length::full ? 0.6 : 0.25;
  std::vector<Row> rows;
  const auto add = [&](const std::vector<Row>& more) { rows.insert(rows.end(), more.begin(), more.end()); };
  const std::vector<Extreme> viscous = viscosities();
  for (std::size_t k = 0; k < viscous.size(); ++k) add(run_extreme(viscous[k], end_time, k + 1 == viscous.size()));
  for (const Extreme& run : sound_speeds()) add(run_extreme(run, end_time, false));
  for (const Extreme& run : spacings()) add(run_extreme(run, end_time, false));
  return rows;
}

}  // namespace

Case extremes_case() {
  Case c;
  c.name = "extremes";
  c.title = "dam break with viscosity over six decades, c0 from 5 to 40 U, spacing halved and doubled";
  c.metric_note =
      "max_density_error: max (ρ/ρ0 − 1) over every step, bounded by the water hammer's U_f/(U_s − U_f) "
      "at Ritter's front speed U_f = 2 sqrt(g H) (U_s = c0 + 2 U_f, c0 = 10 sqrt(2 g H) unless set); "
      "viscous_limited_step_fraction: the share of steps the viscous limit set, for the most viscous run (the limit "
      "binds above nu = h c0 / 2)";
  c.run = run_all;
  return c;
}

}  // namespace tide::stress
