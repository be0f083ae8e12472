#pragma once

#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "tide/core/kernels/kernel.hpp"
#include "tide/core/kernels/runtime_kernel.hpp"
#include "tide/core/particle_set.hpp"
#include "tide/core/scene.hpp"
#include "tide/neighbor/neighbor_grid.hpp"
#include "tide/solvers/equation_of_state.hpp"
#include "tide/solvers/interactions.hpp"
#include "tide/solvers/moving_walls.hpp"
#include "tide/solvers/particle_fields.hpp"
#include "tide/solvers/phases.hpp"
#include "tide/solvers/pipeline.hpp"
#include "tide/solvers/rigid_bodies.hpp"
#include "tide/solvers/simulation.hpp"
#include "tide/solvers/time_step.hpp"

namespace tide {

namespace passes {
struct MultiphaseTerms;
struct SurfaceTensionSettings;
struct ViscositySettings;
}  // namespace passes

/// Weakly compressible SPH: density by summation (or continuity with δ-SPH diffusion), Tait or
/// linear equation of state, symmetric pressure force, Monaghan artificial or Morris laminar
/// viscosity, walls of particles with extrapolated pressure, kick–drift–kick integration with an
/// adaptive time step. Every pass gathers from neighbours and writes only its own particle, so
/// results are bitwise identical for any thread count. A scene whose fluid blocks use several
/// materials runs multiphase: a phase index per particle, each phase's equation of state and
/// viscosity, and the number-density formulation of Hu & Adams 2006. solver.surface_tension adds
/// one of three tension models (docs/multiphase.md).
template <int D>
class Wcsph final : public Simulation<D> {
 public:
  explicit Wcsph(const scene::Scene& scene);
  ~Wcsph() override;
  // The pipeline's stages hold `this`.
  Wcsph(const Wcsph&) = delete;
  Wcsph& operator=(const Wcsph&) = delete;

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
  const EquationOfState& equation_of_state() const { return eos_; }
  /// Gravity now: the scene's, or less while it is being raised (solver.gravity_ramp_time).
  Vector<D> gravity() const override;
  const AnyKernel<D>& kernel() const override { return kernel_.any(); }
  Real rest_density() const override { return eos_.rest_density(); }
  Real smoothing_length() const override { return smoothing_length_; }
  Real max_speed() const override { return max_speed_; }
  std::size_t removed_total() const override { return interactions_.fluid_grid().removed_total(); }
  std::size_t neighbor_builds() const override { return interactions_.builds(); }
  const Pipeline& pipeline() const override { return pipeline_; }
  /// The phases of a multiphase scene; null for a single fluid.
  const Phases* phases() const { return phases_ ? &*phases_ : nullptr; }
  /// The pairwise model's force strength s_ab between phases a and b (Tartakovsky & Meakin 2005);
  /// 0 without it.
  Real pair_strength(Index a, Index b) const;
  /// The pairwise model's force strength s_aw between phase a and the wall contacts; 0 without it.
  Real wall_strength(Index a) const;
  double bytes_per_particle() const override;
  MemoryUsage memory_usage() const override;
  const RigidBodies<D>* bodies() const override { return &bodies_; }
  void save(StateArchive& archive) const override;
  void restore(const StateArchive& archive) override;
  void edit_start(FunctionRef<void(ParticleSet<D>&)> edit) override;

 private:
  /// The neighbour search and what the first step reads from the start state (construction, edit_start).
  void start();
  void set_hydrostatic_density();
  /// How interactions_ lists the pairs after an update: by the density pass where it can.
  typename Interactions<D>::Listing listing() const;
  /// The stages of a step, in order, for what the scene uses.
  Pipeline build_pipeline();
  /// The neighbour search, with the density pass where that pass lists the pairs.
  Stage neighbor_search_stage();
  /// From the density to the accelerations: what the start runs after its neighbour search too.
  std::vector<Stage> force_stages();
  /// Whether the density pass lists the neighbours (summation density with a skin), so that it
  /// runs in the neighbour search's stage.
  bool density_lists_neighbors() const;
  std::string_view density_pass_name() const;
  /// The gravity the forces of the step of `context` use.
  Vector<D> step_gravity(const StepContext& context) const;
  void kick_drift(Real dt);
  void kick(Real dt);
  void inject_phase();
  /// The pressure of `eos` at density rho, clamped at 0 where solver.clamp_negative_pressure says.
  Real pressure_at(const EquationOfState& eos, Real rho) const;
  void sum_density();
  void apply_equation_of_state();
  void extrapolate_wall_state(const Vector<D>& gravity);
  void compute_acceleration(const Vector<D>& gravity);
  /// The momentum pass of solver.riemann_solver "low_dissipation" (passes/riemann.hpp), with the
  /// kernel gradient correction where solver.kernel_gradient_correction asks for it.
  void compute_riemann_acceleration(const passes::ViscositySettings& viscosity, const Vector<D>& gravity);
  /// The fluid's force on every body particle, summed per body (RigidBodies::sum_forces).
  void compute_body_forces();
  /// The phase field, the phases and the wall volume for the multiphase passes; empty terms for a
  /// single fluid.
  passes::MultiphaseTerms multiphase_terms() const;
  void add_surface_tension();
  /// Continuity density: ρ += Δt Dρ/Dt.
  void integrate_density(const Vector<D>& gravity, Real dt);
  void compute_density_rate(const Vector<D>& gravity);
  /// Continuity density with clamped pressure: a free-surface particle's density is held at ρ0 or
  /// above (passes/free_surface_density.hpp).
  bool holds_free_surface_density() const;
  void hold_free_surface_density();
  void shift_particles(Real dt);
  /// The inflow buffer (domain.inflow, which the scene must have): its particles at the inflow
  /// velocity, moved as if they had drifted at it over `drift_time`.
  void impose_inflow(Real drift_time);
  /// Whether the inflow injects a phase (domain.inflow.phase in a multiphase scene).
  bool injects_phase() const;
  void check_state();
  /// What bound the last time step, for an instability message: a step above its stable limit
  /// is a common cause.
  std::string time_step_note() const;

  scene::Scene scene_;
  Real smoothing_length_;
  RuntimeKernel<D> kernel_;
  EquationOfState eos_;
  Real kinematic_viscosity_;
  std::optional<Phases> phases_;
  std::unique_ptr<const passes::SurfaceTensionSettings> tension_;
  TimeStepRule time_step_rule_;
  ParticleSet<D> fluid_;
  FluidFields<D> fluid_fields_;
  Interactions<D> interactions_;
  MovingWalls<D> moving_walls_;
  RigidBodies<D> bodies_;
  ContactLaw contact_law_;  // between the bodies and with the walls
  double time_ = 0;
  std::uint64_t step_count_ = 0;
  TimeStep last_time_step_;
  Real max_speed_ = 0;       // of the fluid's particles
  Real max_body_speed_ = 0;  // of the bodies' particles
  Real max_acceleration_ = 0;
  Pipeline pipeline_;
};

extern template class Wcsph<2>;
extern template class Wcsph<3>;

}  // namespace tide
