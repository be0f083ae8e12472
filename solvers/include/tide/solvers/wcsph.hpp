#pragma once

#include <cstdint>
#include <memory>
#include <optional>
#include <string>

#include "tide/core/kernels/kernel.hpp"
#include "tide/core/particle_set.hpp"
#include "tide/core/scene.hpp"
#include "tide/neighbor/neighbor_grid.hpp"
#include "tide/solvers/equation_of_state.hpp"
#include "tide/solvers/fluid_wall_neighbors.hpp"
#include "tide/solvers/time_step.hpp"

namespace tide {

/// Handles of the fluid fields the WCSPH passes use.
template <int D>
struct FluidFields {
  VectorField position;
  VectorField velocity;
  VectorField acceleration;
  ScalarField mass;
  ScalarField density;
  ScalarField pressure;
  ScalarField density_rate;         // only with continuity density (slot unused otherwise)
  VectorField shift;                // only with particle shifting (slot unused otherwise)
  ScalarField position_divergence;  // only with particle shifting: ∇·r, the free-surface marker
};

/// Handles of the wall-particle fields (Adami, Hu & Adams 2012).
template <int D>
struct WallFields {
  VectorField position;
  VectorField velocity;  // extrapolated fluid velocity mirrored for the no-slip condition
  ScalarField mass;
  ScalarField density;
  ScalarField pressure;
  std::optional<VectorField> surface_velocity;  // the wall's own velocity; only when some wall moves
};

/// Wall-clock seconds spent in each part of the step, summed since construction.
struct PassTimes {
  double neighbor_search = 0;  // sort, reorder, cell tables
  double density = 0;          // summation (with EOS) or continuity update and EOS
  double wall_state = 0;       // wall pressure, density and velocity extrapolation
  double momentum = 0;         // pressure, viscous and body forces
  double integration = 0;      // kicks, drift, stability check and reductions
  double shifting = 0;         // particle shifting (zero when off)
  double total() const { return neighbor_search + density + wall_state + momentum + integration + shifting; }
};

/// What one step did.
struct StepReport {
  TimeStep time_step;
  std::size_t removed = 0;  // particles that left the domain in this step
};

/// Weakly compressible SPH: density by summation (or continuity with δ-SPH diffusion), Tait or
/// linear equation of state, symmetric pressure force, Monaghan artificial or Morris laminar
/// viscosity, walls of particles with extrapolated pressure, kick–drift–kick integration with an
/// adaptive time step. Every pass gathers from neighbours and writes only its own particle, so
/// results are bitwise identical for any thread count.
template <int D>
class Wcsph {
 public:
  explicit Wcsph(const scene::Scene& scene);

  /// Advances one adaptive time step; throws InstabilityError when the state leaves its bounds.
  StepReport step();

  const scene::Scene& scene() const { return scene_; }
  /// Simulated time in s, kept in double so that a float build still resolves small steps late in a run.
  double time() const { return time_; }
  std::uint64_t step_count() const { return step_count_; }
  const ParticleSet<D>& fluid() const { return fluid_; }
  const ParticleSet<D>& walls() const { return walls_; }
  const FluidFields<D>& fluid_fields() const { return fluid_fields_; }
  const WallFields<D>& wall_fields() const { return wall_fields_; }
  const EquationOfState& equation_of_state() const { return eos_; }
  /// Gravity now: the scene's, or less while it is being raised (solver.gravity_ramp_time).
  Vector<D> gravity() const { return gravity_at(time_); }
  const NeighborGrid<D>& fluid_grid() const { return neighbors_.fluid_grid(); }
  const NeighborGrid<D>& wall_grid() const { return neighbors_.wall_grid(); }
  Real smoothing_length() const { return smoothing_length_; }
  const AnyKernel<D>& kernel() const { return kernel_; }
  Real max_speed() const { return max_speed_; }
  std::size_t removed_total() const { return neighbors_.fluid_grid().removed_total(); }
  const PassTimes& pass_times() const { return pass_times_; }
  /// Bytes per fluid particle: fluid and wall fields plus every neighbour table.
  double bytes_per_particle() const;

 private:
  /// Gravity at time t: the scene's, raised smoothly from zero over solver.gravity_ramp_time.
  Vector<D> gravity_at(double t) const;
  /// The part of a body force that a fluid at rest balances with a pressure gradient: its
  /// components along the closed (non-periodic) axes.
  Vector<D> hydrostatic_part(Vector<D> body_force) const;
  void set_hydrostatic_density();
  void compute_interactions(const Vector<D>& gravity);
  void compute_density_rate(const Vector<D>& gravity);
  void shift_particles(Real dt);
  void check_state();
  /// What bound the last time step, for an instability message: a step above its stable limit
  /// is a common cause.
  std::string time_step_note() const;

  scene::Scene scene_;
  Real smoothing_length_;
  AnyKernel<D> kernel_;
  EquationOfState eos_;
  Real kinematic_viscosity_;
  Vector<D> gravity_;
  TimeStepRule time_step_rule_;
  ParticleSet<D> fluid_;
  ParticleSet<D> walls_;
  FluidFields<D> fluid_fields_;
  WallFields<D> wall_fields_;
  FluidWallNeighbors<D> neighbors_;
  double time_ = 0;
  std::uint64_t step_count_ = 0;
  TimeStep last_time_step_;
  Real max_speed_ = 0;
  Real max_acceleration_ = 0;
  PassTimes pass_times_;
};

extern template class Wcsph<2>;
extern template class Wcsph<3>;

}  // namespace tide
