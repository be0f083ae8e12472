#pragma once

// What every scheme does to set up a scene: its reference fluid material, the neighbour domain,
// fluid and wall particles with their fields and mass, the gravity ramp, and the pass clock.

#include <algorithm>
#include <span>
#include <string>

#include "tide/core/kernels/kernel.hpp"
#include "tide/core/memory_usage.hpp"
#include "tide/core/particle_set.hpp"
#include "tide/core/scene.hpp"
#include "tide/neighbor/neighbor_grid.hpp"
#include "tide/solvers/interactions.hpp"
#include "tide/solvers/moving_walls.hpp"
#include "tide/solvers/phases.hpp"
#include "tide/solvers/rigid_bodies.hpp"
#include "tide/solvers/wcsph.hpp"

namespace tide::setup {

/// The material of the first fluid block: the reference of a multiphase scene (walls, reports).
const scene::Material& reference_material(const scene::Scene& scene);

/// c0: the material's sound_speed, else 10 × its max_speed (Monaghan 1994: Mach 0.1).
Real reference_sound_speed(const scene::Material& material);

template <int D>
GridDomain<D> grid_domain(const scene::Scene& scene);

/// The neighbour lists' skin in metres: solver.neighbor_skin particle spacings (or the scheme's
/// default), less where a periodic axis could not otherwise hold three cells of support + skin.
Real neighbor_skin(const scene::Scene& scene, Real support_radius);

/// ρ0 / Σ_k W(|k| Δx): the mass that gives a particle deep in the lattice exactly the rest density.
template <int D>
Real particle_mass(const scene::Scene& scene, const AnyKernel<D>& kernel, Real rest_density);

/// Per-material constants of a multiphase scene; std::invalid_argument names a fluid material
/// without a positive sound_speed or max_speed.
template <int D>
Phases make_phases(const scene::Scene& scene, const AnyKernel<D>& kernel);

/// Fluid particles sampled from the scene, with the fields every scheme uses (FluidFields'
/// optional slots left unset) and density ρ0. With `phases`, also the phase index, and mass and
/// density from each particle's phase.
template <int D>
ParticleSet<D> make_fluid(const scene::Scene& scene, Real mass, Real rest_density, FluidFields<D>& fields,
                          const Phases* phases = nullptr);

/// Wall particles sampled from the scene with the fields of WallFields (a velocity only for no-slip
/// walls, a surface velocity only where some wall moves along its surface), density ρ0 and
/// pressure zero, added to `interactions` as wall contacts: fixed ones, "walls", those of the
/// scene's walls.slip, and, where obstacles set the other slip, "free-slip walls" or "no-slip
/// walls" (none where the scene has no wall of that slip); then one moving contact for each
/// obstacle with a motion, named by its key path ("walls.obstacles[2]") and handed to `moving`,
/// and one for each body (walls.obstacles[k].body), handed to `bodies` (null for a scheme without
/// bodies, where check_capabilities refuses them).
template <int D>
void add_wall_contacts(const scene::Scene& scene, Real mass, Real rest_density, Interactions<D>& interactions,
                       MovingWalls<D>& moving, RigidBodies<D>* bodies);

/// The volume of one wall particle, m_b/ρ0 (walls continue the fluid's lattice); 0 without walls.
template <int D>
Real wall_volume(const Interactions<D>& interactions, Real rest_density) {
  for (std::size_t k = 0; k < interactions.contact_count(); ++k) {
    const Contact<D>& contact = interactions.contact(k);
    if (contact.role() == ContactRole::wall && !contact.particles().empty())
      return contact.particles()[contact.fields().mass][0] / rest_density;
  }
  return 0;
}

/// p_i = ρ0 |g| (top − height of i), top being the highest particle plus half a spacing (its
/// share of the column): the pressure of the fluid at rest under `gravity` (zero without gravity).
template <int D>
void hydrostatic_pressure(const ParticleSet<D>& fluid, const Vector<D>& gravity, Real spacing, Real rest_density,
                          std::span<Real> pressure);

/// The same for fluids of several rest densities (`rest_densities`, by particle): p_i = |g| ∫ ρ̄ dz
/// from the top down to particle i, ρ̄ the mean rest density of the particles in each slab of
/// one spacing's depth; exact for fluids in horizontal layers.
template <int D>
void layered_hydrostatic_pressure(const ParticleSet<D>& fluid, const Vector<D>& gravity, Real spacing,
                                  std::span<const Real> rest_densities, std::span<Real> pressure);

/// A vector of the particles' precision as a 3D vector in double (z = 0 in 2D), as the rigid
/// bodies take forces and gravity.
template <int D>
Eigen::Vector3d to_space(const Vector<D>& v) {
  Eigen::Vector3d space = Eigen::Vector3d::Zero();
  for (int d = 0; d < D; ++d) space[d] = static_cast<double>(v[d]);
  return space;
}

/// Gravity at time t: the scene's, raised smoothly from zero over solver.gravity_ramp_time.
template <int D>
Vector<D> gravity_at(const scene::Scene& scene, double t);

/// The part of a body force that a fluid at rest balances with a pressure gradient: its
/// components along the closed (non-periodic) axes. Along a periodic axis the pressure is
/// periodic too: a body force there (a periodic channel's driving force) builds no hydrostatic
/// pressure.
template <int D>
Vector<D> hydrostatic_part(const scene::Scene& scene, Vector<D> body_force) {
  for (int d = 0; d < D; ++d)
    if (scene.domain.periodic[d]) body_force[d] = 0;
  return body_force;
}

/// What a scheme keeps, item by item: fluid and contact fields (with their reorder workspace)
/// and every neighbour structure, at the capacity of each buffer.
template <int D>
MemoryUsage memory_usage(const ParticleSet<D>& fluid, const Interactions<D>& interactions) {
  MemoryUsage usage;
  fluid.add_memory(usage, "fluid");
  interactions.add_memory(usage);
  return usage;
}

/// Bytes per fluid particle of memory_usage.
template <int D>
double bytes_per_particle(const ParticleSet<D>& fluid, const Interactions<D>& interactions) {
  const double fluid_count = static_cast<double>(std::max<std::size_t>(fluid.size(), 1));
  return static_cast<double>(memory_usage<D>(fluid, interactions).total()) / fluid_count;
}

/// Six significant digits, for messages.
std::string format_number(double value);

}  // namespace tide::setup
