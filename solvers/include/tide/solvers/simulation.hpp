#pragma once

#include <algorithm>
#include <cstdint>
#include <memory>
#include <optional>
#include <string_view>
#include <vector>

#include "tide/core/kernels/kernel.hpp"
#include "tide/core/memory_usage.hpp"
#include "tide/core/particle_set.hpp"
#include "tide/core/scene.hpp"
#include "tide/neighbor/neighbor_grid.hpp"
#include "tide/solvers/interactions.hpp"
#include "tide/solvers/particle_fields.hpp"
#include "tide/solvers/time_step.hpp"

namespace tide {

/// Wall-clock seconds spent in each part of the step, summed since construction.
struct PassTimes {
  double neighbor_search = 0;  // sort, reorder, cell tables, lists (and a density pass that lists them)
  double density = 0;          // summation (with EOS) or continuity update and EOS; incompressible: also α
  double wall_state = 0;       // wall pressure, density and velocity extrapolation
  double momentum = 0;         // pressure, viscous and body forces (incompressible: viscous and body forces)
  double pressure_solve = 0;   // incompressible schemes: the implicit pressure solves (zero for WCSPH)
  double integration = 0;      // kicks, drift, stability check and reductions
  double shifting = 0;         // particle shifting (zero when off)
  double surface_tension = 0;  // colour gradient, normals and tension forces (zero without tension)
  double total() const {
    return neighbor_search + density + wall_state + momentum + pressure_solve + integration + shifting +
           surface_tension;
  }
};

/// How one implicit pressure solve ended.
struct SolveReport {
  int iterations = 0;  // pressure updates made
  double error = 0;    // the mean density error it left, as a share of ρ0 (see IncompressibleSph::solve)
  bool converged = false;
};

/// Iterations and final errors of a stretch of solves of one kind.
struct SolveTally {
  std::size_t solves = 0;
  std::size_t missed = 0;  // solves that ended at the iteration cap above their threshold
  std::uint64_t iterations = 0;
  int max_iterations = 0;
  double error_sum = 0;
  double max_error = 0;

  void add(const SolveReport& report) {
    ++solves;
    missed += report.converged ? 0 : 1;
    iterations += static_cast<std::uint64_t>(report.iterations);
    max_iterations = std::max(max_iterations, report.iterations);
    error_sum += report.error;
    max_error = std::max(max_error, report.error);
  }
  double mean_iterations() const { return solves ? static_cast<double>(iterations) / static_cast<double>(solves) : 0; }
  double mean_error() const { return solves ? error_sum / static_cast<double>(solves) : 0; }
};

/// What one step did.
struct StepReport {
  TimeStep time_step;
  std::size_t removed = 0;                      // particles that left the domain in this step
  std::optional<SolveReport> density_solve;     // incompressible schemes
  std::optional<SolveReport> divergence_solve;  // DFSPH
};

/// What `tide run` and the validation cases drive, whatever the scheme.
template <int D>
class Simulation {
 public:
  virtual ~Simulation() = default;

  /// Advances one adaptive time step; throws InstabilityError when the state leaves its bounds.
  virtual StepReport step() = 0;

  virtual const scene::Scene& scene() const = 0;
  /// Simulated time in s, kept in double so that a float build still resolves small steps late in a run.
  virtual double time() const = 0;
  virtual std::uint64_t step_count() const = 0;
  virtual const ParticleSet<D>& fluid() const = 0;
  virtual const FluidFields<D>& fluid_fields() const = 0;
  /// The fluid's neighbour relations: its own grid and lists, and every contact (walls, ...).
  virtual const Interactions<D>& interactions() const = 0;
  virtual const AnyKernel<D>& kernel() const = 0;
  /// Gravity now: the scene's, or less while it is being raised (solver.gravity_ramp_time).
  virtual Vector<D> gravity() const = 0;
  virtual Real rest_density() const = 0;
  virtual Real smoothing_length() const = 0;
  virtual Real max_speed() const = 0;
  virtual std::size_t removed_total() const = 0;
  /// Steps (and the start) that re-sorted the fluid and rebuilt its neighbour lists: every step
  /// without a skin (solver.neighbor_skin), fewer with one.
  virtual std::size_t neighbor_builds() const = 0;
  virtual const PassTimes& pass_times() const = 0;
  /// The passes one step runs, in order, as the scene assembled them: a pass a scene does not
  /// need is not in the list (DESIGN.md, "Pipelines").
  virtual const std::vector<std::string_view>& pipeline() const = 0;
  /// Bytes per fluid particle: fluid and wall fields plus every neighbour table.
  virtual double bytes_per_particle() const = 0;
  /// Those bytes item by item (MemoryUsage); a scheme that does not itemise them reports one item.
  virtual MemoryUsage memory_usage() const {
    MemoryUsage usage;
    usage.add("all (not itemised)",
              static_cast<std::size_t>(bytes_per_particle() * static_cast<double>(fluid().size())));
    return usage;
  }
};

/// The scheme the scene's solver.scheme names, built from the scene.
template <int D>
std::unique_ptr<Simulation<D>> make_simulation(const scene::Scene& scene);

/// "wcsph", "dfsph" or "iisph".
std::string_view scheme_name(scene::Scheme scheme);

}  // namespace tide
