#pragma once

// IncompressibleSph's member definitions, instantiated once per dimension
// (incompressible_sph_2d.cpp, incompressible_sph_3d.cpp): a file per dimension lets two cores
// share the compile of the passes.

#include "tide/solvers/incompressible_sph.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <functional>
#include <limits>
#include <span>
#include <sstream>
#include <stdexcept>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "passes/continuity.hpp"
#include "passes/density_summation.hpp"
#include "passes/momentum.hpp"
#include "passes/particle_shifting.hpp"
#include "passes/pressure_solve.hpp"
#include "passes/wall_state.hpp"
#include "simulation_setup.hpp"
#include "start_edit.hpp"
#include "state_check.hpp"
#include "tide/core/log.hpp"
#include "tide/core/parallel.hpp"
#include "tide/solvers/capabilities.hpp"
#include "tide/solvers/instability.hpp"

namespace tide {
namespace {

// Iterations each solve makes at least: two for the density solve, one for the divergence solve
// (the loop conditions of Ihmsen et al. 2014, Alg. 1, and Bender & Koschier 2017, Alg. 2–3).
constexpr int min_density_iterations = 2;
constexpr int min_divergence_iterations = 1;

// Chebyshev semi-iterative acceleration of the density solve's projected Jacobi sweeps (Golub &
// Van Loan, Sec. 11.2.8; with projection, Wang 2015, "A Chebyshev semi-iterative approach for
// accelerating projective and position-based dynamics", eq. 12): after `chebyshev_delay` plain
// sweeps, p⁽ᵏ⁺¹⁾ = ω_k (p̂⁽ᵏ⁺¹⁾ − p⁽ᵏ⁻¹⁾) + p⁽ᵏ⁻¹⁾, with p̂ the Jacobi sweep and ω from the
// recurrence of the Chebyshev polynomials for a Jacobi spectral radius ρ. Jacobi corrects one
// kernel support per sweep, so the smooth errors (a whole column's pressure a few percent off)
// take ~(depth/h)² sweeps; Chebyshev takes ~depth/h. ρ below the true radius only slows the
// smoothest modes (|T_k(x/ρ)/T_k(1/ρ)| < 1 for ρ < x < 1); the relaxation keeps the rough modes
// at ≥ −0.5 (effective_relaxation). Measured on the 2D tank, 25 rows, at a mean density error of
// 1e-5: 14 sweeps per step on average (120 at most) against 57 (856) with plain Jacobi, the same
// pressures. The divergence solve keeps plain Jacobi: accelerated, its pressure and the density
// solve's drifted apart in opposite directions (±60% of ρ0 g depth each on the tank).
constexpr Real chebyshev_radius = Real(0.99);
constexpr int chebyshev_delay = 5;

// The conjugate gradients' stopping test (solve()): the error estimate looks `energy_delay`
// iterations ahead, and the pressure's error in the energy norm must be within
// `energy_tolerance` of the step's velocity change, a relative error of the pressure
// acceleration. It applies to the density solve while its held set changed at most
// `max_projections` times. Measured on the 2D dam break (a/Δx = 40, DFSPH, 1 thread): with the
// test on every solve 30 s against 2.9 s before the conjugate gradients (the held set changed at
// nearly every iteration and each solve ran to its cap); 18 s with the limit of 8; 4.8 s with the
// divergence solve on the mean density error alone where it is projected (p ≥ 0). Closed and
// periodic flows keep the test in the divergence solve: the Taylor–Green vortex at 100 across,
// DFSPH, 0.098 without it, 0.015 with it.
constexpr int energy_delay = 3;
constexpr Real energy_tolerance = Real(0.005);
constexpr int restart_interval = 25;
constexpr int max_projections = 8;

// ω_k of the Chebyshev recurrence after `accelerated` accelerated sweeps (Wang 2015, eq. 12).
Real chebyshev_weight(int accelerated, Real previous_weight) {
  constexpr Real rho2 = chebyshev_radius * chebyshev_radius;
  if (accelerated == 0) return 2 / (2 - rho2);
  return 4 / (4 - rho2 * previous_weight);
}

// Sum and largest value of the positive excesses of one sweep, with the particle that has it.
struct ExcessSummary {
  Real sum = 0;
  Real max = 0;
  std::size_t worst = 0;

