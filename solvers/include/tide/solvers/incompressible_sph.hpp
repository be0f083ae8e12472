#pragma once

#include <cstdint>
#include <optional>
#include <string_view>
#include <vector>

#include "tide/core/kernels/kernel.hpp"
#include "tide/core/kernels/runtime_kernel.hpp"
#include "tide/core/particle_set.hpp"
#include "tide/core/scene.hpp"
#include "tide/solvers/incompressible_scheme.hpp"
#include "tide/solvers/interactions.hpp"
#include "tide/solvers/moving_walls.hpp"
#include "tide/solvers/particle_fields.hpp"
#include "tide/solvers/phases.hpp"
#include "tide/solvers/pipeline.hpp"
#include "tide/solvers/simulation.hpp"
#include "tide/solvers/time_step.hpp"

namespace tide {

/// Handles of the fluid fields only the implicit pressure solves use.
template <int D>
struct PressureSolveFields {
  ScalarField factor;  // α_i = 1/|∂ρ*_i/∂p_i| · Δt²: the Jacobi diagonal (passes/pressure_solve.hpp)
  VectorField predicted_velocity;  // v*: the velocity before the pressure of the solve in progress
  ScalarField density_excess;      // ρ*_i − ρ0 (density solve) or Δt Dρ_i/Dt (divergence solve) of the last sweep
  std::optional<ScalarField> divergence_pressure;  // DFSPH only: the pressure of the divergence solve
};

/// Incompressible SPH, DFSPH or IISPH (IncompressibleScheme says which): density by summation,
/// the non-pressure forces (viscosity of the WCSPH passes, gravity) integrated first, then the
/// pressure that brings every particle's predicted density to ρ0 found by Jacobi sweeps (or, one
/// fluid, preconditioned conjugate gradients where solver.pressure_solver asks), with an
/// adaptive time step from the flow speed alone. Walls are the WCSPH wall particles, with their
/// pressure extrapolated from the fluid's before every sweep (passes/pressure_solve.hpp). The first
/// solve starts from the hydrostatic pressure. A solve that misses its threshold within the iteration cap logs a
/// warning; solver.max_failed_solves consecutive steps with such a miss stop the run with an
/// InstabilityError. Several fluids (rest densities within max_incompressible_density_ratio of
/// each other) take the number-density form of WCSPH's multiphase passes (density
/// ρ_i = m_i Σ_j W_ij and the pressure force of Hu & Adams 2006), each particle's density driven
/// to the rest density of its phase, from a layered hydrostatic start. Every pass gathers, so
/// results are bitwise identical for any thread count.
template <int D>
class IncompressibleSph final : public Simulation<D> {
 public:
  explicit IncompressibleSph(const scene::Scene& scene);
  // The pipeline's stages hold `this`.
  IncompressibleSph(const IncompressibleSph&) = delete;
  IncompressibleSph& operator=(const IncompressibleSph&) = delete;

  StepReport step() override;

  const scene::Scene& scene() const override { return scene_; }
  bool steer(const Eigen::Vector3d& displacement) override;
  bool set_gravity(const Vector<D>& gravity) override;
  bool set_kinematic_viscosity(Real viscosity) override;
  double time() const override { return time_; }
  std::uint64_t step_count() const override { return step_count_; }
  const ParticleSet<D>& fluid() const override { return fluid_; }
  const FluidFields<D>& fluid_fields() const override { return fluid_fields_; }
  const Interactions<D>& interactions() const override { return interactions_; }
  const AnyKernel<D>& kernel() const override { return kernel_.any(); }
  Vector<D> gravity() const override { return gravity_; }
  Real rest_density() const override { return rest_density_; }
  const PressureSolveFields<D>& solve_fields() const { return solve_fields_; }
  const IncompressibleScheme& scheme() const { return scheme_; }
  Real relaxation() const { return relaxation_; }
  Real smoothing_length() const override { return smoothing_length_; }
  Real max_speed() const override { return max_speed_; }
  std::size_t removed_total() const override { return interactions_.fluid_grid().removed_total(); }
  std::size_t neighbor_builds() const override { return interactions_.builds(); }
  const Pipeline& pipeline() const override { return pipeline_; }
  double bytes_per_particle() const override;
  void save(StateArchive& archive) const override;
  void restore(const StateArchive& archive) override;
  void edit_start(FunctionRef<void(ParticleSet<D>&)> edit) override;
  /// The phases of a multiphase scene; null for a single fluid.
  const Phases* phases() const { return phases_ ? &*phases_ : nullptr; }

