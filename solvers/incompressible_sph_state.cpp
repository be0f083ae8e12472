// What IncompressibleSph keeps between two steps, for checkpoints (docs/output.md, "Checkpoints").

#include <stdexcept>
#include <vector>

#include "simulation_setup.hpp"
#include "tide/core/particle_set_state.hpp"
#include "tide/solvers/incompressible_sph.hpp"

namespace tide {

template <int D>
void IncompressibleSph<D>::save(StateArchive& archive) const {
  // The solves' warm start is the pressure fields of the fluid (pressure, divergence_pressure).
  save_particles(archive, "fluid", fluid_);
  interactions_.save(archive);
  archive.put_double("scheme/time", time_);
  archive.put_counts("scheme/steps", {step_count_, static_cast<std::uint64_t>(failed_steps_in_a_row_),
                                      static_cast<std::uint64_t>(worst_particle_)});
  archive.put_reals("scheme/maxima", std::vector<Real>{max_speed_, max_acceleration_, worst_excess_});
}

template <int D>
void IncompressibleSph<D>::restore(const StateArchive& archive) {
  restore_particles(archive, "fluid", fluid_);
  // The density solve walks the lists, and their cached gradients, of the last step's search.
  interactions_.restore(archive, fluid_, Interactions<D>::NextStep::walks_first);
  const auto steps = archive.counts("scheme/steps");
  const auto maxima = archive.reals("scheme/maxima");
  if (steps.size() != 3 || maxima.size() != 3)
    throw std::runtime_error("checkpoint: scheme/steps or scheme/maxima has another length");
  time_ = archive.double_value("scheme/time");
  step_count_ = steps[0];
  failed_steps_in_a_row_ = static_cast<int>(steps[1]);
  worst_particle_ = steps[2];
  max_speed_ = maxima[0];
  max_acceleration_ = maxima[1];
  worst_excess_ = maxima[2];
  gravity_ = setup::gravity_at<D>(scene_, time_);  // as advance_time sets it
  cache_gradients();                               // at the positions of the last search, which nothing has moved since
  // Places the walls where the last step did (the same τ, bit for bit), for their largest speed.
  if (!moving_walls_.empty()) moving_walls_.move_to(time_ - scene_.time.start, step_count_, time_);
}

template void IncompressibleSph<2>::save(StateArchive&) const;
template void IncompressibleSph<3>::save(StateArchive&) const;
template void IncompressibleSph<2>::restore(const StateArchive&);
template void IncompressibleSph<3>::restore(const StateArchive&);

}  // namespace tide
