#include "start_edit.hpp"

#include <stdexcept>
#include <string>

namespace tide::setup {

template <int D>
void edit_start_fields(std::uint64_t step_count, ParticleSet<D>& fluid, FunctionRef<void(ParticleSet<D>&)> edit) {
  if (step_count != 0)
    throw std::logic_error("the starting fields can be set only before the first step (this run has taken " +
                           std::to_string(step_count) + ")");
  const std::size_t count = fluid.size();
  edit(fluid);
  if (fluid.size() != count)
    throw std::logic_error("setting the starting fields changed the particle count from " + std::to_string(count) +
                           " to " + std::to_string(fluid.size()));
}

template void edit_start_fields<2>(std::uint64_t, ParticleSet<2>&, FunctionRef<void(ParticleSet<2>&)>);
template void edit_start_fields<3>(std::uint64_t, ParticleSet<3>&, FunctionRef<void(ParticleSet<3>&)>);

}  // namespace tide::setup
