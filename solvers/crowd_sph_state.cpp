// What CrowdSph keeps between two steps, for checkpoints (docs/output.md, "Checkpoints"). Its
// only random numbers are the desired speeds, drawn once when the agents are placed and kept as
// a field: no generator state is left to save.

#include <stdexcept>
#include <vector>

#include "tide/core/particle_set_state.hpp"
#include "tide/solvers/crowd_sph.hpp"

namespace tide {

void CrowdSph::save(StateArchive& archive) const {
  save_particles(archive, "fluid", agents_);
  interactions_.save(archive);
  archive.put_double("scheme/time", time_);
  archive.put_count("scheme/steps", step_count_);
  archive.put_counts("scheme/exited", std::vector<std::uint64_t>(exited_.begin(), exited_.end()));
  archive.put_doubles("scheme/peak", {peak_.density, peak_.position[0], peak_.position[1], peak_.time});
  archive.put_reals("scheme/maxima", std::vector<Real>{max_speed_, max_acceleration_});
}

void CrowdSph::restore(const StateArchive& archive) {
  restore_particles(archive, "fluid", agents_);
  interactions_.restore(archive, agents_, Interactions<2>::NextStep::updates_first);
  time_ = archive.double_value("scheme/time");
  step_count_ = archive.count_value("scheme/steps");
  const auto exited = archive.counts("scheme/exited");
  const auto peak = archive.doubles("scheme/peak");
  const auto maxima = archive.reals("scheme/maxima");
  if (exited.size() != exited_.size() || peak.size() != 4 || maxima.size() != 2)
    throw std::runtime_error("checkpoint: scheme/exited, scheme/peak or scheme/maxima has another length");
  exited_.assign(exited.begin(), exited.end());
  peak_ = {peak[0], {peak[1], peak[2]}, peak[3]};
  max_speed_ = maxima[0];
  max_acceleration_ = maxima[1];
}

}  // namespace tide
