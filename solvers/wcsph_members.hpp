#pragma once

// Wcsph's member definitions, instantiated once per dimension (wcsph_2d.cpp, wcsph_3d.cpp): a
// file per dimension lets two cores share the compile of the passes.

#include "tide/solvers/wcsph.hpp"

#include <array>
#include <cmath>
#include <cstdio>
#include <limits>
#include <numbers>
#include <stdexcept>
#include <string>
#include <utility>

#include "passes/body_force.hpp"
#include "passes/continuity.hpp"
#include "passes/density_summation.hpp"
#include "passes/free_surface_density.hpp"
#include "passes/inflow.hpp"
#include "passes/momentum.hpp"
#include "passes/particle_shifting.hpp"
#include "passes/riemann.hpp"
#include "passes/surface_tension.hpp"
#include "passes/wall_state.hpp"
#include "simulation_setup.hpp"
#include "start_edit.hpp"
#include "state_check.hpp"
#include "surface_tension_setup.hpp"
#include "tide/core/parallel.hpp"
#include "tide/solvers/capabilities.hpp"
#include "tide/solvers/particle_sampling.hpp"

namespace tide {

using setup::format_number;

template <int D>
Wcsph<D>::Wcsph(const scene::Scene& scene)
    : scene_(scene),
      smoothing_length_(static_cast<Real>(scene.smoothing_ratio * scene.particle_spacing)),
      kernel_(make_kernel<D>(scene.kernel, smoothing_length_)),
      eos_(scene.solver.equation_of_state, static_cast<Real>(setup::reference_material(scene).rest_density),
           setup::reference_sound_speed(setup::reference_material(scene)),
           static_cast<Real>(scene.solver.tait_exponent), static_cast<Real>(scene.solver.background_pressure)),
      kinematic_viscosity_(static_cast<Real>(setup::reference_material(scene).kinematic_viscosity)),
      interactions_(setup::grid_domain<D>(scene), kernel_support_factor(scene.kernel) * smoothing_length_,
                    setup::neighbor_skin(scene, kernel_support_factor(scene.kernel) * smoothing_length_)),
      moving_walls_(setup::grid_domain<D>(scene)),
      bodies_(setup::grid_domain<D>(scene)) {
  if (!(eos_.sound_speed() > 0))
    throw std::invalid_argument(scene.source + ": the material needs a positive sound_speed or max_speed");
  check_capabilities(scene);
  if (scene::fluid_material_count(scene) > 1) phases_ = setup::make_phases<D>(scene, kernel_.any());
  const Real particle_mass = setup::particle_mass<D>(scene, kernel_.any(), eos_.rest_density());
  fluid_ = setup::make_fluid<D>(scene, particle_mass, eos_.rest_density(), fluid_fields_, phases());
  setup::SchemeSurfaceTension tension = setup::make_surface_tension<D>(
      scene, kernel_.any(), phases(), eos_.rest_density(), particle_mass, fluid_, fluid_fields_);
  tension_ = std::move(tension.settings);
  if (scene.solver.density == scene::DensityMethod::continuity) {
    fluid_fields_.density_rate = fluid_.add_scalar("density_rate");
    set_hydrostatic_density();
  }
  setup::add_wall_contacts<D>(scene, particle_mass, eos_.rest_density(), interactions_, moving_walls_, &bodies_);

  time_step_rule_.smoothing_length = smoothing_length_;
  time_step_rule_.sound_speed = phases_ ? phases_->fastest_sound : eos_.sound_speed();
  time_step_rule_.kinematic_viscosity = scene.solver.viscosity == scene::ViscosityModel::laminar
                                            ? (phases_ ? phases_->largest_kinematic_viscosity : kinematic_viscosity_)
                                            : Real(0);
  time_step_rule_.capillary_limit = tension.capillary_limit;
  time_step_rule_.cfl = static_cast<Real>(scene.solver.cfl);
  time_step_rule_.viscous_number = static_cast<Real>(scene.solver.viscous_number);
  time_step_rule_.force_number = static_cast<Real>(scene.solver.force_number);
  contact_law_ = contact_law(scene.solver.body_contact, static_cast<Real>(scene.particle_spacing),
                             acoustic_time_step(time_step_rule_, 0));
  time_ = scene.time.start;

  if (!moving_walls_.empty()) moving_walls_.move_to(0, step_count_, time_);  // their velocity at the start
  if (!bodies_.empty()) bodies_.place(step_count_, time_);
  start();
  pipeline_ = build_pipeline();
}

template <int D>
void Wcsph<D>::edit_start(FunctionRef<void(ParticleSet<D>&)> edit) {
  setup::edit_start_fields<D>(step_count_, fluid_, edit);
  start();
}

template <int D>
void Wcsph<D>::start() {
  std::vector<Stage> stages{neighbor_search_stage()};
  for (Stage& stage : force_stages()) stages.push_back(std::move(stage));
  StepContext at_start;  // dt = 0: the forces at the start time
  Pipeline(std::move(stages)).run(at_start);
  check_state();
}

template <int D>
Wcsph<D>::~Wcsph() = default;

template <int D>
Pipeline Wcsph<D>::build_pipeline() {
  std::vector<Stage> stages;
  stages.push_back({"kick_drift", [this](StepContext& c) { kick_drift(c.dt); }});
  if (scene_.domain.inflow) stages.push_back({"inflow_drift", [this](StepContext& c) { impose_inflow(c.dt); }});
  if (injects_phase()) stages.push_back({"inflow_phase", [this](StepContext&) { inject_phase(); }});
  if (!moving_walls_.empty()) {
    stages.push_back({"prescribed_motion", [this](StepContext& c) {
                        const double end = time_ + c.dt;  // where the walls are at the step's end
                        moving_walls_.move_to(end - scene_.time.start, step_count_ + 1, end);
                      }});
  }
  if (!bodies_.empty()) {
    stages.push_back({"body_kick_drift", [this](StepContext& c) {
                        bodies_.kick_drift(c.dt, setup::to_space(gravity()), step_count_ + 1, time_);
                      }});
  }
  stages.push_back(neighbor_search_stage());
  if (scene_.solver.density == scene::DensityMethod::continuity)
    stages.push_back({"continuity", [this](StepContext& c) { integrate_density(step_gravity(c), c.dt); }});
  if (holds_free_surface_density())
    stages.push_back({"free_surface_density", [this](StepContext&) { hold_free_surface_density(); }});
  for (Stage& stage : force_stages()) stages.push_back(std::move(stage));
  stages.push_back({"kick", [this](StepContext& c) { kick(c.dt); }});
  if (!bodies_.empty())
    stages.push_back(
        {"body_kick", [this](StepContext& c) { bodies_.kick(c.dt, setup::to_space(step_gravity(c)), time_); }});
  if (scene_.domain.inflow) stages.push_back({"inflow_velocity", [this](StepContext&) { impose_inflow(0); }});
  stages.push_back({"advance_time", [this](StepContext& c) {
                      time_ += c.dt;
                      ++step_count_;
                    }});
  stages.push_back({"state_check", [this](StepContext&) { check_state(); }});
  if (scene_.solver.shifting != scene::Shifting::none)
    stages.push_back({"particle_shifting", [this](StepContext& c) { shift_particles(c.dt); }});
  return Pipeline(std::move(stages));
}

template <int D>
Stage Wcsph<D>::neighbor_search_stage() {
  const auto search = [this](StepContext& c) { c.report.removed = interactions_.update(fluid_, listing()); };
  if (!density_lists_neighbors()) return {"neighbor_search", search};
  // The density pass lists the pairs as it walks them: the two cannot be timed apart.
  return {std::string("neighbor_search+").append(density_pass_name()), [this, search](StepContext& c) {
            search(c);
            sum_density();
          }};
}

template <int D>
std::vector<Stage> Wcsph<D>::force_stages() {
  std::vector<Stage> stages;
  if (scene_.solver.density == scene::DensityMethod::continuity) {
    stages.push_back({"equation_of_state", [this](StepContext&) { apply_equation_of_state(); }});
  } else if (!density_lists_neighbors()) {
    stages.push_back({std::string(density_pass_name()), [this](StepContext&) { sum_density(); }});
  }
  if (interactions_.contact_count() > 0)
    stages.push_back({"wall_state", [this](StepContext& c) { extrapolate_wall_state(step_gravity(c)); }});
  stages.push_back({"momentum", [this](StepContext& c) { compute_acceleration(step_gravity(c)); }});
  if (!bodies_.empty()) {
    stages.push_back({"body_force", [this](StepContext&) { compute_body_forces(); }});
    stages.push_back({"body_contact", [this](StepContext&) { bodies_.touch(contact_law_, interactions_); }});
  }
  if (tension_) {
    std::string name;
    for (const std::string_view pass : passes::surface_tension_passes(scene_.solver.surface_tension.model)) {
      if (!name.empty()) name += '+';
      name += pass;
    }
    stages.push_back({name, [this](StepContext&) { add_surface_tension(); }});
  }
  return stages;
}

template <int D>
bool Wcsph<D>::density_lists_neighbors() const {
  // As Interactions::update leaves the listing to the next pair walk.
  return interactions_.fluid_grid().skin() > 0 && listing() == Interactions<D>::Listing::in_next_pair_walk;
}

template <int D>
std::string_view Wcsph<D>::density_pass_name() const {
  return phases_ ? "number_density" : "density_summation";
}

template <int D>
Vector<D> Wcsph<D>::step_gravity(const StepContext& context) const {
  // The forces of a step use the gravity at its end: time_ is the start until advance_time.
  return setup::gravity_at<D>(scene_, time_ + context.dt);
}

template <int D>
bool Wcsph<D>::steer(const Eigen::Vector3d& displacement) {
  return moving_walls_.steer(displacement, static_cast<Real>(scene_.particle_spacing));
}

template <int D>
bool Wcsph<D>::set_gravity(const Vector<D>& gravity) {
  for (int d = 0; d < D; ++d) scene_.gravity[d] = static_cast<double>(gravity[d]);
  return true;
}

template <int D>
bool Wcsph<D>::set_kinematic_viscosity(Real viscosity) {
  if (phases_ || scene_.solver.viscosity != scene::ViscosityModel::laminar) return false;
  kinematic_viscosity_ = viscosity;
  time_step_rule_.kinematic_viscosity = viscosity;
  return true;
}

template <int D>
Vector<D> Wcsph<D>::gravity() const {
  return setup::gravity_at<D>(scene_, time_);
}

template <int D>
typename Interactions<D>::Listing Wcsph<D>::listing() const {
  // Summation density is the first pass to walk the pairs after an update, and needs only r²: it
  // lists them (walk_fluid_pairs).
  using Listing = typename Interactions<D>::Listing;
  return scene_.solver.density == scene::DensityMethod::summation ? Listing::in_next_pair_walk : Listing::now;
}

template <int D>
void Wcsph<D>::set_hydrostatic_density() {
  // Continuity density starts from the fluid at rest under gravity: ρ from the equation of state
  // at the hydrostatic pressure (plus the background pressure).
  auto density = fluid_[fluid_fields_.density];
  setup::hydrostatic_pressure<D>(fluid_, setup::hydrostatic_part<D>(scene_, gravity()),
                                 static_cast<Real>(scene_.particle_spacing), eos_.rest_density(), density);
  const Real surface_pressure = eos_.pressure(eos_.rest_density());  // the background pressure
  for_each_particle(fluid_.size(), [&](std::size_t i) { density[i] = eos_.density(surface_pressure + density[i]); });
}

template <int D>
Real Wcsph<D>::pressure_at(const EquationOfState& eos, Real rho) const {
  const Real p = eos.pressure(rho);
  return scene_.solver.clamp_negative_pressure ? std::max(p, Real(0)) : p;
}

template <int D>
void Wcsph<D>::sum_density() {
  auto pressure = fluid_[fluid_fields_.pressure];
  const auto set_pressure = [&](std::size_t i, Real rho) { pressure[i] = pressure_at(eos_, rho); };
  const auto set_phase_pressure = [&, phase = phases_ ? std::as_const(fluid_)[fluid_fields_.phase]
                                                      : std::span<const Index>{}](std::size_t i, Real rho) {
    pressure[i] = pressure_at(phases_->table[phase[i]].eos, rho);
  };
  if (phases_) {
    passes::density_summation<D, true>(kernel_, fluid_, fluid_fields_, interactions_, set_phase_pressure);
  } else {
    passes::density_summation<D>(kernel_, fluid_, fluid_fields_, interactions_, set_pressure);
  }
}

template <int D>
void Wcsph<D>::apply_equation_of_state() {
  auto pressure = fluid_[fluid_fields_.pressure];
  const auto density = std::as_const(fluid_)[fluid_fields_.density];
  for_each_particle(fluid_.size(), [&](std::size_t i) { pressure[i] = pressure_at(eos_, density[i]); });
}

template <int D>
void Wcsph<D>::extrapolate_wall_state(const Vector<D>& gravity) {
  // Several fluids: the walls keep ρ0 (their volume enters the momentum pass, not their density).
  const passes::WallPressureExtrapolation<D> wall_pressure{phases_ ? nullptr : &eos_, gravity,
                                                           scene_.solver.clamp_negative_pressure};
  passes::wall_states<D>(kernel_, interactions_, fluid_, fluid_fields_, &wall_pressure);
}

template <int D>
void Wcsph<D>::compute_acceleration(const Vector<D>& gravity) {
  const passes::ViscositySettings viscosity =
      passes::viscosity_settings(scene_, eos_.sound_speed(), kinematic_viscosity_, smoothing_length_);
  const passes::ArtificialStressSettings stress{static_cast<Real>(scene_.solver.artificial_stress),
                                                1 / kernel_.value(static_cast<Real>(scene_.particle_spacing))};
  if (scene_.solver.riemann_solver == scene::RiemannSolver::low_dissipation) {
    compute_riemann_acceleration(viscosity, gravity);
    return;
  }
  const passes::MultiphaseTerms multiphase = multiphase_terms();
  const std::span<Real> scratch =
      phases_ ? std::span<Real>{} : interactions_.pass_scratch(fluid_.size() + interactions_.contact_particle_count());
  passes::fluid_acceleration<D>(kernel_, viscosity, stress, fluid_, fluid_fields_, interactions_, gravity, scratch,
                                phases_ ? &multiphase : nullptr);
}

template <int D>
void Wcsph<D>::compute_riemann_acceleration(const passes::ViscositySettings& viscosity, const Vector<D>& gravity) {
  const passes::RiemannSettings<D> riemann{eos_.sound_speed(), eos_.rest_density(), gravity};
  std::span<const Real> correction;
  if (scene_.solver.kernel_gradient_correction) {
    const std::span<Real> table = interactions_.pass_scratch(fluid_.size() * D * D);
    passes::kernel_gradient_correction<D>(kernel_, fluid_, fluid_fields_, interactions_, table);
    correction = table;
  }
  // The viscosity model and the correction picked once per pass, outside the particle loop.
  const auto run = [&]<scene::ViscosityModel Model>() {
    if (correction.empty()) {
      passes::riemann_momentum<D, Model, false>(kernel_, viscosity, riemann, fluid_, fluid_fields_, interactions_, {});
    } else {
      passes::riemann_momentum<D, Model, true>(kernel_, viscosity, riemann, fluid_, fluid_fields_, interactions_,
                                               correction);
    }
  };
  if (viscosity.model == scene::ViscosityModel::artificial) {
    run.template operator()<scene::ViscosityModel::artificial>();
  } else {
    run.template operator()<scene::ViscosityModel::laminar>();
  }
}

template <int D>
passes::MultiphaseTerms Wcsph<D>::multiphase_terms() const {
  if (!phases_) return {};
  return {fluid_[fluid_fields_.phase], phases_->table, setup::wall_volume<D>(interactions_, eos_.rest_density())};
}

template <int D>
void Wcsph<D>::compute_body_forces() {
  const passes::ViscositySettings viscosity =
      passes::viscosity_settings(scene_, eos_.sound_speed(), kinematic_viscosity_, smoothing_length_);
  const passes::MultiphaseTerms multiphase = multiphase_terms();
  bodies_.for_each_force_field([&](const Contact<D>& body, VectorView<D> force) {
    passes::body_force<D>(kernel_, viscosity, body, fluid_, fluid_fields_, force, phases_ ? &multiphase : nullptr);
  });
  bodies_.sum_forces();
}

template <int D>
Real Wcsph<D>::pair_strength(Index a, Index b) const {
  if (!tension_ || tension_->pair_strength.empty()) return 0;
  return tension_->pair_strength[a * tension_->phase_count + b];
}

template <int D>
Real Wcsph<D>::wall_strength(Index a) const {
  if (!tension_ || tension_->wall_strength.empty()) return 0;
  return tension_->wall_strength[a];
}

template <int D>
void Wcsph<D>::add_surface_tension() {
  const std::span<const Index> phase = phases_ ? std::as_const(fluid_)[fluid_fields_.phase] : std::span<const Index>{};
  passes::surface_tension<D>(kernel_, scene_.solver.surface_tension.model, *tension_, fluid_, fluid_fields_, phase,
                             interactions_);
}

template <int D>
void Wcsph<D>::integrate_density(const Vector<D>& gravity, Real dt) {
  compute_density_rate(setup::hydrostatic_part<D>(scene_, gravity));
  auto density = fluid_[fluid_fields_.density];
  const auto rate = std::as_const(fluid_)[fluid_fields_.density_rate];
  for_each_particle(fluid_.size(), [&](std::size_t i) { density[i] += dt * rate[i]; });
}

template <int D>
bool Wcsph<D>::holds_free_surface_density() const {
  return scene_.solver.density == scene::DensityMethod::continuity && scene_.solver.clamp_negative_pressure;
}

template <int D>
void Wcsph<D>::hold_free_surface_density() {
  // Lind et al. 2012's free-surface threshold, ∇·r < D − ½, as for particle shifting.
  passes::hold_free_surface_density<D>(kernel_, fluid_, fluid_fields_, interactions_, Real(D) - Real(0.5),
                                       eos_.rest_density(), interactions_.pass_scratch(fluid_.size()));
}

template <int D>
void Wcsph<D>::compute_density_rate(const Vector<D>& gravity) {
  if (scene_.solver.riemann_solver == scene::RiemannSolver::low_dissipation) {
    const passes::RiemannSettings<D> riemann{eos_.sound_speed(), eos_.rest_density(), gravity};
    passes::riemann_continuity<D>(kernel_, riemann, fluid_, fluid_fields_, interactions_);
    return;
  }
  const passes::DensityDiffusion<D> diffusion{eos_, gravity, static_cast<Real>(scene_.solver.delta_sph),
                                              eos_.sound_speed()};
  passes::continuity<D>(kernel_, fluid_, fluid_fields_, interactions_, diffusion.delta > 0 ? &diffusion : nullptr);
}

template <int D>
StepReport Wcsph<D>::step() {
  StepContext context;
  // The acoustic limit counts the bodies' and the moving walls' particles as the fluid's (a falling
  // body meeting still water, a fan's tips).
  const Real fastest = std::max({max_speed_, max_body_speed_, moving_walls_.max_particle_speed()});
  context.report.time_step = choose_time_step(time_step_rule_, fastest, max_acceleration_);
  last_time_step_ = context.report.time_step;
  context.dt = context.report.time_step.dt;
  pipeline_.run(context);
  return context.report;
}

template <int D>
void Wcsph<D>::kick_drift(Real dt) {
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

template <int D>
void Wcsph<D>::kick(Real dt) {
  auto v = fluid_[fluid_fields_.velocity];
  const auto a = std::as_const(fluid_)[fluid_fields_.acceleration];
  for_each_particle(fluid_.size(), [&](std::size_t i) { v.set(i, v[i] + (dt / 2) * a[i]); });
}

template <int D>
void Wcsph<D>::inject_phase() {
  const Index phase = static_cast<Index>(*scene_.domain.inflow->phase);
  passes::inject_phase<D>(static_cast<Real>(scene_.domain.box.max[0]), phase, phases_->table[phase].mass, fluid_,
                          fluid_fields_);
}

template <int D>
void Wcsph<D>::impose_inflow(Real drift_time) {
  const auto& inflow = scene_.domain.inflow;
  passes::impose_inflow_velocity<D>(static_cast<Real>(scene_.domain.box.min[0]), static_cast<Real>(inflow->length),
                                    static_cast<Real>(inflow->velocity), drift_time, fluid_, fluid_fields_);
}

template <int D>
bool Wcsph<D>::injects_phase() const {
  return phases_ && scene_.domain.inflow && scene_.domain.inflow->phase;
}

template <int D>
void Wcsph<D>::shift_particles(Real dt) {
  passes::shift_particles<D>(kernel_, static_cast<Real>(scene_.particle_spacing), smoothing_length_, max_speed_, dt,
                             fluid_, fluid_fields_, interactions_);
}

template <int D>
double Wcsph<D>::bytes_per_particle() const {
  return setup::bytes_per_particle<D>(fluid_, interactions_);
}

template <int D>
MemoryUsage Wcsph<D>::memory_usage() const {
  return setup::memory_usage<D>(fluid_, interactions_);
}

template <int D>
void Wcsph<D>::check_state() {
  const Real rho0 = eos_.rest_density();
  const Real ratio = static_cast<Real>(scene_.solver.max_density_ratio);
  StateLimits limits;
  limits.min_density = scene_.solver.density == scene::DensityMethod::continuity ? rho0 / ratio : Real(0);
  limits.max_density = ratio * rho0;
  limits.density_band =
      "outside [rho0/" + format_number(ratio) + ", " + format_number(ratio) + " rho0], solver.max_density_ratio";
  limits.max_speed = static_cast<Real>(scene_.solver.max_mach_number) * eos_.sound_speed();
  limits.speed_bound = "faster than " + format_number(scene_.solver.max_mach_number) +
                       " x c0 = " + format_number(limits.max_speed) + " m/s, solver.max_mach_number";
  limits.note = [this] { return time_step_note(); };
  if (phases_) bound_density_by_phase(limits, rho0, *phases_, std::as_const(fluid_)[fluid_fields_.phase]);
  const StateMaxima maxima = check_fluid_state<D>(fluid_, fluid_fields_, limits, step_count_, time_);
  max_speed_ = maxima.speed;
  max_acceleration_ = maxima.acceleration;
  if (!bodies_.empty())
    max_body_speed_ = bodies_.checked_max_particle_speed(limits.max_speed, limits.speed_bound, step_count_, time_);
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

}  // namespace tide
