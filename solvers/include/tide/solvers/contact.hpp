#pragma once

#include <string>
#include <utility>
#include <vector>

#include "tide/core/memory_usage.hpp"
#include "tide/core/particle_set.hpp"
#include "tide/neighbor/neighbor_grid.hpp"
#include "tide/neighbor/neighbor_list.hpp"
#include "tide/solvers/particle_fields.hpp"

namespace tide {

template <int D>
class Interactions;

/// What a contact's particles are to the fluid. Walls are boundary particles whose pressure,
/// density and (no-slip) velocity are extrapolated from the fluid beside them (Adami, Hu & Adams
/// 2012; passes/wall_state.hpp).
enum class ContactRole { wall };

/// Whether a contact's particles change position during a run. A static contact is sorted into
/// its grid once; a moving one is re-sorted with the fluid whenever the lists are rebuilt, and
/// its displacement counts in the skin's check (Interactions).
enum class ContactMotion { fixed, moving };

/// A set of particles the fluid interacts with (the "contact relation" of SPHinXsys, as opposed
/// to the fluid's inner one): the particles and their field handles, their role, and the
/// neighbour lists from the fluid into them and back, which Interactions builds and refines.
/// Passes read a contact through its fields and its walks; only Interactions changes its lists.
template <int D>
class Contact {
 public:
  Contact(std::string name, ContactRole role, ContactMotion motion, ParticleSet<D> particles, WallFields<D> fields,
          const GridDomain<D>& domain, Real support_radius, Real skin)
      : name_(std::move(name)),
        role_(role),
        motion_(motion),
        particles_(std::move(particles)),
        fields_(std::move(fields)),
        grid_(domain, support_radius, SortAlgorithm::radix, CellLookup::automatic, skin) {}

  Contact(const Contact&) = delete;
  Contact& operator=(const Contact&) = delete;

  const std::string& name() const { return name_; }
  ContactRole role() const { return role_; }
  bool moves() const { return motion_ == ContactMotion::moving; }
  /// Whether the fluid feels the contact's viscosity: no-slip walls, which carry the mirrored
  /// velocity the viscous terms read; free-slip walls have no velocity field.
  bool viscous() const { return fields_.velocity.has_value(); }

  ParticleSet<D>& particles() { return particles_; }
  const ParticleSet<D>& particles() const { return particles_; }
  const WallFields<D>& fields() const { return fields_; }
  /// The particles' positions as of the last Interactions::update (or add_contact), kept so that
  /// a walk does not look the field up once per fluid particle.
  const ConstVectorView<D>& positions() const { return positions_; }
  const NeighborGrid<D>& grid() const { return grid_; }

  /// Calls f(b, x_ib, r²) for every contact neighbour b of fluid particle i (NeighborList::for_each).
  template <class F>
  void for_each_neighbor(std::size_t i, const ConstVectorView<D>& fluid_x, F&& f) const {
    fluid_to_contact_list_.for_each(i, fluid_x, positions(), f);
  }
  /// The same walk in runs of NeighborRun (NeighborList::for_each_run).
  template <bool Offsets = true, class F>
  void for_each_run(std::size_t i, const ConstVectorView<D>& fluid_x, F&& f) const {
    fluid_to_contact_list_.template for_each_run<Offsets>(i, fluid_x, positions(), f);
  }
  /// Calls f(j, x_bj, r²) for every fluid neighbour j of contact particle b.
  template <class F>
  void for_each_fluid_neighbor_of(std::size_t b, const ConstVectorView<D>& fluid_x, F&& f) const {
    contact_to_fluid_list_.for_each(b, positions(), fluid_x, f);
  }
  /// The same walk in runs of NeighborRun.
  template <class F>
  void for_each_fluid_run_of(std::size_t b, const ConstVectorView<D>& fluid_x, F&& f) const {
    contact_to_fluid_list_.for_each_run(b, positions(), fluid_x, f);
  }

  /// Adds one item per buffer of its fields, grid, cross tables and lists, named after the
  /// contact ("<name> grid", "fluid-<name> list", ...).
  void add_memory(MemoryUsage& usage, bool skin) const {
    particles_.add_memory(usage, name_);
    grid_.add_memory(usage, name_ + " grid");
    fluid_to_contact_.add_memory(usage, "fluid-" + name_ + " table");
    contact_to_fluid_.add_memory(usage, name_ + "-fluid table");
    fluid_to_contact_list_.add_memory(usage, "fluid-" + name_ + " list");
    contact_to_fluid_list_.add_memory(usage, name_ + "-fluid list");
    if (!skin) return;
    fluid_to_contact_candidates_.add_memory(usage, "fluid-" + name_ + " candidates");
    contact_to_fluid_candidates_.add_memory(usage, name_ + "-fluid candidates");
    if (moves()) usage.add(name_ + " candidates.positions at build", built_x_);
  }

 private:
  friend class Interactions<D>;

  std::string name_;
  ContactRole role_;
  ContactMotion motion_;
  ParticleSet<D> particles_;
  WallFields<D> fields_;
  NeighborGrid<D> grid_;
  CrossNeighbors<D> fluid_to_contact_;
  CrossNeighbors<D> contact_to_fluid_;
  // With a skin only: the lists of radius support + skin the walked lists are refined from.
  NeighborList<D> fluid_to_contact_candidates_;
  NeighborList<D> contact_to_fluid_candidates_;
  NeighborList<D> fluid_to_contact_list_;
  NeighborList<D> contact_to_fluid_list_;
  std::vector<Real> built_x_;  // moving, with a skin: positions at the last build, by component
  ConstVectorView<D> positions_;
};

}  // namespace tide
