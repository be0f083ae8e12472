#pragma once

// Acceleration of every fluid particle: pressure, viscosity, artificial stress and body force in
// one gather pass.

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <span>

#include "tide/core/parallel.hpp"
#include "tide/core/scene.hpp"
#include "tide/solvers/fluid_wall_neighbors.hpp"
#include "tide/solvers/particle_fields.hpp"

namespace tide::passes {

struct ViscositySettings {
  scene::ViscosityModel model = scene::ViscosityModel::artificial;
  bool walls_viscous = true;  // false for free-slip walls
  Real alpha = 0;
  Real beta = 0;
  Real sound_speed = 0;
  Real kinematic_viscosity = 0;
  Real smoothing_length = 0;
};

/// The viscosity settings of a scene, with the velocity scale c of the artificial viscosity.
inline ViscositySettings viscosity_settings(const scene::Scene& scene, Real sound_speed, Real kinematic_viscosity,
                                            Real smoothing_length) {
  return {scene.solver.viscosity,
          scene.walls.slip == scene::WallSlip::no_slip,
          static_cast<Real>(scene.solver.alpha),
          static_cast<Real>(scene.solver.beta),
          sound_speed,
          kinematic_viscosity,
          smoothing_length};
}

/// Monaghan's (2000) artificial stress; `epsilon` = 0 compiles the pass without it.
struct ArtificialStressSettings {
  Real epsilon = 0;
  Real inverse_lattice_kernel = 0;  // 1 / W(Δx), the kernel at one particle spacing
};

namespace detail {

// ∇W_ij = F(r) x_ij for every radial kernel: F read through the kernel's own gradient, so a pass
// over arrays of pairs needs no kernel-specific code (the unit vector's zero components fold away).
template <int D, class Kernel>
inline Real gradient_factor(const Kernel& kernel, Real r) {
  return kernel.gradient(Vector<D>::Unit(0), r)[0];
}

// The viscous acceleration on i from one neighbour j is c_∇ ∇W_ij + c_v v_ij; these are c_∇, c_v.
// Artificial: Monaghan 1992, eq. 4.1–4.2: −m_j Π_ij ∇W_ij, Π_ij = (−α c μ + β μ²)/ρ̄_ij when
//   v_ij·x_ij < 0, μ = h v_ij·x_ij / (r² + 0.01 h²). Approaching pairs only, without a branch
//   (v·x < 0 for about half the pairs, unpredictably): a receding pair gets μ = 0 and so Π = 0.
// Laminar: Morris, Fox & Zhu 1997, eq. 8: m_j (μ_i + μ_j) x_ij·∇W_ij / (ρ_i ρ_j (r² + 0.01 h²)) v_ij,
//   with x_ij·∇W_ij = F r² for ∇W_ij = F x_ij.
struct ViscousCoefficients {
  Real along_gradient = 0;
  Real along_v = 0;
};

template <scene::ViscosityModel Model>
inline ViscousCoefficients viscous_coefficients(const ViscositySettings& s, Real m_j, Real rho_i, Real rho_j,
                                                Real v_dot_x, Real r2, Real gradient) {
  const Real h = s.smoothing_length;
  const Real regularised_r2 = r2 + Real(0.01) * h * h;
  if constexpr (Model == scene::ViscosityModel::artificial) {
    const Real mu = h * std::min(v_dot_x, Real(0)) / regularised_r2;
    const Real pi = (-s.alpha * s.sound_speed * mu + s.beta * mu * mu) / (Real(0.5) * (rho_i + rho_j));
    return {-m_j * pi, 0};
  } else {
    const Real dynamic_sum = s.kinematic_viscosity * (rho_i + rho_j);
    return {0, m_j * dynamic_sum * (gradient * r2) / (rho_i * rho_j * regularised_r2)};
  }
}

// A particle's share R_i of the artificial stress: ε |p_i|/ρ_i² where it is in tension (p_i < 0),
// none under compression. Gray, Monaghan & Swift 2001 take R = −ε σ/ρ² from each principal
// stress σ that is tensile (σ > 0); a fluid's stress is −p I, which gives this scalar form.
inline Real artificial_stress_share(Real epsilon, Real p_over_rho2) {
  return p_over_rho2 < 0 ? -epsilon * p_over_rho2 : Real(0);
}

// (W(r)/W(Δx))^4: the artificial stress acts only between particles closer than about the
// initial spacing, and grows fast as they approach (Monaghan 2000, n = 4).
template <class Kernel>
inline Real artificial_stress_weight(const Kernel& kernel, const ArtificialStressSettings& s, Real r) {
  const Real f = kernel.value(r) * s.inverse_lattice_kernel;
  const Real f2 = f * f;
  return f2 * f2;
}

// The particle-i side of the momentum pass and the terms of one batch of neighbours (fluid or
// wall, given as their fields): first every pair's coefficients in a loop without branches, then
// the sums in neighbour order.
template <int D, scene::ViscosityModel Model, bool WithPressure, bool ArtificialStress, class Kernel>
struct MomentumGather {
  const Kernel& kernel;
  const ViscositySettings& settings;
  const ArtificialStressSettings& stress;
  Vector<D> v_i;
  Real rho_i;
  Real p_over_rho2_i;
  Real stress_i;

