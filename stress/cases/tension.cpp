// Tension: the rotating square patch (Colagrossi 2005; Le Touzé et al. 2013), a free square of
// fluid spun at ω, u = −ω (y − y_c), v = ω (x − x_c). The centripetal acceleration needs
// p = p_c + ½ ρ ω² r² with p = 0 at the surface, so the inside of the patch is in tension, which
// standard SPH cannot hold: the pressure force turns attractive and particles clump in pairs
// (Swegle, Hicks & Attaway 1995). Run without and with artificial stress (Monaghan 2000).

#include <algorithm>

#include "case_support.hpp"

namespace tide::stress {
namespace {

constexpr double side = 1;       // L, m
constexpr double spin = 1;       // ω, rad/s
constexpr double epsilon = 0.2;  // Monaghan 2000's ε for fluids
constexpr double close_fraction_bound = 0.01;
// Measured in the core, the central disc of radius 0.35 L, at least two kernel supports inside
// the surface: fluid that stays in the patch while its corners stretch into thin arms, whose
// one-sided surface layers are a free-surface matter, not the bulk's tension (the whole-patch
// figures go into the note).
constexpr double core_radius = 0.35 * side;

scene::Scene patch_scene(int particles_across, double artificial_stress) {
  scene::Scene s;
  s.source = "rotating square patch";
  s.dimension = 2;
  s.particle_spacing = side / particles_across;
  // Monaghan 2000's kernel and smoothing length: the cubic spline at h = 1.3 Δx. (With Wendland C2
  // at h = 1.7 Δx, W(r)/W(Δx) grows so slowly that (W/W(Δx))^4 outweighs 1/ε = 5 only below
  // 0.5 Δx: ε = 0.2 then leaves 3.5% of the core paired, against 12% without.)
  s.kernel = KernelType::cubic_spline;
  s.smoothing_ratio = 1.3;
  // c0 = 10 × the corner speed ω L/√2.
  s.materials.push_back({"water", water_density, 0, std::nullopt, spin * side / std::sqrt(2.0)});
  s.fluid.push_back(
      {0, scene::Box{{-side / 2, -side / 2, 0}, {side / 2, side / 2, 0}}, scene::RigidRotation{{0, 0, 0}, spin}});
  s.walls.layers = 0;
  s.domain.box = {{-2 * side, -2 * side, 0}, {2 * side, 2 * side, 0}};
  s.gravity = {0, 0, 0};
  s.solver.density = scene::DensityMethod::continuity;
  s.solver.clamp_negative_pressure = false;  // the case is about tension
  s.solver.artificial_stress = artificial_stress;
  return s;
}

std::vector<Row> run_patch(Length length, double artificial_stress) {
  const int particles_across = length == Length::full ? 50 : 30;
  const double end_time = length == Length::full ? 2.0 : 1.5;
  const bool with_stress = artificial_stress > 0;
  Row row{
      "tension",
      std::string(with_stress ? "artificial stress ε = " + format_number(artificial_stress) : "no artificial stress") +
          ", " + std::to_string(particles_across) + " particles across, t = " + format_number(end_time) + " s",
      "close_pair_fraction", below(close_fraction_bound), with_stress};
  return measured({row}, [&](std::vector<Row>& rows) {
    const scene::Scene s = patch_scene(particles_across, artificial_stress);
    Wcsph<2> simulation(s);
    double core = 0, whole = 0, nearest = std::numeric_limits<double>::infinity();
    const RunStats stats = run_until(simulation, end_time, [&](const Wcsph<2>& state) {
      if (state.step_count() % 20 != 0) return;
      const Pairing in_core = pairing(state, s.particle_spacing, core_radius);
      const Pairing everywhere = pairing(state, s.particle_spacing, std::numeric_limits<double>::infinity());
      core = std::max(core, in_core.close_fraction);
      whole = std::max(whole, everywhere.close_fraction);
      nearest = std::min(nearest, everywhere.min_distance);
    });
    rows[0].value = core;
    rows[0].note = "whole patch: close pair fraction up to " + format_number(whole) + ", min pair distance " +
                   format_number(nearest) + " dx";
    record_run(rows, stats);
  });
}

}  // namespace

Case tension_case() {
  Case c;
  c.name = "tension";
  c.title = "rotating square patch (negative pressure inside), without and with artificial stress";
  c.metric_note =
      "close_pair_fraction: the largest fraction, over the run (every 20 steps), of particles whose nearest "
      "neighbour is nearer than 0.5 dx; a regular distribution has none, tensile clumping pairs particles up";
  c.run = [](Length length) {
    std::vector<Row> rows = run_patch(length, 0);
    for (Row& row : run_patch(length, epsilon)) rows.push_back(std::move(row));
    return rows;
  };
  return c;
}

}  // namespace tide::stress
