#pragma once

// Acceleration of every fluid particle: pressure, viscosity and body force in one gather pass.

#include <cmath>

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

namespace detail {

// Viscous acceleration on i from one neighbour j.
// Artificial: Monaghan 1992, eq. 4.1–4.2: −m_j Π_ij ∇W_ij, Π_ij = (−α c μ + β μ²)/ρ̄_ij when
//   v_ij·x_ij < 0, μ = h v_ij·x_ij / (r² + 0.01 h²).
// Laminar: Morris, Fox & Zhu 1997, eq. 8: m_j (μ_i + μ_j) x_ij·∇W_ij / (ρ_i ρ_j (r² + 0.01 h²)) v_ij.
template <int D, scene::ViscosityModel Model>
inline Vector<D> viscous_term(const ViscositySettings& s, Real m_j, Real rho_i, Real rho_j, const Vector<D>& v_ij,
                              const Vector<D>& x_ij, Real r2, const Vector<D>& grad_w) {
  const Real h = s.smoothing_length;
  const Real regularised_r2 = r2 + Real(0.01) * h * h;
  if constexpr (Model == scene::ViscosityModel::artificial) {
    const Real v_dot_x = v_ij.dot(x_ij);
    if (v_dot_x >= 0) return Vector<D>::Zero();
    const Real mu = h * v_dot_x / regularised_r2;
    const Real pi = (-s.alpha * s.sound_speed * mu + s.beta * mu * mu) / (Real(0.5) * (rho_i + rho_j));
    return (-m_j * pi) * grad_w;
  } else {
    const Real dynamic_sum = s.kinematic_viscosity * (rho_i + rho_j);
    return (m_j * dynamic_sum * x_ij.dot(grad_w) / (rho_i * rho_j * regularised_r2)) * v_ij;
  }
}

}  // namespace detail

/// a_i = −Σ_j m_j (p_i/ρ_i² + p_j/ρ_j²) ∇W_ij (Monaghan 1992, eq. 3.3) + viscous terms + g,
/// summed over fluid and wall neighbours (walls with their extrapolated p, ρ and velocity).
/// Without `WithPressure`, the non-pressure part only: what an incompressible scheme integrates
/// before its pressure solve.
template <int D, scene::ViscosityModel Model, bool WithPressure = true, class Kernel>
void momentum(const Kernel& kernel, const ViscositySettings& settings, ParticleSet<D>& fluid, const FluidFields<D>& f,
              const FluidWallNeighbors<D>& neighbors, const ParticleSet<D>& walls, const WallFields<D>& w,
              const Vector<D>& gravity) {
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
  for_each_particle(fluid.size(), [&](std::size_t i) {
    const Vector<D> v_i = v[i];
    const Real rho_i = density[i];
    const Real p_over_rho2_i = pressure[i] / (rho_i * rho_i);
    Vector<D> a = gravity;
    neighbors.for_each_fluid_neighbor(i, x, [&](Index j, const Vector<D>& x_ij, Real r2) {
      if (j == i) return;
      const Real rho_j = density[j];
      const Vector<D> grad_w = kernel.gradient(x_ij, std::sqrt(r2));
      if constexpr (WithPressure) a -= (mass[j] * (p_over_rho2_i + pressure[j] / (rho_j * rho_j))) * grad_w;
      a += detail::viscous_term<D, Model>(settings, mass[j], rho_i, rho_j, v_i - v[j], x_ij, r2, grad_w);
    });
    if (!WithPressure && !settings.walls_viscous) {
      acceleration.set(i, a);
      return;
    }
    neighbors.for_each_wall_neighbor(i, x, wall_x, [&](Index b, const Vector<D>& x_ib, Real r2) {
      const Real rho_b = wall_density[b];
      const Vector<D> grad_w = kernel.gradient(x_ib, std::sqrt(r2));
      if constexpr (WithPressure) a -= (wall_mass[b] * (p_over_rho2_i + wall_pressure[b] / (rho_b * rho_b))) * grad_w;
      if (settings.walls_viscous)
        a += detail::viscous_term<D, Model>(settings, wall_mass[b], rho_i, rho_b, v_i - wall_v[b], x_ib, r2, grad_w);
    });
    acceleration.set(i, a);
  });
}

/// momentum() with the viscosity model of `settings`, chosen once per pass.
template <int D, bool WithPressure = true, class Kernel>
void fluid_acceleration(const Kernel& kernel, const ViscositySettings& settings, ParticleSet<D>& fluid,
                        const FluidFields<D>& f, const FluidWallNeighbors<D>& neighbors, const ParticleSet<D>& walls,
                        const WallFields<D>& w, const Vector<D>& gravity) {
  if (settings.model == scene::ViscosityModel::artificial) {
    momentum<D, scene::ViscosityModel::artificial, WithPressure>(kernel, settings, fluid, f, neighbors, walls, w,
                                                                 gravity);
  } else {
    momentum<D, scene::ViscosityModel::laminar, WithPressure>(kernel, settings, fluid, f, neighbors, walls, w, gravity);
  }
}

}  // namespace tide::passes
