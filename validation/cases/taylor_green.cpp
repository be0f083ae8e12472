// Taylor–Green vortex at Re = 100 in the periodic unit square (U = 1 m/s, L = 1 m, ρ0 = 1):
// the velocity field keeps its shape and decays as exp(b t), b = −8π²/Re (Taylor & Green 1937).

#include <cmath>
#include <numbers>
#include <vector>

#include "case_support.hpp"

namespace tide::validation {
namespace {

constexpr double reynolds = 100;
constexpr double end_time = 1.0;
const double decay_rate = -8 * std::numbers::pi * std::numbers::pi / reynolds;

scene::Scene vortex_scene(int cells, const Variant& variant) {
  scene::Scene s;
  s.source = "taylor-green vortex";
  s.dimension = 2;
  s.particle_spacing = 1.0 / cells;
  s.materials.push_back({"fluid", 1.0, 1.0 / reynolds, std::nullopt, 1.0});  // c0 = 10 U
  s.fluid.push_back({0, scene::Box{{0, 0, 0}, {1, 1, 0}}, scene::TaylorGreenVelocity{1, 1}});
  apply_variant(s, variant);
  s.walls.layers = 0;
  s.gravity = {0, 0, 0};
  s.domain.box = {{0, 0, 0}, {1, 1, 0}};
  s.domain.periodic = {true, true, false};
  s.solver.viscosity = scene::ViscosityModel::laminar;
  s.solver.clamp_negative_pressure = false;
  // Without shifting the particles drift into the vortex's stagnation lines and the pressure
  // noise takes the flow's energy (the error exceeds 90% at t = 1 for every resolution; a
  // background pressure only adds noise to the pressure force). Fickian particle shifting keeps
  // the distribution uniform (Lind et al. 2012; Sun et al. 2017 run this vortex with shifting).
  s.solver.shifting = scene::Shifting::fickian;
  return s;
}

RunRecord run_vortex(int cells, const Variant& variant) {
  const auto simulation_owner = make_simulation<2>(vortex_scene(cells, variant));
  Simulation<2>& simulation = *simulation_owner;
  // Least-squares slope of ln(max speed) against t over the run: the measured decay rate.
  double sum_t = 0, sum_l = 0, sum_tt = 0, sum_tl = 0;
  int samples = 0;
  const auto sample = [&](const Simulation<2>& s) {
    const double t = s.time();
    const double l = std::log(static_cast<double>(s.max_speed()));
    sum_t += t;
    sum_l += l;
    sum_tt += t * t;
    sum_tl += t * l;
    ++samples;
  };
  SweepCount sweeps;
  const double wall_seconds = run_until(simulation, end_time, sample, &sweeps);
  const double slope = (samples * sum_tl - sum_t * sum_l) / (samples * sum_tt - sum_t * sum_t);

  const auto x = simulation.fluid()[simulation.fluid_fields().position];
  const auto v = simulation.fluid()[simulation.fluid_fields().velocity];
  const double amplitude = std::exp(decay_rate * simulation.time());
  const double k = 2 * std::numbers::pi;
  RelativeL2 error;
  for (std::size_t i = 0; i < simulation.fluid().size(); ++i) {
    const double u = -amplitude * std::cos(k * x[i][0]) * std::sin(k * x[i][1]);
    const double w = amplitude * std::sin(k * x[i][0]) * std::cos(k * x[i][1]);
    error.add(v[i][0], u);
    error.add(v[i][1], w);
  }
  return make_record("taylor_green", variant, cells, simulation, wall_seconds,
                     {{"velocity_l2_error", error.value()},
                      {"decay_rate_error", std::abs(slope - decay_rate) / std::abs(decay_rate)},
                      {"sweeps_per_step", sweeps.per_step()}});
}

}  // namespace

Case taylor_green_case() {
  Case c;
  c.name = "taylor_green";
  c.title = "Taylor–Green vortex, Re = 100";
  c.reference = "the exact solution u = −e^{bt} cos 2πx sin 2πy, v = e^{bt} sin 2πx cos 2πy, b = −8π²/Re";
  c.resolution_meaning = "particles across the unit square";
  c.metric_notes = {"velocity_l2_error: ‖v − v_exact‖₂ / ‖v_exact‖₂ over all particles at t = 1 s",
                    "decay_rate_error: |b_measured − b| / |b|, b_measured the least-squares slope of ln(max speed) "
                    "over 0 < t ≤ 1 s",
                    "sweeps_per_step: DFSPH and IISPH: pressure-solve sweeps per step, density and divergence solves "
                    "together; WCSPH: 0"};
  c.resolutions = {25, 50, 100};
  c.test_resolution = 25;
  c.run = run_vortex;
  return c;
}

}  // namespace tide::validation
