#pragma once

#include <cstdint>
#include <memory>
#include <optional>
#include <string_view>

#include <Eigen/Core>

#include "tide/core/kernels/kernel.hpp"
#include "tide/core/memory_usage.hpp"
#include "tide/core/particle_set.hpp"
#include "tide/core/scene.hpp"
#include "tide/core/state_archive.hpp"
#include "tide/neighbor/neighbor_grid.hpp"
#include "tide/solvers/crowd_status.hpp"
#include "tide/solvers/interactions.hpp"
#include "tide/solvers/particle_fields.hpp"
#include "tide/solvers/pipeline.hpp"
#include "tide/solvers/rigid_bodies.hpp"
#include "tide/solvers/step_report.hpp"

namespace tide {

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
  /// The stages step() runs, in order, as the scene assembled them, with the wall time of each
  /// summed since construction: a stage the scene does not need is not in the list.
  virtual const Pipeline& pipeline() const = 0;
  /// The rigid bodies the fluid moves (walls.obstacles[k].body); null for a scheme without them.
  virtual const RigidBodies<D>* bodies() const { return nullptr; }
  /// The crowd's counts and means (solver.scheme "crowd"); empty for a fluid scheme.
  virtual std::optional<CrowdStatus> crowd_status() const { return std::nullopt; }

  // Changes while it runs (tide serve's controls), from the next step on; false where the scheme
  // or the scene has nothing to change.

  /// Sends the scene's steered obstacles (scene::Steered) towards being displaced by
  /// `displacement` from where the scene puts them, kept inside the domain.
  virtual bool steer(const Eigen::Vector3d& /*displacement*/) { return false; }
  /// Replaces the scene's gravity vector (solver.gravity_ramp_time still raises it from zero).
  virtual bool set_gravity(const Vector<D>& /*gravity*/) { return false; }
  /// Replaces the fluid's kinematic viscosity, m²/s: only for laminar viscosity with one fluid.
  virtual bool set_kinematic_viscosity(Real /*viscosity*/) { return false; }

  /// Puts everything the next step reads into `archive` (a checkpoint, docs/output.md).
  virtual void save(StateArchive& archive) const = 0;
  /// Continues from what save() put for the same scene into `archive`: every step after this one
  /// gives the same bits as it would have after save(). std::runtime_error naming the entry when
  /// the archive lacks one or holds it at another length.
  virtual void restore(const StateArchive& archive) = 0;
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

/// "wcsph", "dfsph", "iisph" or "crowd".
std::string_view scheme_name(scene::Scheme scheme);

}  // namespace tide
