// Violent impact: water thrown against walls, where WCSPH meets its largest pressures and
// speeds. Each scene is held to the bounds of the water hammer at its impact speed U (see
// WaterHammer): the pressure and compression of fluid stopped by a wall at once, the worst an
// impact can do, and the speed that pressure can throw a free surface to. U is the free fall from
// the highest fluid to the floor, or the jet's speed. Artificial viscosity α = 0.1 in all three:
// the water hammer is a shock.

#include <algorithm>

#include "case_support.hpp"

namespace tide::stress {
namespace {

struct Impact {
  std::string settings;
  scene::Scene scene;
  double speed;  // U, m/s
  double end_time;
};

std::vector<Row> run_impact(const Impact& impact) {
  const double c0 = 10 * impact.speed;  // the scenes set max_speed = U
  const WaterHammer hammer = water_hammer(impact.speed, c0, impact.scene.solver.tait_exponent, water_density);
  std::vector<Row> rows{
      {"violent_impact", impact.settings, "max_speed_over_U", below(hammer.speed / impact.speed)},
      {"violent_impact", impact.settings, "max_pressure_over_rho0_c0_U",
       below(hammer.pressure / (water_density * c0 * impact.speed))},
      {"violent_impact", impact.settings, "max_density_error", below(hammer.density_error)},
  };
  return measured(std::move(rows), [&](std::vector<Row>& out) {
    Wcsph<2> simulation(impact.scene);
    double speed = 0, pressure = 0, density = 0;
    const RunStats stats = run_until(simulation, impact.end_time, [&](const Wcsph<2>& state) {
      speed = std::max(speed, static_cast<double>(state.max_speed()));
      pressure = std::max(pressure, max_pressure(state));
      density = std::max(density, max_density_error(state, impact.scene.solver.density));
    });
    out[0].value = speed / impact.speed;
    out[1].value = pressure / (water_density * c0 * impact.speed);
    out[2].value = density;
    out[0].note = std::to_string(simulation.removed_total()) + " particles splashed out of the domain";
    record_run(out, stats);
  });
}

// Martin & Moyce's column (a = H/2) released in a tank 4a wide, with a low block on the floor
// that the front hits before it climbs the opposite wall (Koshizuka & Oka 1996 set an obstacle
// this way).
Impact dam_break(Length length) {
  constexpr double height = 0.4;
  const double spacing = length == Length::full ? 0.005 : 0.02;
  const double speed = std::sqrt(2 * standard_gravity * height);
  scene::Scene s = dam_break_scene("dam break with obstacle", spacing, height);
  s.walls.obstacles.push_back({scene::Box{{0.6, 0, 0}, {0.64, 0.08, 0}}, {}, std::nullopt, std::nullopt, std::nullopt});
  const double end_time = length == Length::full ? 1.5 : 0.8;
  return {"dam break 0.2 x 0.4 m onto a 0.04 x 0.08 m block and the far wall, dx = " + format_number(spacing) +
              " m, t = " + format_number(end_time) + " s",
          s, speed, end_time};
}

// A disc of water falling 0.16 m into a pool, hitting its surface at about 1.8 m/s.
Impact drop(Length length) {
  constexpr double width = 0.4, pool = 0.1, radius = 0.04, centre = 0.3;
  const double spacing = length == Length::full ? 0.004 : 0.01;
  const double speed = std::sqrt(2 * standard_gravity * (centre + radius));
  scene::Scene s = container_scene("drop into a pool", spacing, width, width, speed);
  s.fluid.push_back({0, scene::Box{{0, 0, 0}, {width, pool, 0}}});
  s.fluid.push_back({0, scene::Ball{{width / 2, centre, 0}, radius}});
  s.solver.alpha = 0.1;
  const double end_time = length == Length::full ? 0.5 : 0.35;
  return {"drop r = 0.04 m from 0.3 m into a 0.1 m pool, dx = " + format_number(spacing) +
              " m, t = " + format_number(end_time) + " s",
          s, speed, end_time};
}

// A slug of water shot at 10 m/s along the floor into the far wall, without gravity: its flat
// front meets the wall all at once, the textbook water hammer.
Impact jet(Length length) {
  constexpr double speed = 10, width = 0.4;
  const double spacing = length == Length::full ? 0.0025 : 0.005;
  scene::Scene s = container_scene("jet against a wall", spacing, width, 0.2, speed);
  s.gravity = {0, 0, 0};
  s.fluid.push_back({0, scene::Box{{0.05, 0, 0}, {0.15, 0.05, 0}}, scene::Vec{speed, 0, 0}});
  s.solver.alpha = 0.1;
  const double end_time = 0.06;  // 0.025 s to the wall, then the splash up the wall
  return {"slug 0.1 x 0.05 m at 10 m/s into a wall, no gravity, dx = " + format_number(spacing) +
              " m, t = " + format_number(end_time) + " s",
          s, speed, end_time};
}

}  // namespace

Case violent_impact_case() {
  Case c;
  c.name = "violent_impact";
  c.title = "dam break onto an obstacle, drop into a pool, jet against a wall";
  c.metric_note =
      "over every step of the run, against the water hammer at the impact speed U (free fall from the initial "
      "height, or the jet's speed; c0 = 10 U, shock speed U_s = c0 + 2 U for Tait γ = 7): max_speed_over_U, the "
      "largest particle speed, bounded by sqrt(2 U_s U); max_pressure_over_rho0_c0_U, the largest pressure, "
      "bounded by ρ0 U_s U; max_density_error, max (ρ/ρ0 − 1), bounded by U/(U_s − U)";
  c.run = [](Length length) {
    std::vector<Row> rows;
    for (const Impact& impact : {dam_break(length), drop(length), jet(length)}) {
      for (Row& row : run_impact(impact)) rows.push_back(std::move(row));
    }
    return rows;
  };
  return c;
}

}  // namespace tide::stress
