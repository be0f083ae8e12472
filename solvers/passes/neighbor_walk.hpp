#pragma once

// The one place that walks a fluid particle's neighbours: its inner (fluid–fluid) list and then
// every contact, in the order the contacts were added. A pass is written as a function of one
// particle that gathers through these walks and returns that particle's new values; the walk
// stores them, so a pass has no way to write another particle (the gather-only rule of
// DESIGN.md, "Passes", which keeps results bitwise the same for any thread count).

#include <cstddef>
#include <span>
#include <type_traits>
#include <utility>

#include "tide/core/parallel.hpp"
#include "tide/solvers/interactions.hpp"

namespace tide::passes {

/// Fluid particle i's neighbours in one contact.
template <int D>
class ContactNeighbors {
 public:
  ContactNeighbors(const Contact<D>& contact, std::size_t number, std::size_t i, const ConstVectorView<D>& fluid_x)
      : contact_(contact), number_(number), i_(i), fluid_x_(fluid_x) {}

  const Contact<D>& contact() const { return contact_; }
  /// The contact's place in Interactions (0 for the first added), for per-contact tables.
  std::size_t number() const { return number_; }
  /// f(b, x_ib, r²) for every neighbour b.
  template <class F>
  void pairs(F&& f) const {
    contact_.for_each_neighbor(i_, fluid_x_, f);
  }
  /// f(run) for runs of neighbours (NeighborRun; `Offsets` false: gradients only, where cached).
  template <bool Offsets = true, class F>
  void runs(F&& f) const {
    contact_.template for_each_run<Offsets>(i_, fluid_x_, f);
  }

 private:
  const Contact<D>& contact_;
  std::size_t number_;
  std::size_t i_;
  const ConstVectorView<D>& fluid_x_;
};

/// Fluid particle i's neighbours: the fluid's own, then each contact's.
template <int D>
class FluidNeighbors {
 public:
  FluidNeighbors(const Interactions<D>& interactions, std::size_t i, const ConstVectorView<D>& fluid_x)
      : interactions_(interactions), i_(i), fluid_x_(fluid_x) {}

  /// f(j, x_ij, r²) for every fluid neighbour j, i itself included (x_ij = 0).
  template <class F>
  void fluid_pairs(F&& f) const {
    interactions_.for_each_fluid_neighbor(i_, fluid_x_, f);
  }
  /// f(run) for runs of fluid neighbours (NeighborRun; `Offsets` false: gradients only, where cached).
  template <bool Offsets = true, class F>
  void fluid_runs(F&& f) const {
    interactions_.template for_each_fluid_run<Offsets>(i_, fluid_x_, f);
  }
  /// f(ContactNeighbors) for every contact, in order.
  template <class F>
  void contacts(F&& f) const {
    for (std::size_t k = 0; k < interactions_.contact_count(); ++k)
      f(ContactNeighbors<D>(interactions_.contact(k), k, i_, fluid_x_));
  }

 private:
  const Interactions<D>& interactions_;
  std::size_t i_;
  const ConstVectorView<D>& fluid_x_;
};

/// Where a walk stores what a pass returns for particle i: a scalar field, a vector field, or
/// several through a struct with set(i, value).
struct ScalarOutput {
  std::span<Real> values;
  void set(std::size_t i, Real value) const { values[i] = value; }
};
template <int D>
struct VectorOutput {
  VectorView<D> values;
  void set(std::size_t i, const Vector<D>& value) const { values.set(i, value); }
};

/// For every fluid particle i, output.set(i, pass(i, neighbours of i)), in parallel. `pass` sees
/// the neighbours through FluidNeighbors and returns particle i's values; it writes nothing.
template <int D, class Pass, class Output>
void for_each_fluid_particle(const Interactions<D>& interactions, const ConstVectorView<D>& fluid_x,
                             const Output& output, const Pass& pass) {
  using Value = std::invoke_result_t<const Pass&, std::size_t, const FluidNeighbors<D>&>;
  static_assert(!std::is_void_v<Value>, "a pass returns particle i's values; the walk stores them");
  for_each_particle(interactions.fluid_grid().particle_count(),
                    [&](std::size_t i) { output.set(i, pass(i, FluidNeighbors<D>(interactions, i, fluid_x))); });
}

/// Contact particle b's fluid neighbours.
template <int D>
class FluidNeighborsOf {
 public:
  FluidNeighborsOf(const Contact<D>& contact, std::size_t b, const ConstVectorView<D>& fluid_x)
      : contact_(contact), b_(b), fluid_x_(fluid_x) {}

  /// f(j, x_bj, r2) for every fluid neighbour j, in the order of
  /// Contact::for_each_fluid_neighbor_of: for sums that take the pairs one by one anyway (a run's
  /// x_ij and r² arrays would only be stored and read back).
  template <class F>
  void pairs(F&& f) const {
    contact_.for_each_fluid_neighbor_of(b_, fluid_x_, f);
  }
  /// f(run) for runs of fluid neighbours (NeighborRun), in the same order.
  template <class F>
  void runs(F&& f) const {
    contact_.for_each_fluid_run_of(b_, fluid_x_, f);
  }

 private:
  const Contact<D>& contact_;
  std::size_t b_;
  const ConstVectorView<D>& fluid_x_;
};

/// For every particle b of `contact`, output.set(b, pass(b, fluid neighbours of b)), the
/// neighbours as FluidNeighborsOf: the passes that give a contact's particles a state from the
/// fluid beside them (passes/wall_state.hpp) or take the fluid's force on them
/// (passes/body_force.hpp).
template <int D, class Pass, class Output>
void for_each_contact_particle(const Contact<D>& contact, const ConstVectorView<D>& fluid_x, const Output& output,
                               const Pass& pass) {
  for_each_particle(contact.particles().size(),
                    [&](std::size_t b) { output.set(b, pass(b, FluidNeighborsOf<D>(contact, b, fluid_x))); });
}

}  // namespace tide::passes
