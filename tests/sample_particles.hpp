#pragma once

// Particle sets for the output tests: fields of every kind, with values that differ per
// particle, component and frame.

#include <cstddef>

#include "tide/core/particle_set.hpp"

namespace tide::testing_support {

/// Scalar, vector and index fields whose values differ per particle, component and frame.
template <int D>
ParticleSet<D> sample_set(std::size_t count, int frame) {
  ParticleSet<D> set;
  set.append(count);
  const auto density = set.add_scalar("density");
  const auto pressure = set.add_scalar("pressure");
  const auto velocity = set.add_vector("velocity");
  const auto phase = set.add_index("phase");
  const auto position = set[set.position()];
  for (std::size_t i = 0; i < count; ++i) {
    set[density][i] = Real(1000.0 + 0.37 * double(i) + frame);
    set[pressure][i] = Real(-0.5 * double(i) + 1.0 / 3.0 + frame);
    set[phase][i] = Index(i % 3);
    for (int d = 0; d < D; ++d) {
      position.component[d][i] = Real(0.1 * double(i) + d + 0.01 * frame);
      set[velocity].component[d][i] = Real(0.01 * double(i) * (d + 1) - frame);
    }
  }
  return set;
}

}  // namespace tide::testing_support