  // skip: the index of particle i among these neighbours (its self pair), or none. Viscous: with
  // the viscous terms (a template flag, so the loop has no branch to vectorise around).
  template <bool Viscous, class Velocity>
  void add(const NeighborBatch<D>& b, std::span<const Real> mass, std::span<const Real> density,
           std::span<const Real> pressure, const Velocity& v, Index skip, Vector<D>& a) const {
    std::array<Real, batch_size> factor;  // ∇W_ij = F x_ij
    std::array<Real, batch_size> pressure_coefficient;
    std::array<Real, batch_size> along_gradient;
    std::array<Real, batch_size> along_v;
    for (Index k = 0; k < b.count; ++k) {
      const Index j = b.j[k];
      const Real rho_j = density[j];
      const Real r = std::sqrt(b.r2[k]);
      const Real gradient = gradient_factor<D>(kernel, r);
      Real v_dot_x = 0;
      for (int d = 0; d < D; ++d) v_dot_x += (v_i[d] - v.component[d][j]) * b.x[d][k];
      Real p = 0;
      if constexpr (WithPressure) {
        const Real p_over_rho2_j = pressure[j] / (rho_j * rho_j);
        Real term = p_over_rho2_i + p_over_rho2_j;
        if constexpr (ArtificialStress)
          term += (stress_i + artificial_stress_share(stress.epsilon, p_over_rho2_j)) *
                  artificial_stress_weight(kernel, stress, r);
        p = mass[j] * term;
      }
      ViscousCoefficients c;
      if constexpr (Viscous)
        c = viscous_coefficients<Model>(settings, mass[j], rho_i, rho_j, v_dot_x, b.r2[k], gradient);
      const bool counted = j != skip;
      factor[k] = gradient;
      pressure_coefficient[k] = counted ? p : Real(0);
      along_gradient[k] = counted ? c.along_gradient : Real(0);
      along_v[k] = counted ? c.along_v : Real(0);
    }
    // In neighbour order, each term rounded as the per-pair form a −= p ∇W, a += viscous does.
    for (Index k = 0; k < b.count; ++k) {
      for (int d = 0; d < D; ++d) {
        const Real grad_w = factor[k] * b.x[d][k];
        if constexpr (WithPressure) a[d] -= pressure_coefficient[k] * grad_w;
        if constexpr (Viscous) {
          if constexpr (Model == scene::ViscosityModel::artificial) {
            a[d] += along_gradient[k] * grad_w;
          } else {
            a[d] += along_v[k] * (v_i[d] - v.component[d][b.j[k]]);
          }
        }
      }
    }
  }
};

}  // namespace detail

/// a_i = −Σ_j m_j (p_i/ρ_i² + p_j/ρ_j²) ∇W_ij (Monaghan 1992, eq. 3.3) + viscous terms + g,
/// summed over fluid and wall neighbours (walls with their extrapolated p, ρ and velocity).
/// With `ArtificialStress`, each pair's pressure term gains (R_i + R_j) (W_ij/W(Δx))^4, a
/// repulsion between particles in tension that stops them clumping in pairs (Monaghan 2000,
/// J. Comput. Phys. 159, the artificial pressure added to the equation of motion). Without
/// `WithPressure`, the non-pressure part only: what an incompressible scheme integrates before
/// its pressure solve.
template <int D, scene::ViscosityModel Model, bool WithPressure, bool ArtificialStress, class Kernel>
void momentum(const Kernel& kernel, const ViscositySettings& settings, const ArtificialStressSettings& stress,
              ParticleSet<D>& fluid, const FluidFields<D>& f, const FluidWallNeighbors<D>& neighbors,
              const ParticleSet<D>& walls, const WallFields<D>& w, const Vector<D>& gravity) {
  const auto x = std::as_const(fluid)[f.position];
  const auto v = std::as_const(fluid)[f.velocity];
  const auto mass = std::as_const(fluid)[f.mass];
  const auto density = std::as_const(fluid)[f.density];
  const auto pressure = std::as_const(fluid)[f.pressure];
  const auto wall_x = walls[w.position];
  const auto wall_v = walls[w.velocity];
  const auto wall_mass = walls[w.mass];
  const auto wall_density = walls[w.density];
  const auto wall_pressure = walls[w.pressure];
  auto acceleration = fluid[f.acceleration];
  const bool walls_needed = WithPressure || settings.walls_viscous;
  constexpr Index none = std::numeric_limits<Index>::max();
  for_each_particle(fluid.size(), [&](std::size_t i) {
    const Real rho_i = density[i];
    const Real p_over_rho2_i = pressure[i] / (rho_i * rho_i);
    const Real stress_i = ArtificialStress ? detail::artificial_stress_share(stress.epsilon, p_over_rho2_i) : Real(0);
    const detail::MomentumGather<D, Model, WithPressure, ArtificialStress, Kernel> gather{
        kernel, settings, stress, v[i], rho_i, p_over_rho2_i, stress_i};
    Vector<D> a = gravity;
    neighbors.for_each_fluid_batch(i, x, [&](const NeighborBatch<D>& b) {
      gather.template add<true>(b, mass, density, pressure, v, static_cast<Index>(i), a);
    });
    if (walls_needed) {
      neighbors.for_each_wall_batch(i, x, wall_x, [&](const NeighborBatch<D>& b) {
        if (settings.walls_viscous) {
          gather.template add<true>(b, wall_mass, wall_density, wall_pressure, wall_v, none, a);
        } else {
          gather.template add<false>(b, wall_mass, wall_density, wall_pressure, wall_v, none, a);
        }
      });
    }
    acceleration.set(i, a);
  });
}

/// momentum() compiled for the viscosity model of `settings` and for artificial stress on or off,
/// picked once per pass outside the particle loop: a scene without artificial stress runs a pass
/// without it.
template <int D, bool WithPressure = true, class Kernel>
void fluid_acceleration(const Kernel& kernel, const ViscositySettings& settings, const ArtificialStressSettings& stress,
                        ParticleSet<D>& fluid, const FluidFields<D>& f, const FluidWallNeighbors<D>& neighbors,
                        const ParticleSet<D>& walls, const WallFields<D>& w, const Vector<D>& gravity) {
  const auto run = [&]<scene::ViscosityModel Model, bool Stress>() {
    momentum<D, Model, WithPressure, Stress>(kernel, settings, stress, fluid, f, neighbors, walls, w, gravity);
  };
  const bool with_stress = WithPressure && stress.epsilon > 0;
  if (settings.model == scene::ViscosityModel::artificial) {
    with_stress ? run.template operator()<scene::ViscosityModel::artificial, WithPressure>()
                : run.template operator()<scene::ViscosityModel::artificial, false>();
  } else {
    with_stress ? run.template operator()<scene::ViscosityModel::laminar, WithPressure>()
                : run.template operator()<scene::ViscosityModel::laminar, false>();
  }
}

}  // namespace tide::passes
