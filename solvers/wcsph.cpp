#include "tide/solvers/wcsph.hpp"

#include <array>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <limits>
#include <numbers>
#include <stdexcept>
#include <string>
#include <variant>

#include "passes/continuity.hpp"
#include "passes/density_summation.hpp"
#include "passes/momentum.hpp"
#include "passes/particle_shifting.hpp"
#include "passes/wall_state.hpp"
#include "tide/core/parallel.hpp"
#include "tide/solvers/instability.hpp"
#include "tide/solvers/particle_sampling.hpp"

namespace tide {
namespace {

const scene::Material& single_material(const scene::Scene& scene) {
  if (scene.materials.empty()) throw std::invalid_argument(scene.source + ": WCSPH needs a fluid material");
  for (const auto& block : scene.fluid) {
    if (block.material != scene.fluid.front().material)
      throw std::invalid_argument(scene.source +
                                  ": this WCSPH solver takes a single fluid material; several fluids need the "
                                  "multiphase scheme");
  }
  return scene.materials.at(scene.fluid.empty() ? 0 : scene.fluid.front().material);
}

Real sound_speed_of(const scene::Material& material) {
  // c0 = 10 v_max keeps density variations near 1% (Monaghan 1994).
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

template <int D>
bool any_moving_wall(const scene::Scene& scene) {
  for (const scene::Obstacle& obstacle : scene.walls.obstacles)
    if (to_vector<D>(obstacle.velocity) != Vector<D>::Zero()) return true;
  return false;
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

// Six significant digits, for messages.
std::string format_number(double value) {
  std::array<char, 32> text{};
  std::snprintf(text.data(), text.size(), "%g", value);
  return text.data();
}

// Adds the seconds since `start` to `total` and restarts the clock.
void lap(std::chrono::steady_clock::time_point& start, double& total) {
  const auto now = std::chrono::steady_clock::now();
  total += std::chrono::duration<double>(now - start).count();
  start = now;
}

// Per-step maxima and the first particle (lowest index) whose state is out of bounds.
struct StateSummary {
  Real max_speed_squared = 0;
  Real max_acceleration_squared = 0;
  std::size_t bad_particle = std::numeric_limits<std::size_t>::max();

  static StateSummary combine(const StateSummary& a, const StateSummary& b) {
    return {std::max(a.max_speed_squared, b.max_speed_squared),
            std::max(a.max_acceleration_squared, b.max_acceleration_squared), std::min(a.bad_particle, b.bad_particle)};
  }
};

// The momentum pass compiled for the viscosity model and for artificial stress on or off, picked
// once per step outside the particle loop: a scene without artificial stress runs a pass without it.
template <int D, class Kernel>
void run_momentum(const Kernel& kernel, const passes::ViscositySettings& viscosity,
                  const passes::ArtificialStressSettings& stress, ParticleSet<D>& fluid, const FluidFields<D>& f,
                  const FluidWallNeighbors<D>& neighbors, const ParticleSet<D>& walls, const WallFields<D>& w,
                  const Vector<D>& gravity) {
  const auto run = [&]<scene::ViscosityModel Model, bool Stress>() {
    passes::momentum<D, Model, Stress>(kernel, viscosity, stress, fluid, f, neighbors, walls, w, gravity);
  };
  const bool with_stress = stress.epsilon > 0;
  if (viscosity.model == scene::ViscosityModel::artificial) {
    with_stress ? run.template operator()<scene::ViscosityModel::artificial, true>()
                : run.template operator()<scene::ViscosityModel::artificial, false>();
  } else {
    with_stress ? run.template operator()<scene::ViscosityModel::laminar, true>()
                : run.template operator()<scene::ViscosityModel::laminar, false>();
  }
}

}  // namespace

template <int D>
Wcsph<D>::Wcsph(const scene::Scene& scene)
    : scene_(scene),
      smoothing_length_(static_cast<Real>(scene.smoothing_ratio * scene.particle_spacing)),
      kernel_(make_kernel<D>(scene.kernel, smoothing_length_)),
      eos_(scene.solver.equation_of_state, static_cast<Real>(single_material(scene).rest_density),
           sound_speed_of(single_material(scene)), static_cast<Real>(scene.solver.tait_exponent),
           static_cast<Real>(scene.solver.background_pressure)),
      kinematic_viscosity_(static_cast<Real>(single_material(scene).kinematic_viscosity)),
      gravity_(to_vector<D>(scene.gravity)),
      neighbors_(grid_domain<D>(scene), kernel_support_factor(scene.kernel) * smoothing_length_) {
  if (!(eos_.sound_speed() > 0))
    throw std::invalid_argument(scene.source + ": the material needs a positive sound_speed or max_speed");
  const Real particle_mass =
      eos_.rest_density() /
      std::visit([&](const auto& kernel) { return lattice_kernel_sum<D>(kernel, scene); }, kernel_);

  fluid_ = make_particles<D>(sample_fluid<D>(scene), particle_mass, "velocity");
  fluid_fields_ = {fluid_.position(),
                   fluid_.vector("velocity"),
                   fluid_.add_vector("acceleration"),
                   fluid_.scalar("mass"),
                   fluid_.add_scalar("density"),
                   fluid_.add_scalar("pressure"),
                   ScalarField{},
                   VectorField{},
                   ScalarField{}};
  if (scene.solver.shifting != scene::Shifting::none) {
    fluid_fields_.shift = fluid_.add_vector("shift");
    fluid_fields_.position_divergence = fluid_.add_scalar("position_divergence");
  }
  if (scene.solver.density == scene::DensityMethod::continuity) {
    fluid_fields_.density_rate = fluid_.add_scalar("density_rate");
    set_hydrostatic_density();
  }
  const bool moving_walls = any_moving_wall<D>(scene);
  walls_ = make_particles<D>(sample_walls<D>(scene), particle_mass, moving_walls ? "surface_velocity" : "");
  wall_fields_ = {walls_.position(),
                  walls_.add_vector("velocity"),
                  walls_.scalar("mass"),
                  walls_.add_scalar("density"),
                  walls_.add_scalar("pressure"),
                  std::nullopt};
  if (moving_walls) wall_fields_.surface_velocity = walls_.vector("surface_velocity");

  time_step_rule_.smoothing_length = smoothing_length_;
  time_step_rule_.sound_speed = eos_.sound_speed();
  time_step_rule_.kinematic_viscosity =
      scene.solver.viscosity == scene::ViscosityModel::laminar ? kinematic_viscosity_ : Real(0);
  time_step_rule_.cfl = static_cast<Real>(scene.solver.cfl);
  time_step_rule_.viscous_number = static_cast<Real>(scene.solver.viscous_number);
  time_step_rule_.force_number = static_cast<Real>(scene.solver.force_number);
  time_ = scene.time.start;

  neighbors_.set_walls(walls_);
  neighbors_.update_fluid(fluid_);
  compute_interactions(gravity_at(time_));
  check_state();
}

template <int D>
Vector<D> Wcsph<D>::gravity_at(double t) const {
  // Adami, Hu & Adams 2012 (Sec. 4.1) start their hydrostatic tank this way:
  // g(t) = g (sin(π (t/t_ramp − 1/2)) + 1) / 2 for t < t_ramp, so the column is loaded without
  // the pressure wave a sudden start sends through it.
  const double ramp_time = scene_.solver.gravity_ramp_time;
  const double elapsed = t - scene_.time.start;
  if (!(ramp_time > 0) || elapsed >= ramp_time) return gravity_;
  const double share = 0.5 * (std::sin(std::numbers::pi * (elapsed / ramp_time - 0.5)) + 1);
  return static_cast<Real>(share) * gravity_;
}

template <int D>
Vector<D> Wcsph<D>::hydrostatic_part(Vector<D> body_force) const {
  // Along a periodic axis the pressure is periodic too: a body force there (the driving force of
  // a periodic channel) accelerates the fluid and builds no hydrostatic pressure.
  for (int d = 0; d < D; ++d)
    if (scene_.domain.periodic[d]) body_force[d] = 0;
  return body_force;
}

template <int D>
void Wcsph<D>::set_hydrostatic_density() {
  // Continuity density starts from the fluid at rest under gravity: p = ρ0 |g| depth below the
  // highest particle (plus half a spacing, its share of the column), ρ from the equation of state.
  auto density = fluid_[fluid_fields_.density];
  const auto x = std::as_const(fluid_)[fluid_fields_.position];
  const Vector<D> gravity = hydrostatic_part(gravity_at(time_));
  const Real g = gravity.norm();
  if (g == 0 || fluid_.empty()) {
    for (Real& rho : density) rho = eos_.rest_density();
    return;
  }
  const Vector<D> up = -gravity / g;
  Real top = -std::numeric_limits<Real>::max();
  for (std::size_t i = 0; i < fluid_.size(); ++i) top = std::max(top, up.dot(x[i]));
  top += static_cast<Real>(scene_.particle_spacing) / 2;
  const Real surface_pressure = eos_.pressure(eos_.rest_density());  // the background pressure
  for_each_particle(fluid_.size(), [&](std::size_t i) {
    density[i] = eos_.density(surface_pressure + eos_.rest_density() * g * (top - up.dot(x[i])));
  });
}

template <int D>
void Wcsph<D>::compute_interactions(const Vector<D>& gravity) {
  const bool summation = scene_.solver.density == scene::DensityMethod::summation;
  passes::ViscositySettings viscosity{scene_.solver.viscosity,
                                      scene_.walls.slip == scene::WallSlip::no_slip,
                                      static_cast<Real>(scene_.solver.alpha),
                                      static_cast<Real>(scene_.solver.beta),
                                      eos_.sound_speed(),
                                      kinematic_viscosity_,
                                      smoothing_length_};
  const passes::ArtificialStressSettings stress{
      static_cast<Real>(scene_.solver.artificial_stress),
      std::visit([&](const auto& kernel) { return 1 / kernel.value(static_cast<Real>(scene_.particle_spacing)); },
                 kernel_)};
  auto clock = std::chrono::steady_clock::now();
  std::visit(
      [&](const auto& kernel) {
        if (summation) {
          passes::density_summation<D>(kernel, fluid_, fluid_fields_, neighbors_, walls_, wall_fields_, eos_,
                                       scene_.solver.clamp_negative_pressure);
        } else {
          const auto density = std::as_const(fluid_)[fluid_fields_.density];
          auto pressure = fluid_[fluid_fields_.pressure];
          const bool clamp = scene_.solver.clamp_negative_pressure;
          for_each_particle(fluid_.size(), [&](std::size_t i) {
            const Real p = eos_.pressure(density[i]);
            pressure[i] = clamp ? std::max(p, Real(0)) : p;
          });
        }
        lap(clock, pass_times_.density);
        passes::wall_state<D>(kernel, walls_, wall_fields_, fluid_, fluid_fields_, neighbors_, eos_, gravity,
                              scene_.solver.clamp_negative_pressure);
        lap(clock, pass_times_.wall_state);
        run_momentum<D>(kernel, viscosity, stress, fluid_, fluid_fields_, neighbors_, walls_, wall_fields_, gravity);
        lap(clock, pass_times_.momentum);
      },
      kernel_);
}

template <int D>
void Wcsph<D>::compute_density_rate(const Vector<D>& gravity) {
  std::visit(
      [&](const auto& kernel) {
        passes::continuity<D>(kernel, eos_, gravity, fluid_, fluid_fields_, neighbors_, walls_, wall_fields_,
                              static_cast<Real>(scene_.solver.delta_sph), eos_.sound_speed());
      },
      kernel_);
}

template <int D>
StepReport Wcsph<D>::step() {
  StepReport report;
  report.time_step = choose_time_step(time_step_rule_, max_speed_, max_acceleration_);
  last_time_step_ = report.time_step;
  const Real dt = report.time_step.dt;
  auto clock = std::chrono::steady_clock::now();
  {
    // Kick (half step) and drift of velocity Verlet.
    auto x = fluid_[fluid_fields_.position];
    auto v = fluid_[fluid_fields_.velocity];
    const auto a = std::as_const(fluid_)[fluid_fields_.acceleration];
    for_each_particle(fluid_.size(), [&](std::size_t i) {
      const Vector<D> half_step_velocity = v[i] + (dt / 2) * a[i];
      v.set(i, half_step_velocity);
      x.set(i, x[i] + dt * half_step_velocity);
    });
  }
  lap(clock, pass_times_.integration);
  report.removed = neighbors_.update_fluid(fluid_);
  lap(clock, pass_times_.neighbor_search);
  const Vector<D> gravity = gravity_at(time_ + dt);
  if (scene_.solver.density == scene::DensityMethod::continuity) {
    compute_density_rate(hydrostatic_part(gravity));
    auto density = fluid_[fluid_fields_.density];
    const auto rate = std::as_const(fluid_)[fluid_fields_.density_rate];
    for_each_particle(fluid_.size(), [&](std::size_t i) { density[i] += dt * rate[i]; });
    lap(clock, pass_times_.density);
  }
  compute_interactions(gravity);
  clock = std::chrono::steady_clock::now();
  {
    auto v = fluid_[fluid_fields_.velocity];
    const auto a = std::as_const(fluid_)[fluid_fields_.acceleration];
    for_each_particle(fluid_.size(), [&](std::size_t i) { v.set(i, v[i] + (dt / 2) * a[i]); });
  }
  time_ += dt;
  ++step_count_;
  check_state();
  lap(clock, pass_times_.integration);
  if (scene_.solver.shifting != scene::Shifting::none) {
    shift_particles(dt);
    lap(clock, pass_times_.shifting);
  }
  return report;
}

template <int D>
void Wcsph<D>::shift_particles(Real dt) {
  const Real spacing = static_cast<Real>(scene_.particle_spacing);
  std::visit(
      [&](const auto& kernel) {
        const passes::ShiftingSettings settings{4 * smoothing_length_ * max_speed_ * dt, kernel.value(spacing),
                                                Real(D) - Real(0.5), Real(D) / 2};
        passes::position_divergence<D>(kernel, fluid_, fluid_fields_, neighbors_, walls_, wall_fields_,
                                       fluid_[fluid_fields_.position_divergence]);
        passes::particle_shifting<D>(kernel, settings, fluid_, fluid_fields_, neighbors_, walls_, wall_fields_,
                                     std::as_const(fluid_)[fluid_fields_.position_divergence],
                                     fluid_[fluid_fields_.shift]);
      },
      kernel_);
  auto x = fluid_[fluid_fields_.position];
  const auto shift = std::as_const(fluid_)[fluid_fields_.shift];
  for_each_particle(fluid_.size(), [&](std::size_t i) { x.set(i, x[i] + shift[i]); });
}

template <int D>
double Wcsph<D>::bytes_per_particle() const {
  const double fluid_count = static_cast<double>(std::max<std::size_t>(fluid_.size(), 1));
  const double fields =
      static_cast<double>(fluid_.bytes_per_particle() * fluid_.size() + walls_.bytes_per_particle() * walls_.size());
  return (fields + static_cast<double>(neighbors_.bytes())) / fluid_count;
}

template <int D>
void Wcsph<D>::check_state() {
  const auto x = fluid_[fluid_fields_.position];
  const auto v = fluid_[fluid_fields_.velocity];
  const auto a = fluid_[fluid_fields_.acceleration];
  const auto density = fluid_[fluid_fields_.density];
  const Real rho0 = eos_.rest_density();
  const Real ratio = static_cast<Real>(scene_.solver.max_density_ratio);
  const bool check_low_density = scene_.solver.density == scene::DensityMethod::continuity;
  const Real max_speed = static_cast<Real>(scene_.solver.max_mach_number) * eos_.sound_speed();
  auto out_of_bounds = [&](std::size_t i, Real speed2) {
    const Real rho = density[i];
    return !std::isfinite(x[i].squaredNorm() + speed2 + a[i].squaredNorm() + rho) || rho > ratio * rho0 ||
           (check_low_density && rho < rho0 / ratio) || speed2 > max_speed * max_speed;
  };
  const StateSummary summary = reduce(
      fluid_.size(), StateSummary{},
      [&](std::size_t i) {
        const Real speed2 = v[i].squaredNorm();
        return StateSummary{speed2, a[i].squaredNorm(),
                            out_of_bounds(i, speed2) ? i : std::numeric_limits<std::size_t>::max()};
      },
      StateSummary::combine);
  max_speed_ = std::sqrt(summary.max_speed_squared);
  max_acceleration_ = std::sqrt(summary.max_acceleration_squared);
  if (summary.bad_particle == std::numeric_limits<std::size_t>::max()) return;

  const std::size_t i = summary.bad_particle;
  const Index id = fluid_[fluid_.id()][i];
  const double t = time_;
  const std::string step_note = time_step_note();
  if (!std::isfinite(x[i].squaredNorm()))
    throw InstabilityError(id, "position", static_cast<double>(x[i].norm()), step_count_, t, "not finite", step_note);
  if (!std::isfinite(v[i].squaredNorm()))
    throw InstabilityError(id, "velocity", static_cast<double>(v[i].norm()), step_count_, t, "not finite", step_note);
  if (!std::isfinite(a[i].squaredNorm()))
    throw InstabilityError(id, "acceleration", static_cast<double>(a[i].norm()), step_count_, t, "not finite",
                           step_note);
  if (!std::isfinite(density[i]) || density[i] > ratio * rho0 || (check_low_density && density[i] < rho0 / ratio))
    throw InstabilityError(
        id, "density", static_cast<double>(density[i]), step_count_, t,
        "outside [rho0/" + format_number(ratio) + ", " + format_number(ratio) + " rho0], solver.max_density_ratio",
        step_note);
  throw InstabilityError(id, "speed", static_cast<double>(v[i].norm()), step_count_, t,
                         "faster than " + format_number(scene_.solver.max_mach_number) +
                             " x c0 = " + format_number(max_speed) + " m/s, solver.max_mach_number",
                         step_note);
}

template <int D>
std::string Wcsph<D>::time_step_note() const {
  if (step_count_ == 0) return "";
  const TimeStepRule& rule = time_step_rule_;
  std::string note = "the last time step was dt = " + format_number(last_time_step_.dt) + " s, set by the " +
                     std::string(time_step_limit_name(last_time_step_.limit)) +
                     " limit (solver.cfl = " + format_number(rule.cfl);
  if (rule.kinematic_viscosity > 0) note += ", solver.viscous_number = " + format_number(rule.viscous_number);
  note += ", solver.force_number = " + format_number(rule.force_number) + ")";
  if (rule.cfl > max_stable_cfl) {
    note += "; solver.cfl above " + format_number(max_stable_cfl) +
            " is beyond the stable limit of the explicit integration: the time step is the likely cause, lower "
            "solver.cfl";
  }
  return note;
}

template class Wcsph<2>;
template class Wcsph<3>;

}  // namespace tide
