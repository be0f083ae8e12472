// What Wcsph keeps between two steps, for checkpoints (docs/output.md, "Checkpoints").

#include <vector>

#include "tide/core/particle_set_state.hpp"
#include "tide/solvers/wcsph.hpp"

namespace tide {

template <int D>
void Wcsph<D>::save(StateArchive& archive) const {
  save_particles(archive, "fluid", fluid_);
  interactions_.save(archive);
  bodies_.save(archive);
  archive.put_double("scheme/time", time_);
  archive.put_counts("scheme/steps", {step_count_, static_cast<std::uint64_t>(last_time_step_.limit)});
  archive.put_reals("scheme/maxima",
                    std::vector<Real>{max_speed_, max_body_speed_, max_acceleration_, last_time_step_.dt});
}

template <int D>
void Wcsph<D>::restore(const StateArchive& archive) {
  restore_particles(archive, "fluid", fluid_);
  // The step starts with the kick and drift: the lists are needed only from its neighbour search.
  interactions_.restore(archive, fluid_, Interactions<D>::NextStep::updates_first);
  bodies_.restore(archive);
  time_ = archive.double_value("scheme/time");
  const auto steps = archive.counts("scheme/steps");
  const auto maxima = archive.reals("scheme/maxima");
  if (steps.size() != 2 || maxima.size() != 4)
    throw std::runtime_error("checkpoint: scheme/steps or scheme/maxima has another length");
  step_count_ = steps[0];
  last_time_step_ = {maxima[3], static_cast<TimeStepLimit>(steps[1])};
  max_speed_ = maxima[0];
  max_body_speed_ = maxima[1];
  max_acceleration_ = maxima[2];
  // Places the walls where the last step did (the same τ, bit for bit), for their largest speed.
  if (!moving_walls_.empty()) moving_walls_.move_to(time_ - scene_.time.start, step_count_, time_);
}

template void Wcsph<2>::save(StateArchive&) const;
template void Wcsph<3>::save(StateArchive&) const;
template void Wcsph<2>::restore(const StateArchive&);
template void Wcsph<3>::restore(const StateArchive&);

}  // namespace tide
