#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <span>
#include <utility>
#include <vector>

#include "tide/core/particle_set.hpp"
#include "tide/core/scene_body.hpp"
#include "tide/core/types.hpp"

namespace tide {

/// One set of solid particles a rigid body may touch: a body's own, or a wall's.
template <int D>
struct SolidParticles {
  ConstVectorView<D> position;
  ConstVectorView<D> velocity;  // unset (null components): the particles are at rest
  std::size_t size = 0;
  Real mass_share = 0;  // each particle's share of its body's mass; infinite for a wall
};

/// The spring, dashpot and friction between two solid particles closer than `distance`: a
/// linear spring-dashpot along the line between them with Coulomb friction across it (Cundall &
/// Strack 1979, "A discrete numerical model for granular assemblies", Géotechnique 29, 47), the
/// friction regularised by the dashpot's coefficient below sliding. The spring k = m ω² and the
/// dashpot 2 ζ m ω act on m, the smaller of the two particles' mass shares, so the pair's force
/// on either particle is the other's with its sign turned (and a wall's particle, of infinite
/// share, takes the body particle's).
struct ContactLaw {
  Real distance = 0;       // Δx: particles closer than this press on each other
  Real frequency = 0;      // ω, rad/s
  Real damping_ratio = 0;  // ζ
  Real friction = 0;       // μ
};

/// The law of `contact` for particles `spacing` apart, with ω = 0.2 / `acoustic_time_step`
/// where the scene leaves it unset; ζ from the restitution e, ζ = −ln e / √(π² + ln² e) (the
/// damped oscillator that leaves a head-on impact at e times its speed).
ContactLaw contact_law(const scene::BodyContact& contact, Real spacing, Real acoustic_time_step);

/// The solid particles near the rigid bodies, binned into cells of the contact distance: a
/// sorted list of (cell, set, particle), so that the neighbours of a point are found in the same
/// order on any thread count. Only the particles within the contact distance of the box around
/// all bodies are binned: a scene's walls are many, its bodies small.
template <int D>
class SolidCells {
 public:
  /// Bins the particles of `solids` near the box around the particles of the sets `bodies`.
  void build(std::span<const SolidParticles<D>> solids, std::span<const std::size_t> bodies, Real distance);

  /// f(set, particle) for every binned particle in the cells around x (those that can be
  /// within the distance), in the list's order.
  template <class F>
  void for_each_near(const Vector<D>& x, F&& f) const {
    std::array<std::int64_t, D> cell = cell_of(x);
    std::array<std::int64_t, D> offset;
    offset.fill(-1);
    for (bool more = true; more;) {
      std::array<std::int64_t, D> near;
      for (int d = 0; d < D; ++d) near[d] = cell[d] + offset[d];
      const auto [first, last] = range_of(key_of(near));
      for (std::size_t e = first; e < last; ++e) f(entries_[e].set, entries_[e].particle);
      int d = 0;
      for (; d < D; ++d) {
        if (++offset[d] <= 1) break;
        offset[d] = -1;
      }
      more = d < D;
    }
  }

 private:
  struct Entry {
    std::uint64_t key;
    std::uint32_t set;
    std::uint32_t particle;
  };

  std::array<std::int64_t, D> cell_of(const Vector<D>& x) const;
  static std::uint64_t key_of(const std::array<std::int64_t, D>& cell);
  std::pair<std::size_t, std::size_t> range_of(std::uint64_t key) const;

  Vector<D> origin_ = Vector<D>::Zero();
  Real inverse_cell_ = 0;
  std::vector<Entry> entries_;
};

/// The contact force on every particle of solid set `body` from the particles of every other
/// solid set near it, into `force`: a gather per particle, so bitwise the same for any thread
/// count.
template <int D>
void contact_forces(const ContactLaw& law, const SolidCells<D>& cells, std::span<const SolidParticles<D>> solids,
                    std::size_t body, VectorView<D> force);

extern template class SolidCells<2>;
extern template class SolidCells<3>;

}  // namespace tide
