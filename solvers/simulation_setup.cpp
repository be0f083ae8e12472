#include "simulation_setup.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <limits>
#include <numbers>
#include <optional>
#include <stdexcept>
#include <string>
#include <type_traits>
#include <variant>
#include <vector>

#include "tide/core/parallel.hpp"
#include "tide/solvers/mass_properties.hpp"
#include "tide/solvers/particle_sampling.hpp"

namespace tide::setup {
namespace {

// A particle set with position, mass and, unless `velocity_name` is empty, the sampled
// velocities in the field of that name.
template <int D>
ParticleSet<D> make_particles(const ParticleSamples<D>& samples, Real mass, const std::string& velocity_name) {
  ParticleSet<D> set;
  set.append(samples.size());
  auto x = set[set.position()];
  const auto m = set.add_scalar("mass");
  for (std::size_t i = 0; i < samples.size(); ++i) {
    x.set(i, samples.positions[i]);
    set[m][i] = mass;
  }
  if (!velocity_name.empty()) {
    auto v = set[set.add_vector(velocity_name)];
    for (std::size_t i = 0; i < samples.size(); ++i) v.set(i, samples.velocities[i]);
  }
  return set;
}

// The obstacle that made a wall sample (ParticleSamples::makers); none for the container.
const scene::Obstacle* maker_of(const scene::Scene& scene, std::size_t maker) {
  return maker == 0 ? nullptr : &scene.walls.obstacles[maker - 1];
}

// The wall samples whose maker passes `keep`, in their order.
template <int D, class Keep>
ParticleSamples<D> walls_made_by(const scene::Scene& scene, const ParticleSamples<D>& walls, Keep&& keep) {
  ParticleSamples<D> kept;
  for (std::size_t i = 0; i < walls.size(); ++i) {
    if (!keep(maker_of(scene, walls.makers[i]))) continue;
    kept.positions.push_back(walls.positions[i]);
    kept.velocities.push_back(walls.velocities[i]);
    kept.makers.push_back(walls.makers[i]);
  }
  return kept;
}

// The samples of the walls that stay in place and have slip `slip`.
template <int D>
ParticleSamples<D> fixed_walls_with_slip(const scene::Scene& scene, const ParticleSamples<D>& walls,
                                         scene::WallSlip slip) {
  return walls_made_by<D>(scene, walls, [&](const scene::Obstacle* obstacle) {
    if (!obstacle) return scene.walls.slip == slip;
    return !obstacle->motion && !obstacle->body && obstacle->slip.value_or(scene.walls.slip) == slip;
  });
}

// The fields every wall contact has: position, mass, density ρ0 and pressure, and the mirrored
// velocity of the no-slip condition.
template <int D>
WallFields<D> add_wall_fields(ParticleSet<D>& walls, scene::WallSlip slip, Real rest_density) {
  WallFields<D> fields{
      walls.position(), std::nullopt, walls.scalar("mass"), walls.add_scalar("density"), walls.add_scalar("pressure"),
      std::nullopt,     std::nullopt};
  if (slip == scene::WallSlip::no_slip) fields.velocity = walls.add_vector("velocity");
  for (Real& rho : walls[fields.density]) rho = rest_density;
  return fields;
}

// The fixed wall contact of `samples` (none when empty).
template <int D>
void add_wall_contact(std::string name, const ParticleSamples<D>& samples, scene::WallSlip slip, Real mass,
                      Real rest_density, Interactions<D>& interactions) {
  if (samples.size() == 0) return;
  const bool moving = std::any_of(samples.velocities.begin(), samples.velocities.end(),
                                  [](const Vector<D>& v) { return v != Vector<D>::Zero(); });
  ParticleSet<D> walls = make_particles<D>(samples, mass, moving ? "surface_velocity" : "");
  WallFields<D> fields = add_wall_fields<D>(walls, slip, rest_density);
  if (moving) fields.surface_velocity = walls.vector("surface_velocity");
  // Wall particles may move along their surface (a conveyor, a lid) but keep their place.
  interactions.add_contact(std::move(name), ContactRole::wall, ContactMotion::fixed, std::move(walls), fields);
}

// A moving contact of its own for obstacle `k` (a prescribed motion or a body), named by its key
// path, with a surface velocity, an acceleration and each particle's start position; none when
// the obstacle has no particles.
template <int D>
struct MovingObstacle {
  Contact<D>* contact = nullptr;
  VectorField start;
};

template <int D>
MovingObstacle<D> add_moving_contact(const scene::Scene& scene, std::size_t k, const ParticleSamples<D>& samples,
                                     Real mass, Real rest_density, Interactions<D>& interactions,
                                     const std::vector<std::string>& extra_vectors = {}) {
  const scene::Obstacle& obstacle = scene.walls.obstacles[k];
  const ParticleSamples<D> own =
      walls_made_by<D>(scene, samples, [&](const scene::Obstacle* maker) { return maker == &obstacle; });
  if (own.size() == 0) return {};
  ParticleSet<D> walls = make_particles<D>(own, mass, "surface_velocity");
  WallFields<D> fields = add_wall_fields<D>(walls, obstacle.slip.value_or(scene.walls.slip), rest_density);
  fields.surface_velocity = walls.vector("surface_velocity");
  fields.acceleration = walls.add_vector("acceleration");
  const VectorField start = walls.add_vector("start_position");
  for (std::size_t b = 0; b < walls.size(); ++b) walls[start].set(b, own.positions[b]);
  for (const std::string& name : extra_vectors) walls.add_vector(name);
  Contact<D>& contact = interactions.add_contact("walls.obstacles[" + std::to_string(k) + "]", ContactRole::wall,
                                                 ContactMotion::moving, std::move(walls), fields);
  return {&contact, start};
}

// Obstacle `k`, which has a prescribed motion.
template <int D>
void add_moving_obstacle(const scene::Scene& scene, std::size_t k, const ParticleSamples<D>& samples, Real mass,
                         Real rest_density, Interactions<D>& interactions, MovingWalls<D>& moving) {
  const MovingObstacle<D> added = add_moving_contact<D>(scene, k, samples, mass, rest_density, interactions);
  if (added.contact) moving.add(*added.contact, *scene.walls.obstacles[k].motion, added.start);
}

// Obstacle `k`, which is a rigid body: its mass properties from its shape and density, and a
// field for the fluid's force on each of its particles.
template <int D>
void add_body(const scene::Scene& scene, std::size_t k, const ParticleSamples<D>& samples, Real mass, Real rest_density,
              Interactions<D>& interactions, RigidBodies<D>& bodies) {
  const scene::Obstacle& obstacle = scene.walls.obstacles[k];
  const MassProperties properties = std::visit(
      [&](const auto& shape) -> MassProperties {
        if constexpr (std::is_same_v<std::decay_t<decltype(shape)>, scene::Plane>) {
          throw std::invalid_argument(scene.source + ": walls.obstacles[" + std::to_string(k) +
                                      "] is a plane, which cannot be a body");
        } else {
          return mass_properties(shape, obstacle.body->density, D);
        }
      },
      obstacle.shape);
  const MovingObstacle<D> added =
      add_moving_contact<D>(scene, k, samples, mass, rest_density, interactions, {"fluid_force", "contact_force"});
  if (!added.contact) return;
  bodies.add(*added.contact, RigidBody(properties, obstacle.body->constraints, D), obstacle.body->release_time,
             to_eigen(obstacle.body->applied_force), added.start, added.contact->particles().vector("fluid_force"),
             added.contact->particles().vector("contact_force"));
}

// Σ_k W(|k| Δx) over the lattice around one particle: the summation density of a particle deep
// in the fluid, per unit mass. It differs from 1/Δx^D by the kernel's discretisation error
// (+0.5% for Wendland C2 at h = 1.3 Δx, i.e. ~1 kPa of Tait pressure at c0 = 15 m/s), so the
// mass is set to ρ0 over this sum and the fluid starts at rest density, without a pressure jump
// at its free surface.
template <int D, class Kernel>
Real lattice_kernel_sum(const Kernel& kernel, const scene::Scene& scene) {
  const Real spacing = static_cast<Real>(scene.particle_spacing);
  const int reach = static_cast<int>(std::ceil(kernel.support_radius() / spacing));
  std::array<int, D> k;
  k.fill(-reach);
  Real sum = 0;
  while (true) {
    Vector<D> offset;
    for (int d = 0; d < D; ++d) offset[d] = spacing * Real(k[d]);
    sum += kernel.value(offset.norm());
    int d = 0;
    for (; d < D; ++d) {
      if (++k[d] <= reach) break;
      k[d] = -reach;
    }
    if (d == D) return sum;
  }
}

}  // namespace

const scene::Material& reference_material(const scene::Scene& scene) {
  if (scene.materials.empty()) throw std::invalid_argument(scene.source + ": the scene needs a fluid material");
  return scene.materials.at(scene.fluid.empty() ? 0 : scene.fluid.front().material);
}

Real reference_sound_speed(const scene::Material& material) {
  return static_cast<Real>(material.sound_speed ? *material.sound_speed : 10 * material.max_speed.value_or(0));
}

template <int D>
GridDomain<D> grid_domain(const scene::Scene& scene) {
  GridDomain<D> domain;
  domain.lower = to_vector<D>(scene.domain.box.min);
  domain.upper = to_vector<D>(scene.domain.box.max);
  for (int d = 0; d < D; ++d) domain.periodic[d] = scene.domain.periodic[d];
  return domain;
}

Real neighbor_skin(const scene::Scene& scene, Real support_radius) {
  const double spacings = scene.solver.neighbor_skin.value_or(scene::default_neighbor_skin(scene.solver.scheme));
  Real skin = static_cast<Real>(spacings * scene.particle_spacing);
  for (int d = 0; d < scene.dimension; ++d) {
    if (!scene.domain.periodic[d]) continue;
    // A periodic axis needs 3 cells of support + skin (with room for the grid's cell margin).
    const Real length = static_cast<Real>(scene.domain.box.max[d] - scene.domain.box.min[d]);
    skin = std::min(skin, std::max(Real(0), length / Real(3.003) - support_radius));
  }
  return skin;
}

template <int D>
Real particle_mass(const scene::Scene& scene, const AnyKernel<D>& kernel, Real rest_density) {
  return rest_density / std::visit([&](const auto& k) { return lattice_kernel_sum<D>(k, scene); }, kernel);
}

template <int D>
Phases make_phases(const scene::Scene& scene, const AnyKernel<D>& kernel) {
  const Real lattice_sum = std::visit([&](const auto& k) { return lattice_kernel_sum<D>(k, scene); }, kernel);
  const std::vector<bool> used = scene::fluid_materials_used(scene);
  Phases phases;
  phases.first_fluid = static_cast<std::size_t>(std::find(used.begin(), used.end(), true) - used.begin());
  phases.lightest_density = std::numeric_limits<Real>::max();
  for (std::size_t k = 0; k < scene.materials.size(); ++k) {
    const scene::Material& material = scene.materials[k];
    const Real rho0 = static_cast<Real>(material.rest_density);
    const Real c0 = reference_sound_speed(material);
    if (used[k] && !(c0 > 0))
      throw std::invalid_argument(scene.source + ": material \"" + material.name +
                                  "\" needs a positive sound_speed or max_speed");
    phases.table.push_back(
        {rho0, rho0 / lattice_sum, rho0 * static_cast<Real>(material.kinematic_viscosity),
         EquationOfState(scene.solver.equation_of_state, rho0, c0, static_cast<Real>(scene.solver.tait_exponent),
                         static_cast<Real>(scene.solver.background_pressure))});
    if (!used[k]) continue;
    phases.lightest_density = std::min(phases.lightest_density, rho0);
    phases.densest_density = std::max(phases.densest_density, rho0);
    phases.fastest_sound = std::max(phases.fastest_sound, c0);
    phases.largest_kinematic_viscosity =
        std::max(phases.largest_kinematic_viscosity, static_cast<Real>(material.kinematic_viscosity));
  }
  return phases;
}

template <int D>
ParticleSet<D> make_fluid(const scene::Scene& scene, Real mass, Real rest_density, FluidFields<D>& fields,
                          const Phases* phases) {
  const ParticleSamples<D> samples = sample_fluid<D>(scene);
  ParticleSet<D> fluid = make_particles<D>(samples, mass, "velocity");
  fields = {fluid.position(),
            fluid.vector("velocity"),
            fluid.add_vector("acceleration"),
            fluid.scalar("mass"),
            fluid.add_scalar("density"),
            fluid.add_scalar("pressure"),
            std::nullopt,
            std::nullopt,
            std::nullopt,
            std::nullopt,
            std::nullopt};
  for (Real& rho : fluid[fields.density]) rho = rest_density;
  if (phases) {
    fields.phase = fluid.add_index("phase");
    auto phase = fluid[fields.phase];
    auto m = fluid[fields.mass];
    auto rho = fluid[fields.density];
    for (std::size_t i = 0; i < fluid.size(); ++i) {
      phase[i] = static_cast<Index>(samples.materials[i]);
      m[i] = phases->table[samples.materials[i]].mass;
      rho[i] = phases->table[samples.materials[i]].rest_density;
    }
  }
  if (scene.solver.shifting != scene::Shifting::none) {
    fields.shift = fluid.add_vector("shift");
    fields.position_divergence = fluid.add_scalar("position_divergence");
  }
  return fluid;
}

template <int D>
void add_wall_contacts(const scene::Scene& scene, Real mass, Real rest_density, Interactions<D>& interactions,
                       MovingWalls<D>& moving, RigidBodies<D>* bodies) {
  const ParticleSamples<D> samples = sample_walls<D>(scene);
  const scene::WallSlip slip = scene.walls.slip;
  const scene::WallSlip other =
      slip == scene::WallSlip::no_slip ? scene::WallSlip::free_slip : scene::WallSlip::no_slip;
  add_wall_contact<D>("walls", fixed_walls_with_slip<D>(scene, samples, slip), slip, mass, rest_density, interactions);
  add_wall_contact<D>(other == scene::WallSlip::no_slip ? "no-slip walls" : "free-slip walls",
                      fixed_walls_with_slip<D>(scene, samples, other), other, mass, rest_density, interactions);
  for (std::size_t k = 0; k < scene.walls.obstacles.size(); ++k) {
    if (scene.walls.obstacles[k].motion)
      add_moving_obstacle<D>(scene, k, samples, mass, rest_density, interactions, moving);
    if (scene.walls.obstacles[k].body) {
      if (!bodies) throw std::logic_error("add_wall_contacts: a body in a scheme without bodies");
      add_body<D>(scene, k, samples, mass, rest_density, interactions, *bodies);
    }
  }
}

namespace {

// What a hydrostatic start measures depths with: |g|, the unit vector against gravity, and the
// top of the fluid along it (its highest particle plus half a spacing, that particle's share).
template <int D>
struct FluidColumn {
  Real g;
  Vector<D> up;
  Real top;
};

// The column of `fluid` under `gravity`; none without gravity or particles, where the
// hydrostatic pressure is zero (written into `pressure`).
template <int D>
std::optional<FluidColumn<D>> fluid_column(const ParticleSet<D>& fluid, const Vector<D>& gravity, Real spacing,
                                           std::span<Real> pressure) {
  const Real g = gravity.norm();
  if (g == 0 || fluid.empty()) {
    std::fill(pressure.begin(), pressure.end(), Real(0));
    return std::nullopt;
  }
  const auto x = fluid[fluid.position()];
  const Vector<D> up = -gravity / g;
  Real top = -std::numeric_limits<Real>::max();
  for (std::size_t i = 0; i < fluid.size(); ++i) top = std::max(top, up.dot(x[i]));
  return FluidColumn<D>{g, up, top + spacing / 2};
}

}  // namespace

template <int D>
void hydrostatic_pressure(const ParticleSet<D>& fluid, const Vector<D>& gravity, Real spacing, Real rest_density,
                          std::span<Real> pressure) {
  const std::optional<FluidColumn<D>> column = fluid_column<D>(fluid, gravity, spacing, pressure);
  if (!column) return;
  const auto x = fluid[fluid.position()];
  const auto [g, up, top] = *column;
  for_each_particle(fluid.size(), [&](std::size_t i) { pressure[i] = rest_density * g * (top - up.dot(x[i])); });
}

template <int D>
void layered_hydrostatic_pressure(const ParticleSet<D>& fluid, const Vector<D>& gravity, Real spacing,
                                  std::span<const Real> rest_densities, std::span<Real> pressure) {
  const std::optional<FluidColumn<D>> column = fluid_column<D>(fluid, gravity, spacing, pressure);
  if (!column) return;
  const auto x = fluid[fluid.position()];
  const auto [g, up, top] = *column;
  // Slab k holds the particles at depths [k Δx, (k + 1) Δx) below the top: its mean rest density
  // ρ̄_k, and the weight of the slabs above it, g Σ_{k' < k} ρ̄_k' Δx.
  const auto slab = [&](std::size_t i) { return static_cast<std::size_t>((top - up.dot(x[i])) / spacing); };
  std::vector<Real> density_sum, count;
  for (std::size_t i = 0; i < fluid.size(); ++i) {
    const std::size_t k = slab(i);
    if (k >= density_sum.size()) {
      density_sum.resize(k + 1, 0);
      count.resize(k + 1, 0);
    }
    density_sum[k] += rest_densities[i];
    count[k] += 1;
  }
  std::vector<Real> mean(density_sum.size(), 0), above(density_sum.size() + 1, 0);
  for (std::size_t k = 0; k < mean.size(); ++k) {
    mean[k] = count[k] > 0 ? density_sum[k] / count[k] : Real(0);
    above[k + 1] = above[k] + g * mean[k] * spacing;
  }
  for_each_particle(fluid.size(), [&](std::size_t i) {
    const std::size_t k = slab(i);
    pressure[i] = above[k] + g * mean[k] * (top - up.dot(x[i]) - Real(k) * spacing);
  });
}

template <int D>
Vector<D> gravity_at(const scene::Scene& scene, double t) {
  // Adami, Hu & Adams 2012 (Sec. 4.1) start their hydrostatic tank this way:
  // g(t) = g (sin(π (t/t_ramp − 1/2)) + 1) / 2 for t < t_ramp, so the column is loaded without
  // the pressure wave a sudden start sends through it.
  const Vector<D> gravity = to_vector<D>(scene.gravity);
  const double ramp_time = scene.solver.gravity_ramp_time;
  const double elapsed = t - scene.time.start;
  if (!(ramp_time > 0) || elapsed >= ramp_time) return gravity;
  const double share = 0.5 * (std::sin(std::numbers::pi * (elapsed / ramp_time - 0.5)) + 1);
  return static_cast<Real>(share) * gravity;
}

std::string format_number(double value) {
  std::array<char, 32> text{};
  std::snprintf(text.data(), text.size(), "%g", value);
  return text.data();
}

template GridDomain<2> grid_domain<2>(const scene::Scene&);
template Real particle_mass<2>(const scene::Scene&, const AnyKernel<2>&, Real);
template Phases make_phases<2>(const scene::Scene&, const AnyKernel<2>&);
template ParticleSet<2> make_fluid<2>(const scene::Scene&, Real, Real, FluidFields<2>&, const Phases*);
template void add_wall_contacts<2>(const scene::Scene&, Real, Real, Interactions<2>&, MovingWalls<2>&, RigidBodies<2>*);
template void hydrostatic_pressure<2>(const ParticleSet<2>&, const Vector<2>&, Real, Real, std::span<Real>);
template void layered_hydrostatic_pressure<2>(const ParticleSet<2>&, const Vector<2>&, Real, std::span<const Real>,
                                              std::span<Real>);
template Vector<2> gravity_at<2>(const scene::Scene&, double);
template GridDomain<3> grid_domain<3>(const scene::Scene&);
template Real particle_mass<3>(const scene::Scene&, const AnyKernel<3>&, Real);
template Phases make_phases<3>(const scene::Scene&, const AnyKernel<3>&);
template ParticleSet<3> make_fluid<3>(const scene::Scene&, Real, Real, FluidFields<3>&, const Phases*);
template void add_wall_contacts<3>(const scene::Scene&, Real, Real, Interactions<3>&, MovingWalls<3>&, RigidBodies<3>*);
template void hydrostatic_pressure<3>(const ParticleSet<3>&, const Vector<3>&, Real, Real, std::span<Real>);
template void layered_hydrostatic_pressure<3>(const ParticleSet<3>&, const Vector<3>&, Real, std::span<const Real>,
                                              std::span<Real>);
template Vector<3> gravity_at<3>(const scene::Scene&, double);

}  // namespace tide::setup