  static ExcessSummary combine(const ExcessSummary& a, const ExcessSummary& b) {
    const bool b_worse = b.max > a.max;
    return {a.sum + b.sum, b_worse ? b.max : a.max, b_worse ? b.worst : a.worst};
  }
};

std::string percent(double share) {
  std::ostringstream text;
  text.precision(3);
  text << 100 * share << '%';
  return text.str();
}

}  // namespace

template <int D>
IncompressibleSph<D>::IncompressibleSph(const scene::Scene& scene)
    : scene_(scene),
      scheme_(incompressible_scheme(scene.solver.scheme)),
      smoothing_length_(static_cast<Real>(scene.smoothing_ratio * scene.particle_spacing)),
      kernel_(make_kernel<D>(scene.kernel, smoothing_length_)),
      rest_density_(static_cast<Real>(setup::reference_material(scene).rest_density)),
      reference_sound_speed_(setup::reference_sound_speed(setup::reference_material(scene))),
      kinematic_viscosity_(static_cast<Real>(setup::reference_material(scene).kinematic_viscosity)),
      gravity_(setup::gravity_at<D>(scene, scene.time.start)),
      interactions_(setup::grid_domain<D>(scene), kernel_support_factor(scene.kernel) * smoothing_length_,
                    setup::neighbor_skin(scene, kernel_support_factor(scene.kernel) * smoothing_length_)),
      moving_walls_(setup::grid_domain<D>(scene)) {
  if (!(reference_sound_speed_ > 0))
    throw std::invalid_argument(scene.source + ": the material needs a positive sound_speed or max_speed");
  check_capabilities(scene);
  relaxation_ =
      effective_relaxation(scheme_, jacobi_spectral_bound<D>(kernel_.any(), static_cast<Real>(scene.particle_spacing)));
  if (scene::fluid_material_count(scene) > 1) phases_ = setup::make_phases<D>(scene, kernel_.any());
  const Real particle_mass = setup::particle_mass<D>(scene, kernel_.any(), rest_density_);
  fluid_ = setup::make_fluid<D>(scene, particle_mass, rest_density_, fluid_fields_, phases());
  fluid_fields_.density_rate = fluid_.add_scalar("density_rate");
  solve_fields_ = {fluid_.add_scalar("pressure_factor"), fluid_.add_vector("predicted_velocity"),
                   fluid_.add_scalar("density_excess"), std::nullopt};
  if (scheme_.divergence_solve) solve_fields_.divergence_pressure = fluid_.add_scalar("divergence_pressure");
  setup::add_wall_contacts<D>(scene, particle_mass, rest_density_, interactions_, moving_walls_, nullptr);
  // The first solve starts from the pressure of the fluid at rest: a Jacobi sweep carries
  // information about one kernel support, so from zero a deep column would need of the order of
  // (depth / h)² sweeps to take its own weight.
  if (phases_) {
    const auto phase = std::as_const(fluid_)[fluid_fields_.phase];
    std::vector<Real> rest_densities(fluid_.size());
    for (std::size_t i = 0; i < fluid_.size(); ++i) rest_densities[i] = phases_->table[phase[i]].rest_density;
    setup::layered_hydrostatic_pressure<D>(fluid_, setup::hydrostatic_part<D>(scene_, gravity_),
                                           static_cast<Real>(scene.particle_spacing), rest_densities,
                                           fluid_[fluid_fields_.pressure]);
  } else {
    setup::hydrostatic_pressure<D>(fluid_, setup::hydrostatic_part<D>(scene_, gravity_),
                                   static_cast<Real>(scene.particle_spacing), rest_density_,
                                   fluid_[fluid_fields_.pressure]);
  }

  time_step_rule_.smoothing_length = smoothing_length_;
  time_step_rule_.sound_speed = 0;
  // Until the flow moves, the velocity limit assumes a tenth of the expected maximum speed c0/10.
  time_step_rule_.speed_floor = reference_sound_speed_ / 100;
  // The viscous forces are explicit: without the acoustic limit, which bounds WCSPH's step far
  // below it, the artificial viscosity needs its own limit, from its shear viscosity
  // ν = α c0 h / (2 (d + 2)) (Monaghan 2005, Sec. 4.4).
  time_step_rule_.kinematic_viscosity =
      scene.solver.viscosity == scene::ViscosityModel::laminar
          ? (phases_ ? phases_->largest_kinematic_viscosity : kinematic_viscosity_)
          : static_cast<Real>(scene.solver.alpha) * reference_sound_speed_ * smoothing_length_ / (2 * (D + 2));
  time_step_rule_.cfl = static_cast<Real>(scene.solver.cfl);
  time_step_rule_.viscous_number = static_cast<Real>(scene.solver.viscous_number);
  time_step_rule_.force_number = static_cast<Real>(scene.solver.force_number);
  time_ = scene.time.start;

  if (!moving_walls_.empty()) moving_walls_.move_to(0, step_count_, time_);  // their velocity at the start
  start();
  pipeline_ = build_pipeline();
}

template <int D>
void IncompressibleSph<D>::edit_start(FunctionRef<void(ParticleSet<D>&)> edit) {
  setup::edit_start_fields<D>(step_count_, fluid_, edit);
  start();
}

template <int D>
void IncompressibleSph<D>::start() {
  std::vector<Stage> stages{neighbor_search_stage()};
  for (Stage& stage : density_stages()) stages.push_back(std::move(stage));
  for (Stage& stage : force_stages()) stages.push_back(std::move(stage));
  StepContext at_start;
  Pipeline(std::move(stages)).run(at_start);
  check_state();
}

template <int D>
bool IncompressibleSph<D>::steer(const Eigen::Vector3d& displacement) {
  return moving_walls_.steer(displacement, static_cast<Real>(scene_.particle_spacing));
}

template <int D>
bool IncompressibleSph<D>::set_gravity(const Vector<D>& gravity) {
  for (int d = 0; d < D; ++d) scene_.gravity[d] = static_cast<double>(gravity[d]);
  gravity_ = setup::gravity_at<D>(scene_, time_);
  return true;
}

template <int D>
bool IncompressibleSph<D>::set_kinematic_viscosity(Real viscosity) {
  if (phases_ || scene_.solver.viscosity != scene::ViscosityModel::laminar) return false;
  kinematic_viscosity_ = viscosity;
  time_step_rule_.kinematic_viscosity = viscosity;
  return true;
}

template <int D>
Pipeline IncompressibleSph<D>::build_pipeline() {
  std::vector<Stage> stages;
  stages.push_back({"predict_velocity", [this](StepContext& c) { predict_velocity(c.dt); }});
  stages.push_back({"density_solve", [this](StepContext& c) {
                      c.report.density_solve =
                          solve(fluid_fields_.pressure, Target::density, scheme_.warm_start, gravity_, c.dt);
                    }});
  // A solve that diverged leaves velocities that would carry particles out of the domain in the
  // drift, where the neighbour search would remove them as lost: the state is checked first.
  stages.push_back({"state_check_before_drift", [this](StepContext&) { check_state(); }});
  stages.push_back({"drift", [this](StepContext& c) { drift(c.dt); }});
  if (scene_.solver.shifting != scene::Shifting::none)
    stages.push_back({"particle_shifting", [this](StepContext& c) { shift_particles(c.dt); }});
  if (!moving_walls_.empty()) {
    stages.push_back({"prescribed_motion", [this](StepContext& c) {
                        const double end = time_ + c.dt;  // where the walls are at the step's end
                        moving_walls_.move_to(end - scene_.time.start, step_count_ + 1, end);
                      }});
  }
  stages.push_back(neighbor_search_stage());
  for (Stage& stage : density_stages()) stages.push_back(std::move(stage));
  if (scheme_.divergence_solve) {
    stages.push_back(
        {"divergence_solve", [this](StepContext& c) { c.report.divergence_solve = solve_divergence(c.dt); }});
  }
  stages.push_back({"advance_time", [this](StepContext& c) {
                      time_ += c.dt;
                      ++step_count_;
                      gravity_ = setup::gravity_at<D>(scene_, time_);
                    }});
  for (Stage& stage : force_stages()) stages.push_back(std::move(stage));
  stages.push_back({"state_check", [this](StepContext& c) {
                      check_state();
                      count_failures(c.report);
                    }});
  return Pipeline(std::move(stages));
}

template <int D>
Stage IncompressibleSph<D>::neighbor_search_stage() {
  return {"neighbor_search", [this](StepContext& c) { c.report.removed = interactions_.update(fluid_); }};
}

template <int D>
std::vector<Stage> IncompressibleSph<D>::density_stages() {
  std::vector<Stage> stages;
  stages.push_back({"gradient_cache", [this](StepContext&) { cache_gradients(); }});
  stages.push_back({phases_ ? "number_density" : "density_summation", [this](StepContext&) { sum_density(); }});
  stages.push_back({"pressure_factor", [this](StepContext&) { compute_pressure_factor(); }});
  return stages;
}

template <int D>
std::vector<Stage> IncompressibleSph<D>::force_stages() {
  std::vector<Stage> stages;
  // Free-slip walls take no viscous force, so their velocity is not needed.
  if (interactions_.has_viscous_contact())
    stages.push_back({"wall_state", [this](StepContext&) { extrapolate_wall_velocity(); }});
  stages.push_back({"non_pressure_momentum", [this](StepContext&) { compute_non_pressure_acceleration(); }});
  return stages;
}

template <int D>
void IncompressibleSph<D>::cache_gradients() {
  interactions_.cache_gradients(kernel_, std::as_const(fluid_)[fluid_fields_.position]);
  uniform_masses_ = !phases_ && passes::masses_are_uniform(std::as_const(fluid_)[fluid_fields_.mass]);
  for (std::size_t k = 0; k < interactions_.contact_count(); ++k) {
    const Contact<D>& contact = interactions_.contact(k);
    uniform_masses_ = uniform_masses_ && passes::masses_are_uniform(contact.particles()[contact.fields().mass]);
  }
}

template <int D>
void IncompressibleSph<D>::sum_density() {
  const auto nothing_more = [](std::size_t, Real) {};
  if (phases_) {
    passes::density_summation<D, true>(kernel_, fluid_, fluid_fields_, interactions_, nothing_more);
  } else {
    passes::density_summation<D>(kernel_, fluid_, fluid_fields_, interactions_, nothing_more);
  }
}

template <int D>
void IncompressibleSph<D>::compute_pressure_factor() {
  if (phases_) {
    passes::pressure_factor<D, true>(kernel_, fluid_, fluid_fields_, solve_fields_, interactions_);
  } else {
    passes::pressure_factor<D>(kernel_, fluid_, fluid_fields_, solve_fields_, interactions_);
  }
}

template <int D>
void IncompressibleSph<D>::extrapolate_wall_velocity() {
  passes::wall_states<D>(kernel_, interactions_, fluid_, fluid_fields_, nullptr);
}

template <int D>
void IncompressibleSph<D>::compute_non_pressure_acceleration() {
  const passes::ViscositySettings viscosity =
      passes::viscosity_settings(scene_, reference_sound_speed_, kinematic_viscosity_, smoothing_length_);
  const std::span<const Index> phase = phases_ ? std::as_const(fluid_)[fluid_fields_.phase] : std::span<const Index>{};
  passes::MultiphaseTerms multiphase;
  if (phases_) multiphase = {phase, phases_->table, setup::wall_volume<D>(interactions_, rest_density_)};
  passes::fluid_acceleration<D, false>(kernel_, viscosity, {}, fluid_, fluid_fields_, interactions_, gravity_, {},
                                       phases_ ? &multiphase : nullptr);
}

template <int D>
SolveReport IncompressibleSph<D>::solve(ScalarField pressure_field, Target target, Real warm_start,
                                        const Vector<D>& wall_gravity, Real dt) {
  const bool density_target = target == Target::density;
  const Real threshold =
      static_cast<Real>(density_target ? scene_.solver.max_density_error : scene_.solver.max_divergence_error);
  const int min_iterations = density_target ? min_density_iterations : min_divergence_iterations;
  const int max_iterations = scene_.solver.max_solver_iterations;
  // clamp_negative_pressure: false marks a closed or periodic flow, whose pressure takes both signs.
  const bool two_sided = !scene_.solver.clamp_negative_pressure;
  auto pressure = fluid_[pressure_field];
  for_each_particle(fluid_.size(), [&](std::size_t i) { pressure[i] *= warm_start; });
  const auto mean_pressure = [&] {
    return reduce(
               fluid_.size(), Real(0), [&](std::size_t i) { return pressure[i]; }, std::plus<>{}) /
           std::max<Real>(Real(fluid_.size()), 1);
  };
  const Real mean_before = two_sided && phases_ ? mean_pressure() : Real(0);

  const auto density = std::as_const(fluid_)[fluid_fields_.density];
  const auto rate = std::as_const(fluid_)[fluid_fields_.density_rate];
  const auto factor = std::as_const(fluid_)[solve_fields_.factor];
  auto excess = fluid_[solve_fields_.density_excess];
  const Real count = static_cast<Real>(std::max<std::size_t>(fluid_.size(), 1));
  // Several fluids: each particle's density is driven to the rest density of its phase, and its
  // excess weighs in the error (and the mean of a closed domain) relative to that, scaled to ρ0
  // of the reference material (weight ρ0 / ρ0_phase; 1 for a single fluid).
  const std::span<const Index> phase = phases_ ? std::as_const(fluid_)[fluid_fields_.phase] : std::span<const Index>{};
  std::vector<Real> phase_weight;
  if (phases_)
    for (const Phase& p : phases_->table) phase_weight.push_back(rest_density_ / p.rest_density);
  const auto rest_density_at = [&](std::size_t i) {
    return phase.empty() ? rest_density_ : phases_->table[phase[i]].rest_density;
  };
  const auto weight_at = [&](std::size_t i) { return phase.empty() ? Real(1) : phase_weight[phase[i]]; };
  const bool conjugate = conjugate_gradients();
  if (!conjugate) iterate_.resize(fluid_.size());
  bool symmetric_walls = conjugate && interactions_.contact_count() > 0;
  if (symmetric_walls) adjoint_.resize(fluid_.size());
  pressure_term_.resize(phases_ ? 0 : fluid_.size());
  Real weight = 1;
  SolveReport report;
  // The error of the velocities `velocity` now holds (the fluid's after a sweep, or the predicted
  // ones): stores ρ*_i − ρ0 = ρ_i + Δt Dρ_i/Dt − ρ0 after the step (density solve), or Δt Dρ_i/Dt
  // (divergence solve), in `excess`, and its mean deviation in `report`.
  const auto measure = [&](VectorField velocity, bool unpressed) {
    FluidFields<D> moving = fluid_fields_;
    moving.velocity = velocity;
    if (phases_) {
      passes::continuity<D, true>(kernel_, fluid_, moving, interactions_, nullptr);
    } else if (uniform_masses_) {
      passes::continuity<D, false, true>(kernel_, fluid_, moving, interactions_, nullptr);
    } else {
      passes::continuity<D>(kernel_, fluid_, moving, interactions_, nullptr);
    }
    for_each_particle(fluid_.size(), [&](std::size_t i) {
      excess[i] = (density_target ? density[i] - rest_density_at(i) : Real(0)) + dt * rate[i];
    });
    // One fluid: the walls' term that makes the pressure equation symmetric (conjugate gradients).
    if (symmetric_walls) {
      passes::wall_pressure_adjoint<D>(kernel_, interactions_, fluid_, fluid_fields_, velocity, wall_adjoint_,
                                       adjoint_);
      for_each_particle(fluid_.size(), [&](std::size_t i) { excess[i] += dt * adjoint_[i]; });
    }
    // A closed or periodic domain fixes the fluid's volume: no pressure changes the mean of ρ*,
    // which drifts from ρ0 as the particle arrangement changes, so the compatible target is
    // ρ* = mean ρ* (as the source of a Poisson problem with periodic or Neumann boundaries is
    // taken mean-free).
    if (two_sided) {
      const Real mean =
          reduce(
              fluid_.size(), Real(0), [&](std::size_t i) { return weight_at(i) * excess[i]; }, std::plus<>{}) /
          count;
      for_each_particle(fluid_.size(), [&](std::size_t i) { excess[i] -= mean / weight_at(i); });
    }
    // With p ≥ 0 the error is that of the complementarity problem p ≥ 0, ρ* ≤ ρ0,
    // p (ρ* − ρ0) = 0: where p > 0 any deviation, where p = 0 compression only (a free surface
    // may expand).
    const ExcessSummary summary = reduce(
        fluid_.size(), ExcessSummary{},
        [&](std::size_t i) {
          const Real e = weight_at(i) * excess[i];
          const bool pressed = two_sided || (!unpressed && pressure[i] > 0);
          const Real deviation = pressed ? std::abs(e) : std::max(e, Real(0));
          return ExcessSummary{deviation, deviation, i};
        },
        ExcessSummary::combine);
    report.error = static_cast<double>(summary.sum / (count * rest_density_));
    report.converged = report.error <= threshold;
    worst_particle_ = summary.worst;
    worst_excess_ = summary.max;
  };
  // The sweeps, then (after sweeps that stopped at their minimum) the fluid without pressure.
  [&] {
    // The walls' pressure is clamped at 0 like the fluid's (a wall particle above the free surface
    // extrapolates to p < 0), except in the conjugate gradients' sweeps, which must be affine in p:
    // their last sweep, for the pressure kept, clamps.
    const passes::WallPressureExtrapolation<D> wall_rule{nullptr, wall_gravity, !two_sided};
    const passes::WallPressureExtrapolation<D> affine_wall_rule{nullptr, wall_gravity, false};
    FluidFields<D> solved = fluid_fields_;
    solved.pressure = pressure_field;
    // One sweep: the velocity the pressure now in `pressure` (and the walls' extrapolated from
    // it) gives, and its density error in `excess`.
    const auto sweep = [&](bool affine = false) {
      passes::wall_states<D>(kernel_, interactions_, fluid_, solved, affine ? &affine_wall_rule : &wall_rule);
      if (phases_) {
        passes::pressure_velocity<D, true>(kernel_, fluid_, fluid_fields_, solve_fields_, pressure, interactions_, dt,
                                           pressure_term_);
      } else if (uniform_masses_) {
        passes::pressure_velocity<D, false, true>(kernel_, fluid_, fluid_fields_, solve_fields_, pressure,
                                                  interactions_, dt, pressure_term_);
      } else {
        passes::pressure_velocity<D>(kernel_, fluid_, fluid_fields_, solve_fields_, pressure, interactions_, dt,
                                     pressure_term_);
      }
      measure(fluid_fields_.velocity, false);
      ++report.sweeps;
    };
    // Projected: p stays ≥ 0, so the fluid takes no tension (Ihmsen et al. 2014, Alg. 1), unless
    // the scene lets the pressure take both signs.
    const Real floor = two_sided ? -std::numeric_limits<Real>::infinity() : Real(0);
    int least_iterations = min_iterations;
    // Σ_i |v_i − v*_i|²: the squared energy norm of the pressure the fluid now has (see
    // conjugate_gradients below).
    const auto pressure_energy = [&] {
      const auto v = std::as_const(fluid_)[fluid_fields_.velocity];
      const auto predicted = std::as_const(fluid_)[solve_fields_.predicted_velocity];
      return reduce(
          fluid_.size(), Real(0), [&](std::size_t i) { return squared_norm<D>(Vector<D>(v[i] - predicted[i])); },
          std::plus<>{});
    };
    Real accuracy = 0;  // tolerance² × reference energy of the conjugate gradients' stopping test
    // Projected Jacobi sweeps, the density solve's Chebyshev-accelerated, from the pressure in
    // `pressure` (its velocity and error already measured) until the threshold is met.
    const auto jacobi = [&] {
      const int first = report.iterations;
      while (!((report.converged && report.iterations >= min_iterations) || report.iterations >= max_iterations)) {
        const int done = report.iterations - first;
        const bool accelerate = density_target && done >= chebyshev_delay;
        if (accelerate) weight = chebyshev_weight(done - chebyshev_delay, weight);
        for_each_particle(fluid_.size(), [&](std::size_t i) {
          const Real step = std::max(pressure[i] + relaxation_ * factor[i] * excess[i] / (dt * dt), floor);
          const Real before = pressure[i];
          pressure[i] = accelerate ? std::max(weight * (step - iterate_[i]) + iterate_[i], floor) : step;
          iterate_[i] = before;
        });
        ++report.iterations;
        sweep();
      }
    };
    if (!conjugate) {
      sweep();
      jacobi();
    } else {
      // Conjugate gradients on the pressure equation A p = b, ρ* − ρ0 = b − A p (Hestenes &
      // Stiefel 1952; preconditioned, Saad 2003, Alg. 9.1), in the unknowns π_i = p_i / ρ_i²: the
      // sweep's velocity is v = v* − Δt G π and its density error ρ − ρ0 + Δt D v, with D the
      // adjoint of G (Σ_i q_i (D a)_i = Σ_i a_i · (G q)_i for one particle mass, the wall terms
      // with the particle's own π included; the walls' extrapolated pressure with its adjoint,
      // passes::wall_pressure_adjoint), so A = Δt² D G is symmetric and positive (semi)definite.
      // A is applied as the difference of two sweeps (the sweep is affine in p while the walls'
      // pressure is not clamped), M = diag(A) (the Jacobi factor α_i) preconditions it.
      // π·A π = Σ_i |Δt (G π)_i|² = Σ_i |v_i − v*_i|²: the energy norm of a
      // pressure error is the velocity error it makes. Its square for iterate k is bounded below
      // by Σ_{j=k}^{k+d−1} α_j r_j·z_j (Strakoš & Tichý 2002, eq. 4.8), known d iterations
      // later; the solve goes on until that is within `energy_tolerance` of the step's velocity
      // change Σ_i (|Δt a_i|² + |v_i − v*_i|²) as well as under the mean-density threshold. The
      // mean density error alone does not see a pressure that is uniformly a few percent off: it
      // only accelerates the column as a whole and compresses the bottom row (docs/validation.md).
      const std::size_t n = fluid_.size();
      sweep(true);
      // The active set: held at p = 0 are the particles a projected Jacobi sweep would leave
      // without pressure (at the free surface, under-dense where the kernel is truncated).
      held_.resize(n);
      const bool released = reduce(
          n, false,
          [&](std::size_t i) {
            held_[i] = !two_sided && pressure[i] + factor[i] * excess[i] / (dt * dt) <= 0;
            const bool change = held_[i] && pressure[i] != 0;
            if (held_[i]) pressure[i] = 0;
            return change;
          },
          std::logical_or<>{});
      if (released) sweep(true);
      const double start_error = report.error;
      start_.assign(pressure.begin(), pressure.end());
      iterate_.assign(pressure.begin(), pressure.end());
      residual_.assign(excess.begin(), excess.end());
      direction_.assign(n, Real(0));
      const auto a = std::as_const(fluid_)[fluid_fields_.acceleration];
      const Real change =
          pressure_energy() + dt * dt *
                                  reduce(
                                      n, Real(0), [&](std::size_t i) { return squared_norm<D>(a[i]); }, std::plus<>{});
      // DFSPH's divergence solve, whose own pressure is small at rest, measures against the step's
      // density solve.
      const Real reference = density_target ? change : std::max(change, reference_energy_);
      if (density_target) reference_energy_ = change;
      accuracy = energy_tolerance * energy_tolerance * reference;
      std::array<Real, energy_delay> recent{};  // α_j r_j·z_j of the last `energy_delay` iterations
      Real previous_rz = 0;
      int run = 0;          // iterations since the gradients (re)started
      int projections = 0;  // restarts for particles that joined the held set
      Real last_restart_error = std::numeric_limits<Real>::infinity();
      least_iterations = energy_delay;
      const auto mean_error = [&] {
        return reduce(
                   n, Real(0),
                   [&](std::size_t i) {
                     const bool pressed = two_sided || iterate_[i] > 0;
                     return pressed ? std::abs(residual_[i]) : std::max(residual_[i], Real(0));
                   },
                   std::plus<>{}) /
               (count * rest_density_);
      };
      const Real inverse_dt2 = 1 / (dt * dt);
      while (true) {
        Real estimate = 0;
        for (const Real term : recent) estimate += term;
        // The estimate holds for one system: while the held set changes from restart to restart
        // (a flow whose free surface moves, rather than water at rest), past `max_projections`
        // restarts the mean density threshold alone decides.
        const bool accurate = (!density_target && !two_sided) || projections > max_projections ||
                              (run >= energy_delay && estimate <= accuracy);
        // Half the cap at most, leaving the rest to the projected Jacobi sweeps below where the
        // gradients did not meet the threshold (the held set far from the solution's, in a
        // column's first steps).
        if ((accurate && mean_error() <= threshold) || 2 * report.iterations >= max_iterations) break;
        const Real rz = reduce(
            n, Real(0),
            [&](std::size_t i) {
              return held_[i] ? Real(0)
                              : factor[i] * inverse_dt2 * residual_[i] * residual_[i] / (density[i] * density[i]);
            },
            std::plus<>{});
        if (!(rz > 0)) break;
        const Real beta = run == 0 ? Real(0) : rz / previous_rz;
        for_each_particle(n, [&](std::size_t i) {
          const Real z = held_[i] ? Real(0) : factor[i] * inverse_dt2 * residual_[i];
          direction_[i] = z + beta * direction_[i];
          pressure[i] = iterate_[i] + direction_[i];
        });
        sweep(true);  // at p + d: A d = r − (ρ* − ρ0 there)
        const Real curvature = reduce(
            n, Real(0),
            [&](std::size_t i) {
              return held_[i] ? Real(0) : direction_[i] * (residual_[i] - excess[i]) / (density[i] * density[i]);
            },
            std::plus<>{});
        if (!(curvature > 0)) break;
        const Real alpha = rz / curvature;
        for_each_particle(n, [&](std::size_t i) {
          iterate_[i] += alpha * direction_[i];
          residual_[i] -= alpha * (residual_[i] - excess[i]);
        });
        recent[static_cast<std::size_t>(run % energy_delay)] = alpha * rz;
        previous_rz = rz;
        ++report.iterations;
        ++run;
        // A particle the step took below p = 0 joins the held ones, at p = 0, and the gradients
        // start again from the residual there (an active-set method: Nocedal & Wright 2006,
        // Sec. 16.5, with restarts as in Polyak 1969). Every `restart_interval` iterations they
        // start again from the residual measured afresh, which the recurrence drifts from (the
        // walls' part of A is symmetric only up to the rounding of its two gathers, and the
        // Jacobi factor ignores it).
        const bool projected = !two_sided && density_target &&
                               reduce(
                                   n, false,
                                   [&](std::size_t i) {
                                     if (held_[i] || iterate_[i] >= 0) return false;
                                     iterate_[i] = 0;
                                     held_[i] = 1;
                                     return true;
                                   },
                                   std::logical_or<>{});
        if (!projected && run % restart_interval != 0) continue;
        for_each_particle(n, [&](std::size_t i) { pressure[i] = iterate_[i]; });
        sweep(true);
        residual_.assign(excess.begin(), excess.end());
        recent.fill(0);
        run = 0;
        if (projected) ++projections;
        // Gradients that no longer lower the error (held particles that the flow compresses
        // again, whose p = 0 then misses the complementarity conditions) hand over to the
        // projected Jacobi sweeps below.
        const Real restart_error = static_cast<Real>(report.error);
        if (!projected && restart_error > Real(0.9) * last_restart_error) break;
        last_restart_error = restart_error;
      }
      const int iterations = report.iterations;
      for_each_particle(n, [&](std::size_t i) { pressure[i] = std::max(iterate_[i], floor); });
      sweep();  // the velocity and density error of the pressure kept
      report.iterations = iterations;
      // Gradients that left a larger error than they started from (the held set or the walls'
      // clamp far from what they assumed) are undone: the solve starts again from its start,
      // with the Jacobi sweeps' own budget.
      if (!report.converged && report.error > start_error) {
        std::copy(start_.begin(), start_.end(), pressure.begin());
        sweep();
        report.iterations = 0;
      }
      // DFSPH's divergence solve is projected only here, at the end (restarts, as in the density
      // solve, took ~5 times the sweeps on the 2D tank); where that leaves it above its threshold
      // (a few steps of a run's start), projected Jacobi sweeps finish it.
      // The sweeps' diagonal α_i leaves out the walls' adjoint term, with which their steps
      // overshoot: they solve the density error without it.
      if (!report.converged && symmetric_walls) {
        symmetric_walls = false;
        sweep();
      }
      if (!report.converged) jacobi();
    }
    // A warm start carries the last step's pressure over. Where the fluid needs no pressure
    // this step, the few sweeps that then meet the threshold leave that pressure almost as it
    // was, so over many steps it integrates the density error: a feedback without damping,
    // measured on the Poiseuille and Couette channels (a transverse velocity growing tenfold
    // every ~20 steps from 1e-11 m/s while the error stayed far below the threshold). So when
    // the solve stopped at its minimum sweeps, the fluid without pressure is tried too and,
    // if it meets the threshold (and, for the conjugate gradients, the pressure moves the fluid
    // by less than their accuracy), kept.
    if (!report.converged || report.iterations > least_iterations || warm_start == 0) return;
    if (conjugate && pressure_energy() > accuracy) return;
    const SolveReport pressed = report;
    measure(solve_fields_.predicted_velocity, true);
    if (!report.converged) {
      report = pressed;
      return;
    }
    report.iterations = pressed.iterations;
    report.sweeps = pressed.sweeps;
    auto v = fluid_[fluid_fields_.velocity];
    const auto predicted = std::as_const(fluid_)[solve_fields_.predicted_velocity];
    for_each_particle(fluid_.size(), [&](std::size_t i) {
      pressure[i] = 0;
      v.set(i, predicted[i]);
    });
  }();
  // A closed or periodic domain leaves the pressure's level free: the sweeps solve for ρ* and a
  // constant pressure moves no particle. With one fluid the sweeps leave the mean pressure where
  // the warm start put it (the mean of ρ* − ρ0 is removed and α_i is nearly uniform, so the
  // updates sum to about zero). With several, the same relative excess is a larger update where
  // ρ0 is larger, and the level drifts with the correlation of excess and phase: measured on two
  // layers at rest (density ratio 3, closed box), the lowest pressure fell from 0 to −1 (ρ0 g
  // times the light layer's depth) over 4 s, the light fluid under the lid went into tension and
  // clumped (ρ/ρ0 = 1.2) and the run failed at 6 s. So with several fluids each solve keeps the
  // mean pressure it started from, the level of the layered hydrostatic start.
  if (two_sided && phases_) {
    const Real drift = mean_pressure() - mean_before;
    for_each_particle(fluid_.size(), [&](std::size_t i) { pressure[i] -= drift; });
  }
  return report;
}

template <int D>
StepReport IncompressibleSph<D>::step() {
  StepContext context;
  // The CFL limit counts the moving walls' particles as the fluid's (a fan's tips).
  context.report.time_step =
      choose_time_step(time_step_rule_, std::max(max_speed_, moving_walls_.max_particle_speed()), max_acceleration_);
  context.dt = context.report.time_step.dt;
  pipeline_.run(context);
  return context.report;
}

template <int D>
void IncompressibleSph<D>::predict_velocity(Real dt) {
  auto predicted = fluid_[solve_fields_.predicted_velocity];
  const auto v = std::as_const(fluid_)[fluid_fields_.velocity];
  const auto a = std::as_const(fluid_)[fluid_fields_.acceleration];
  for_each_particle(fluid_.size(), [&](std::size_t i) { predicted.set(i, v[i] + dt * a[i]); });
}

template <int D>
void IncompressibleSph<D>::drift(Real dt) {
  auto x = fluid_[fluid_fields_.position];
  const auto v = std::as_const(fluid_)[fluid_fields_.velocity];
  for_each_particle(fluid_.size(), [&](std::size_t i) { x.set(i, x[i] + dt * v[i]); });
}

template <int D>
void IncompressibleSph<D>::shift_particles(Real dt) {
  passes::shift_particles<D>(kernel_, static_cast<Real>(scene_.particle_spacing), smoothing_length_, max_speed_, dt,
                             fluid_, fluid_fields_, interactions_);
}

template <int D>
SolveReport IncompressibleSph<D>::solve_divergence(Real dt) {
  auto predicted = fluid_[solve_fields_.predicted_velocity];
  const auto v = std::as_const(fluid_)[fluid_fields_.velocity];
  for_each_particle(fluid_.size(), [&](std::size_t i) { predicted.set(i, v[i]); });
  return solve(*solve_fields_.divergence_pressure, Target::divergence, scheme_.divergence_warm_start, Vector<D>::Zero(),
               dt);
}

template <int D>
void IncompressibleSph<D>::count_failures(const StepReport& report) {
  const bool density_missed = !report.density_solve->converged;
  const bool divergence_missed = report.divergence_solve && !report.divergence_solve->converged;
  if (!density_missed && !divergence_missed) {
    failed_steps_in_a_row_ = 0;
    return;
  }
  const SolveReport& missed = density_missed ? *report.density_solve : *report.divergence_solve;
  const std::string which = density_missed ? "density" : "divergence";
  const double threshold = density_missed ? scene_.solver.max_density_error : scene_.solver.max_divergence_error;
  std::ostringstream message;
  message << "step " << step_count_ << ", t = " << time_ << " s: the " << which
          << " solve left a mean density error of " << percent(missed.error) << " of rho0 after " << missed.iterations
          << " iterations (threshold " << percent(threshold) << ")";
  log_warning(message.str());
  if (++failed_steps_in_a_row_ < scene_.solver.max_failed_solves) return;
  // The diagnosis names the particle the last sweep found most compressed.
  const Index id = fluid_[fluid_.id()][std::min(worst_particle_, fluid_.size() - 1)];
  throw InstabilityError(id, which + " excess", static_cast<double>(worst_excess_), step_count_, time_,
                         "the pressure solve missed its threshold of " + percent(threshold) + " in " +
                             std::to_string(failed_steps_in_a_row_) + " consecutive steps; last mean density error " +
                             percent(missed.error) + " after " + std::to_string(missed.iterations) +
                             " iterations (raise solver.max_solver_iterations or lower solver.cfl)");
}

template <int D>
void IncompressibleSph<D>::check_state() {
  const Real ratio = static_cast<Real>(scene_.solver.max_density_ratio);
  StateLimits limits;
  limits.max_density = ratio * rest_density_;
  limits.density_band = "above " + setup::format_number(ratio) + " rho0, solver.max_density_ratio";
  limits.max_speed = static_cast<Real>(scene_.solver.max_mach_number) * reference_sound_speed_;
  limits.speed_bound = "faster than " + setup::format_number(scene_.solver.max_mach_number) +
                       " x c0 = " + setup::format_number(limits.max_speed) +
                       " m/s (c0: the material's sound_speed, else 10 max_speed), solver.max_mach_number";
  if (phases_) bound_density_by_phase(limits, rest_density_, *phases_, std::as_const(fluid_)[fluid_fields_.phase]);
  const StateMaxima maxima = check_fluid_state<D>(fluid_, fluid_fields_, limits, step_count_, time_);
  max_speed_ = maxima.speed;
  max_acceleration_ = maxima.acceleration;
}

template <int D>
double IncompressibleSph<D>::bytes_per_particle() const {
  const std::size_t scratch_entries = iterate_.capacity() + start_.capacity() + residual_.capacity() +
                                      direction_.capacity() + pressure_term_.capacity() +
                                      held_.capacity() / sizeof(Real);
  const double scratch = fluid_.size() > 0 ? double(sizeof(Real) * scratch_entries) / fluid_.size() : 0;
  return setup::bytes_per_particle<D>(fluid_, interactions_) + scratch;
}

}  // namespace tide