 private:
  /// The neighbour search and what the first step reads from the start state (construction, edit_start).
  void start();
  enum class Target { density, divergence };

  /// The stages of a step, in order, for what the scene uses.
  Pipeline build_pipeline();
  Stage neighbor_search_stage();
  /// Gradient cache, density and α_i after a neighbour search: what the start runs too.
  std::vector<Stage> density_stages();
  /// The non-pressure accelerations: what the start runs too.
  std::vector<Stage> force_stages();
  void cache_gradients();
  void sum_density();
  void compute_pressure_factor();
  void extrapolate_wall_velocity();
  void compute_non_pressure_acceleration();
  void predict_velocity(Real dt);
  void drift(Real dt);
  void shift_particles(Real dt);
  /// DFSPH's divergence solve, from the velocities after the density solve.
  SolveReport solve_divergence(Real dt);
  SolveReport solve(ScalarField pressure, Target target, Real warm_start, const Vector<D>& wall_gravity, Real dt);
  /// The scene asks for conjugate gradients and there is one fluid (several fluids keep the projected Jacobi
  /// sweeps, whose update need not be symmetric).
  bool conjugate_gradients() const {
    return !phases_ && scene_.solver.pressure_solver == scene::PressureSolver::conjugate_gradients;
  }
  void count_failures(const StepReport& report);
  void check_state();

  scene::Scene scene_;
  IncompressibleScheme scheme_;
  Real relaxation_ = 1;  // ω of the Jacobi sweeps for this kernel (effective_relaxation)
  Real smoothing_length_;
  RuntimeKernel<D> kernel_;
  Real rest_density_;
  Real reference_sound_speed_;  // c0 of the material: velocity scale of the artificial viscosity and speed bound
  Real kinematic_viscosity_;
  Vector<D> gravity_;  // at the time the non-pressure acceleration was computed
  std::optional<Phases> phases_;
  TimeStepRule time_step_rule_;
  ParticleSet<D> fluid_;
  FluidFields<D> fluid_fields_;
  PressureSolveFields<D> solve_fields_;
  // Scratch of one solve, not sorted: the conjugate gradients' iterate p_k (the Jacobi sweeps:
  // p⁽ᵏ⁻¹⁾ of the Chebyshev recurrence), residual ρ* − ρ0, search direction (in p), and the
  // particles held at p = 0 (solve()).
  std::vector<Real> iterate_;
  std::vector<Real> start_;  // the pressure the conjugate gradients started from
  std::vector<Real> residual_;
  std::vector<Real> direction_;
  std::vector<unsigned char> held_;
  // The walls' adjoint term of the density error (passes::wall_pressure_adjoint): per fluid
  // particle, and per wall particle of each contact.
  std::vector<Real> adjoint_;
  std::vector<std::vector<Real>> wall_adjoint_;
  // Σ_i (|Δt a_i|² + |v_i − v*_i|²) of the step's density solve: the scale of the same step's
  // divergence solve's stopping test (written before it is read in every step, so no checkpoint
  // holds it).
  Real reference_energy_ = 0;
  std::vector<Real> pressure_term_;  // p/ρ² of one fluid in a sweep (passes::pressure_velocity); scratch
  // One fluid whose particles all have one mass, and walls of one mass: the sweeps read the masses
  // so (passes::NeighborMasses). Set with the gradient cache, after every neighbour update.
  bool uniform_masses_ = false;
  Interactions<D> interactions_;
  MovingWalls<D> moving_walls_;
  double time_ = 0;
  std::uint64_t step_count_ = 0;
  Real max_speed_ = 0;
  Real max_acceleration_ = 0;
  int failed_steps_in_a_row_ = 0;
  std::size_t worst_particle_ = 0;  // largest excess of the last solve, for the diagnosis
  Real worst_excess_ = 0;
  Pipeline pipeline_;
};

extern template class IncompressibleSph<2>;
extern template class IncompressibleSph<3>;

}  // namespace tide
