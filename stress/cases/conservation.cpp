// Conservation: the Taylor–Green vortex in the periodic unit square with no viscosity at all
// (artificial viscosity α = 0, no laminar viscosity, no shifting). Summation density with the
// symmetric pressure force is a Hamiltonian particle system (Monaghan 2005, Sec. 3), and
// kick-drift-kick integration is symplectic, so the total energy — kinetic plus the elastic
// energy of the equation of state — must stay at its initial value up to a bounded O(Δt²)
// oscillation, without drift.

#include <algorithm>

#include "case_support.hpp"

namespace tide::stress {
namespace {

constexpr double energy_budget = 1e-3;  // relative: well above the O(Δt²) oscillation, far below a leak

std::vector<Row> run_vortex(Length length) {
  const int cells = length == Length::full ? 50 : 25;
  const double end_time = length == Length::full ? 2.0 : 0.5;
  const std::string settings =
      "Taylor-Green, alpha = 0, " + std::to_string(cells) + " particles across, t = " + format_number(end_time) + " s";
  return measured({{"conservation", settings, "max_relative_energy_change", below(energy_budget)}},
                  [&](std::vector<Row>& out) {
                    scene::Scene s;
                    s.source = "inviscid taylor-green vortex";
                    s.dimension = 2;
                    s.particle_spacing = 1.0 / cells;
                    s.kernel = KernelType::wendland_c2;
                    s.smoothing_ratio = 1.7;
                    s.materials.push_back({"fluid", 1.0, 0, std::nullopt, 1.0});  // U = 1 m/s, c0 = 10 m/s
                    s.fluid.push_back({0, scene::Box{{0, 0, 0}, {1, 1, 0}}, scene::TaylorGreenVelocity{1, 1}});
                    s.walls.layers = 0;
                    s.gravity = {0, 0, 0};
                    s.domain.box = {{0, 0, 0}, {1, 1, 0}};
                    s.domain.periodic = {true, true, false};
                    s.solver.alpha = 0;
                    s.solver.clamp_negative_pressure = false;
                    Wcsph<2> simulation(s);
                    const auto energy = [&](const Wcsph<2>& state) {
                      return kinetic_energy(state) + internal_and_potential_energy(state, s.gravity);
                    };
                    const double initial = energy(simulation);
                    double change = 0;
                    const RunStats stats = run_until(simulation, end_time, [&](const Wcsph<2>& state) {
                      change = std::max(change, std::abs(energy(state) - initial) / initial);
                    });
                    out[0].value = change;
                    out[0].note = "E0 = " + format_number(initial) + " J/m, kinetic share " +
                                  format_number(kinetic_energy(simulation) / initial) + " at the end";
                    record_run(out, stats);
                  });
}

}  // namespace

Case conservation_case() {
  Case c;
  c.name = "conservation";
  c.title = "inviscid Taylor-Green vortex: total energy of a closed periodic flow";
  c.metric_note =
      "max_relative_energy_change: max over every step of |E − E0| / E0, E = Σ m (½ v² + e(ρ)), "
      "e(ρ) = ∫ p/ρ² dρ from ρ0";
  c.run = run_vortex;
  return c;
}

}  // namespace tide::stress
