#pragma once

// The simulation behind tidesph.Simulation, whatever its dimension: steps, runs, the starting
// fields, checkpoints, and a lock that keeps two Python threads from stepping it at once (the
// module releases the GIL while it steps).

#include <chrono>
#include <cstdint>
#include <filesystem>
#include <memory>
#include <mutex>
#include <variant>

#include "run_statistics.hpp"
#include "scene_source.hpp"
#include "tide/solvers/simulation.hpp"

namespace tide::python {

/// Shared with the NumPy views of its fields (their keepalive): a restore gives the handle a new
/// simulation and leaves the old one to the views that still show it.
using AnySimulation = std::variant<std::shared_ptr<Simulation<2>>, std::shared_ptr<Simulation<3>>>;

class SimulationHandle {
 public:
  explicit SimulationHandle(SceneSource source);

  const SceneSource& source() const { return source_; }
  const AnySimulation& simulation() const { return simulation_; }
  const RunStatistics& statistics() const { return statistics_; }
  /// Held by every call that reads or changes the simulation.
  std::mutex& mutex() const { return mutex_; }

  /// One step (the caller holds mutex()).
  StepReport step();
  /// Steps until the time reaches `until` or `wall_budget` has passed (the caller holds mutex());
  /// true once the time has reached `until`.
  bool run_for(double until, std::chrono::duration<double> wall_budget);
  /// Writes the state to `file` atomically, as `tide run --checkpoint-every` does (the caller
  /// holds mutex()).
  void write_checkpoint(const std::filesystem::path& file) const;
  /// Continues from a checkpoint of this scene (one this class or `tide run` wrote), in a new
  /// simulation; the statistics start again (the caller holds mutex()).
  void restore_checkpoint(const std::filesystem::path& file);

 private:
  SceneSource source_;
  AnySimulation simulation_;
  RunStatistics statistics_;
  mutable std::mutex mutex_;
};

}  // namespace tide::python
