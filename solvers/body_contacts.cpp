#include "tide/solvers/body_contacts.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <tuple>

#include "tide/core/parallel.hpp"

namespace tide {

ContactLaw contact_law(const scene::BodyContact& contact, Real spacing, Real acoustic_time_step) {
  const double log_e = std::log(contact.restitution);
  ContactLaw law;
  law.distance = spacing;
  law.frequency = static_cast<Real>(contact.frequency.value_or(0.2 / static_cast<double>(acoustic_time_step)));
  law.damping_ratio = static_cast<Real>(-log_e / std::sqrt(std::numbers::pi * std::numbers::pi + log_e * log_e));
  law.friction = static_cast<Real>(contact.friction);
  return law;
}

namespace {

// Cells are keyed by their coordinates from the box's corner, 21 bits per axis with one cell of
// margin below; coordinates outside that range (a particle far from the box, or not finite) are
// clamped to its edge, which only adds candidates that the distance test then drops.
constexpr std::int64_t cell_bias = 1;
constexpr std::int64_t cell_limit = (std::int64_t{1} << 21) - 1;

}  // namespace

template <int D>
std::array<std::int64_t, D> SolidCells<D>::cell_of(const Vector<D>& x) const {
  std::array<std::int64_t, D> cell;
  for (int d = 0; d < D; ++d) {
    const Real c = std::floor((x[d] - origin_[d]) * inverse_cell_);
    cell[d] = c >= 0 && c < Real(cell_limit) ? static_cast<std::int64_t>(c) : (c >= 0 ? cell_limit : -cell_bias);
  }
  return cell;
}

template <int D>
std::uint64_t SolidCells<D>::key_of(const std::array<std::int64_t, D>& cell) {
  std::uint64_t key = 0;
  for (int d = 0; d < D; ++d) {
    const std::int64_t c = std::clamp<std::int64_t>(cell[d] + cell_bias, 0, cell_limit);
    key = (key << 21) | static_cast<std::uint64_t>(c);
  }
  return key;
}

template <int D>
std::pair<std::size_t, std::size_t> SolidCells<D>::range_of(std::uint64_t key) const {
  const auto by_key = [](const Entry& e, std::uint64_t k) { return e.key < k; };
  const auto first = std::lower_bound(entries_.begin(), entries_.end(), key, by_key);
  auto last = first;
  while (last != entries_.end() && last->key == key) ++last;
  return {static_cast<std::size_t>(first - entries_.begin()), static_cast<std::size_t>(last - entries_.begin())};
}

template <int D>
void SolidCells<D>::build(std::span<const SolidParticles<D>> solids, std::span<const std::size_t> bodies,
                          Real distance) {
  entries_.clear();
  Vector<D> low = Vector<D>::Constant(std::numeric_limits<Real>::infinity());
  Vector<D> high = -low;
  for (const std::size_t body : bodies) {
    const SolidParticles<D>& set = solids[body];
    for (std::size_t p = 0; p < set.size; ++p) {
      low = low.cwiseMin(set.position[p]);
      high = high.cwiseMax(set.position[p]);
    }
  }
  if (!(low[0] <= high[0])) return;
  low.array() -= distance;
  high.array() += distance;
  origin_ = low;
  inverse_cell_ = 1 / distance;
  for (std::size_t s = 0; s < solids.size(); ++s) {
    const SolidParticles<D>& set = solids[s];
    for (std::size_t p = 0; p < set.size; ++p) {
      const Vector<D> x = set.position[p];
      if ((x.array() < low.array()).any() || (x.array() > high.array()).any()) continue;
      entries_.push_back({key_of(cell_of(x)), static_cast<std::uint32_t>(s), static_cast<std::uint32_t>(p)});
    }
  }
  std::sort(entries_.begin(), entries_.end(), [](const Entry& a, const Entry& b) {
    return std::tie(a.key, a.set, a.particle) < std::tie(b.key, b.set, b.particle);
  });
}

template <int D>
void contact_forces(const ContactLaw& law, const SolidCells<D>& cells, std::span<const SolidParticles<D>> solids,
                    std::size_t body, VectorView<D> force) {
  const SolidParticles<D>& own = solids[body];
  const Real distance2 = law.distance * law.distance;
  for_each_particle(own.size, [&](std::size_t a) {
    const Vector<D> x_a = own.position[a];
    const Vector<D> v_a = own.velocity.component[0] ? own.velocity[a] : Vector<D>::Zero();
    Vector<D> total = Vector<D>::Zero();
    cells.for_each_near(x_a, [&](std::uint32_t set, std::uint32_t p) {
      if (set == body) return;
      const SolidParticles<D>& other = solids[set];
      const Vector<D> x_ap = x_a - other.position[p];
      const Real r2 = x_ap.squaredNorm();
      if (!(r2 < distance2) || r2 == 0) return;
      const Real r = std::sqrt(r2);
      const Vector<D> n = x_ap / r;
      const Vector<D> v_ap = other.velocity.component[0] ? Vector<D>(v_a - other.velocity[p]) : v_a;
      const Real m = std::min(own.mass_share, other.mass_share);
      const Real stiffness = m * law.frequency * law.frequency;
      const Real damping = 2 * law.damping_ratio * m * law.frequency;
      const Real v_n = v_ap.dot(n);
      const Real normal = std::max(stiffness * (law.distance - r) - damping * v_n, Real(0));
      total += normal * n;
      const Vector<D> v_t = v_ap - v_n * n;
      const Real slip = v_t.norm();
      if (slip > 0) total -= (std::min(law.friction * normal, damping * slip) / slip) * v_t;
    });
    force.set(a, total);
  });
}

template class SolidCells<2>;
template class SolidCells<3>;
template void contact_forces<2>(const ContactLaw&, const SolidCells<2>&, std::span<const SolidParticles<2>>,
                                std::size_t, VectorView<2>);
template void contact_forces<3>(const ContactLaw&, const SolidCells<3>&, std::span<const SolidParticles<3>>,
                                std::size_t, VectorView<3>);

}  // namespace tide
