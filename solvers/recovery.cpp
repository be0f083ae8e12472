#include "tide/solvers/recovery.hpp"

#include <span>
#include <stdexcept>
#include <string>

#include "tide/core/parallel.hpp"
#include "tide/solvers/particle_sampling.hpp"

namespace tide {

template <int D>
double material_mass_in(const Simulation<D>& simulation, std::size_t material, const scene::Box& region) {
  const auto& fluid = simulation.fluid();
  const auto& f = simulation.fluid_fields();
  const auto x = fluid[f.position];
  const auto mass = fluid[f.mass];
  const bool multiphase = scene::fluid_material_count(simulation.scene()) > 1;
  const std::span<const Index> phase = multiphase ? fluid[f.phase] : std::span<const Index>{};
  const Vector<D> lower = to_vector<D>(region.min), upper = to_vector<D>(region.max);
  return reduce(
      fluid.size(), 0.0,
      [&](std::size_t i) {
        if (multiphase && phase[i] != static_cast<Index>(material)) return 0.0;
        const Vector<D> xi = x[i];
        for (int d = 0; d < D; ++d)
          if (!(xi[d] >= lower[d] && xi[d] < upper[d])) return 0.0;
        return static_cast<double>(mass[i]);
      },
      [](double a, double b) { return a + b; });
}

template <int D>
RecoveryMeter<D>::RecoveryMeter(const Simulation<D>& simulation, const scene::Recovery& recovery)
    : recovery_(recovery), initial_mass_(material_mass_in<D>(simulation, recovery.material, recovery.region)) {
  if (!(initial_mass_ > 0)) {
    throw std::invalid_argument(simulation.scene().source +
                                ": /output/recovery/region holds no particle of material \"" +
                                simulation.scene().materials.at(recovery.material).name + "\" at the start");
  }
}

template <int D>
double RecoveryMeter<D>::mass(const Simulation<D>& simulation) const {
  return material_mass_in<D>(simulation, recovery_.material, recovery_.region);
}

template double material_mass_in<2>(const Simulation<2>&, std::size_t, const scene::Box&);
template double material_mass_in<3>(const Simulation<3>&, std::size_t, const scene::Box&);
template class RecoveryMeter<2>;
template class RecoveryMeter<3>;

}  // namespace tide
