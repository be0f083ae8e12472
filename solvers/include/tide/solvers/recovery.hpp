#pragma once

// The recovery of one fluid from a region (scene key output.recovery, docs/scenes.md): the oil
// recovery of a cavity in the water flooding of Zhou et al. 2010, the share of the oil that was
// in the cavity at the start and is no longer there.

#include <cstddef>

#include "tide/core/scene.hpp"
#include "tide/solvers/simulation.hpp"

namespace tide {

/// The mass of `material` inside `region` (a box, min inclusive, max exclusive): Σ m_i over the
/// fluid particles of that phase, or over every fluid particle in a single-phase scene. A
/// deterministic reduction, so the same for any thread count.
template <int D>
double material_mass_in(const Simulation<D>& simulation, std::size_t material, const scene::Box& region);

/// Measures recovery = 1 − M(t)/M(0) of the scene's output.recovery, with M the mass of its
/// material in its region and M(0) taken when it is made.
template <int D>
class RecoveryMeter {
 public:
  /// std::invalid_argument when the region holds none of the material at the start.
  RecoveryMeter(const Simulation<D>& simulation, const scene::Recovery& recovery);

  double initial_mass() const { return initial_mass_; }
  /// The material's mass in the region now.
  double mass(const Simulation<D>& simulation) const;
  /// 1 − mass / initial mass.
  double recovery(double mass) const { return 1 - mass / initial_mass_; }

 private:
  scene::Recovery recovery_;
  double initial_mass_ = 0;
};

extern template class RecoveryMeter<2>;
extern template class RecoveryMeter<3>;

}  // namespace tide
