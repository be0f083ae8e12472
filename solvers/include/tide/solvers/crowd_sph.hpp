#pragma once

#include <cstdint>
#include <optional>
#include <vector>

#include "tide/core/kernels/runtime_kernel.hpp"
#include "tide/core/particle_set.hpp"
#include "tide/core/scene.hpp"
#include "tide/solvers/crowd_status.hpp"
#include "tide/solvers/interactions.hpp"
#include "tide/solvers/moving_walls.hpp"
#include "tide/solvers/navigation_field.hpp"
#include "tide/solvers/particle_fields.hpp"
#include "tide/solvers/pipeline.hpp"
#include "tide/solvers/simulation.hpp"
#include "tide/solvers/time_step.hpp"

namespace tide {

/// People as SPH particles (solver.scheme "crowd", docs/crowds.md), 2D: each agent is a particle
/// of one person's mass in the number density, ρ_i = Σ_j W_ij in persons/m² (van Toll et al.
/// 2021, Sec. 4); an uneasiness pressure p = K max(ρ − W(0) − ρ_c, 0) above the comfortable density
/// ρ_c of the other agents (the agent's own term W(0) left out) pushes agents from crowded places to less crowded ones;
/// each agent relaxes toward its desired velocity, its own desired speed along the navigation field's direction to the
/// nearest exit (or its group's fixed heading); agents and walls repel one another at short range
/// (passes/crowd_forces.hpp). Agents entering an exit region are removed and counted. Walls are the scene's wall
/// particles, as contacts. Symplectic Euler steps; every pass gathers, so results are bitwise the same for any thread
/// count.
class CrowdSph final : public Simulation<2> {
 public:
  explicit CrowdSph(const scene::Scene& scene);
  // The pipeline's stages hold `this`.
  CrowdSph(const CrowdSph&) = delete;
  CrowdSph& operator=(const CrowdSph&) = delete;

  StepReport step() override;

  const scene::Scene& scene() const override { return scene_; }
  double time() const override { return time_; }
  std::uint64_t step_count() const override { return step_count_; }
  const ParticleSet<2>& fluid() const override { return agents_; }
  const FluidFields<2>& fluid_fields() const override { return fields_; }
  const Interactions<2>& interactions() const override { return interactions_; }
  const AnyKernel<2>& kernel() const override { return kernel_.any(); }
  /// Agents walk on the floor: no gravity in the plane.
  Vector<2> gravity() const override { return Vector<2>::Zero(); }
  /// The comfortable density ρ_c, persons/m².
  Real rest_density() const override { return static_cast<Real>(scene_.crowd->comfortable_density); }
  Real smoothing_length() const override { return smoothing_length_; }
  Real max_speed() const override { return max_speed_; }
  /// Agents lost through the domain's sides, not through an exit (exited()).
  std::size_t removed_total() const override { return interactions_.fluid_grid().removed_total(); }
  std::size_t neighbor_builds() const override { return interactions_.builds(); }
  const Pipeline& pipeline() const override { return pipeline_; }
  void save(StateArchive& archive) const override;
  void restore(const StateArchive& archive) override;
  void edit_start(FunctionRef<void(ParticleSet<2>&)> edit) override;
  double bytes_per_particle() const override;
  std::optional<CrowdStatus> crowd_status() const override;

  const NavigationField& navigation() const { return navigation_; }
  /// Each agent's desired speed, m/s (reordered with the agents).
  ScalarField desired_speed() const { return desired_speed_; }
  /// Each agent's fixed heading where some group has one (zero for the others; reordered with the agents).
  const std::optional<VectorField>& heading() const { return heading_; }
  /// Agents that left through each exit so far (crowd.exits order).
  const std::vector<std::size_t>& exited() const { return exited_; }
  /// The largest density since the start, where and when.
  const CrowdPeak& peak() const { return peak_; }

 private:
  /// The neighbour search and what the first step reads from the start state (construction, edit_start).
  void start();
  Pipeline build_pipeline();
  /// Returns the agents the search removed: those that left the domain elsewhere than through an exit.
  std::size_t search_and_sum_density();
  void compute_acceleration();
  void kick_drift(Real dt);
  /// Counts the agents inside each exit region (the first that holds them) and removes them.
  void remove_exited();
  void check_state();
  /// Keeps the largest density of this step in peak_ if it is the largest so far; warns, once,
  /// when it first passes crush_density.
  void record_peak();

  scene::Scene scene_;
  Real smoothing_length_;
  RuntimeKernel<2> kernel_;
  TimeStepRule time_step_rule_;
  Real time_step_cap_;  // s: the relaxation and body-contact limits (crowd_sph.cpp)
  Interactions<2> interactions_;
  MovingWalls<2>
      moving_walls_;  // none: add_wall_contacts hands moving obstacles here, and the capabilities refuse them
  NavigationField navigation_;
  ParticleSet<2> agents_;
  FluidFields<2> fields_;
  ScalarField desired_speed_;
  std::optional<VectorField> heading_;  // where some group walks along a fixed heading (zero for the others)
  std::vector<std::size_t> exited_;
  CrowdPeak peak_;
  double time_ = 0;
  std::uint64_t step_count_ = 0;
  Real max_speed_ = 0;
  Real max_acceleration_ = 0;
  Pipeline pipeline_;
};

}  // namespace tide
