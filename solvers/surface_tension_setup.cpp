#include "surface_tension_setup.hpp"

#include <array>
#include <cmath>
#include <memory>
#include <numbers>
#include <variant>

#include "tide/solvers/time_step.hpp"

namespace tide::setup {

template <int D>
Real pairwise_tension_per_strength(Real spacing, Real support_radius) {
  // φ(r) = ∫_r^R cos(3πρ/(2R)) dρ = −(2R/(3π)) (1 + sin(3πr/(2R))) for a unit-strength force.
  const Real wave = Real(1.5) * std::numbers::pi_v<Real> / support_radius;
  const int reach = static_cast<int>(std::ceil(support_radius / spacing));
  std::array<int, D> k;
  k.fill(-reach);
  Real sum = 0;
  while (true) {
    Real r2 = 0;
    for (int d = 0; d < D; ++d) r2 += Real(k[d] * k[d]) * spacing * spacing;
    const Real r = std::sqrt(r2);
    if (r2 > 0 && r < support_radius) sum += std::abs(Real(k[D - 1])) * spacing * -(1 + std::sin(wave * r)) / wave;
    int d = 0;
    for (; d < D; ++d) {
      if (++k[d] <= reach) break;
      k[d] = -reach;
    }
    if (d == D) break;
  }
  const Real number_density = 1 / std::pow(spacing, Real(D));
  return -number_density / 4 * sum;
}

template <int D>
passes::SurfaceTensionSettings surface_tension_settings(const scene::Scene& scene, const AnyKernel<D>& kernel,
                                                        const Phases* phases, Real rest_density, Real wall_volume) {
  const scene::SurfaceTension& tension = scene.solver.surface_tension;
  passes::SurfaceTensionSettings s;
  s.coefficient = static_cast<Real>(tension.coefficient);
  s.support_radius = std::visit([](const auto& k) { return k.support_radius(); }, kernel);
  s.phase_count = phases ? phases->table.size() : 1;
  const Index first = phases ? static_cast<Index>(phases->first_fluid) : 0;
  s.colour_phase = first;
  const Real h = static_cast<Real>(scene.smoothing_ratio * scene.particle_spacing);
  // Normals weaker than 0.15/h (about a quarter of the peak |∇c| ≈ 0.6/h of a sharp interface
  // with Wendland C2 at h = 1.5 Δx) are left out of the curvature: their direction is set by a
  // few far neighbours. Morris 2000 takes 0.01/h; on the Laplace test (multiphase_test.cpp) the
  // pressure jump is +5.5% at 0.1/h, −1.6% at 0.15/h and −6.8% at 0.2/h for R = 8 Δx.
  s.normal_threshold = Real(0.15) / h;
  s.wall_volume = wall_volume;
  if (phases) {
    for (const Phase& phase : phases->table) s.rest_density.push_back(phase.rest_density);
    s.density_scale = 2 / (phases->lightest_density + phases->densest_density);
  } else {
    s.rest_density.push_back(rest_density);
    s.density_scale = 1 / rest_density;
  }
  // Akinci et al. 2013 give the 3D normalisations 32/(π R^9) and 0.007/R^3.25; in 2D one power of
  // R less keeps the forces per unit mass in the same units.
  const Real radius = s.support_radius;
  s.cohesion_scale = Real(32) / (std::numbers::pi_v<Real> * std::pow(radius, Real(D == 3 ? 9 : 8)));
  s.adhesion_scale = Real(0.007) / std::pow(radius, Real(D == 3 ? 3.25 : 2.25));
  s.adhesion = static_cast<Real>(tension.adhesion);

  // Pairwise strengths from the mean-field tension of pair forces, σ_ab = k (s_aa + s_bb − 2 s_ab)
  // with a void's strengths zero (k: pairwise_tension_per_strength, a free surface being
  // σ = k s), and Young's law cos θ = (σ_bw − σ_aw)/σ_ab for the first fluid a
  // (Tartakovsky & Meakin 2005, Sec. 3). One fluid: s = σ/k and s_aw = s (1 + cos θ)/2.
  // Two fluids: s_aa = s_bb = σ/k and s_ab = s/2 make σ_ab = σ; s_aw − s_bw = s cos θ / 2, with
  // s_aw + s_bw = s. The wall particles continue the fluid's lattice, so the fluid–wall lattice sum
  // is k too; tests/contact_angle_test.cpp finds the energy minimum of lattice-sampled drops within
  // 1° of θ. Both laws hold only contrasts, s_aa + s_bb − 2 s_ab and s_aw − s_bw: lowering every
  // fluid pair's strength by c and every fluid–wall one by c/2 changes neither σ nor θ in a filled
  // domain. Without unlike_attraction c = s/2, the most that leaves no strength negative: s_ab = 0,
  // s_aa = s_bb = s/2 and s_aw, s_bw = s (1 ± cos θ)/4, each fluid meeting the wall by the one-fluid
  // rule. Less like-pair cohesion is less of the lattice stiffness that pins a contact line
  // (docs/multiphase.md, "Contact angle").
  s.pair_strength.assign(s.phase_count * s.phase_count, 0);
  s.wall_strength.assign(s.phase_count, 0);
  if (tension.model == scene::SurfaceTensionModel::pairwise) {
    const Real strength =
        s.coefficient / pairwise_tension_per_strength<D>(static_cast<Real>(scene.particle_spacing), radius);
    const Real cos_angle = static_cast<Real>(std::cos(tension.contact_angle * std::numbers::pi / 180));
    if (!phases) {
      s.pair_strength[0] = strength;
      s.wall_strength[0] = strength * (1 + cos_angle) / 2;
    } else {
      std::size_t second = first;
      for (const scene::FluidBlock& block : scene.fluid)
        if (block.material != first) second = block.material;
      const std::size_t n = s.phase_count;
      const Real common = tension.unlike_attraction ? 0 : strength / 2;
      s.pair_strength[first * n + first] = strength - common;
      s.pair_strength[second * n + second] = strength - common;
      s.pair_strength[first * n + second] = strength / 2 - common;
      s.pair_strength[second * n + first] = strength / 2 - common;
      s.wall_strength[first] = strength * (2 + cos_angle) / 4 - common / 2;
      s.wall_strength[second] = strength * (2 - cos_angle) / 4 - common / 2;
    }
  }
  return s;
}

template <int D>
SchemeSurfaceTension make_surface_tension(const scene::Scene& scene, const AnyKernel<D>& kernel, const Phases* phases,
                                          Real rest_density, Real particle_mass, ParticleSet<D>& fluid,
                                          FluidFields<D>& fields) {
  const scene::SurfaceTensionModel model = scene.solver.surface_tension.model;
  SchemeSurfaceTension tension;
  if (model == scene::SurfaceTensionModel::none) return tension;
  tension.settings = std::make_unique<const passes::SurfaceTensionSettings>(
      surface_tension_settings<D>(scene, kernel, phases, rest_density, particle_mass / rest_density));
  if (model != scene::SurfaceTensionModel::pairwise) fields.colour_gradient = fluid.add_vector("colour_gradient");
  if (model == scene::SurfaceTensionModel::csf || model == scene::SurfaceTensionModel::pairwise) {
    tension.capillary_limit = capillary_time_step(phases ? phases->lightest_density : rest_density,
                                                  static_cast<Real>(scene.smoothing_ratio * scene.particle_spacing),
                                                  tension.settings->coefficient);
  }
  return tension;
}

template Real pairwise_tension_per_strength<2>(Real, Real);
template Real pairwise_tension_per_strength<3>(Real, Real);
template passes::SurfaceTensionSettings surface_tension_settings<2>(const scene::Scene&, const AnyKernel<2>&,
                                                                    const Phases*, Real, Real);
template passes::SurfaceTensionSettings surface_tension_settings<3>(const scene::Scene&, const AnyKernel<3>&,
                                                                    const Phases*, Real, Real);
template SchemeSurfaceTension make_surface_tension<2>(const scene::Scene&, const AnyKernel<2>&, const Phases*, Real,
                                                      Real, ParticleSet<2>&, FluidFields<2>&);
template SchemeSurfaceTension make_surface_tension<3>(const scene::Scene&, const AnyKernel<3>&, const Phases*, Real,
                                                      Real, ParticleSet<3>&, FluidFields<3>&);

}  // namespace tide::setup
