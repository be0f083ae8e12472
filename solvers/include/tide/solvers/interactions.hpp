#pragma once

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <memory>
#include <span>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "tide/core/kernels/runtime_kernel.hpp"
#include "tide/core/memory_usage.hpp"
#include "tide/core/parallel.hpp"
#include "tide/core/particle_set_state.hpp"
#include "tide/core/scratch_arena.hpp"
#include "tide/core/state_archive.hpp"
#include "tide/neighbor/neighbor_grid.hpp"
#include "tide/neighbor/neighbor_list.hpp"
#include "tide/solvers/contact.hpp"

namespace tide {

/// The fluid's neighbour relations: its inner list (fluid–fluid, from the fluid grid) and any
/// number of contacts (Contact: walls today), each with the lists from the fluid into it and
/// back. All grids share domain, support and skin. Each list is walked through a NeighborList,
/// so the distance filter of the cell walk runs once per step, not once per pass and sweep.
///
/// Without a skin, every update re-sorts the fluid (and the moving contacts) and rebuilds every
/// list. With a skin s, an update re-sorts and rebuilds the candidate lists (radius support + s)
/// only when they no longer hold every pair inside the support: the fluid has as many particles
/// as at the last build, all inside the domain box (a particle outside is removed, or wrapped on
/// a periodic axis, only by a rebuild), and no fluid or moving-contact particle has moved more
/// than s/2 since (two particles close in by s at most). Every update then refines the
/// candidates into the lists the passes walk.
///
/// Passes do not walk these lists themselves: passes/neighbor_walk.hpp does, fluid then each
/// contact in the order they were added.
template <int D>
class Interactions {
 public:
  Interactions(const GridDomain<D>& domain, Real support_radius, Real skin = 0)
      : fluid_grid_(domain, support_radius, SortAlgorithm::radix, CellLookup::automatic, skin) {}

  /// Adds a contact and sorts its particles into its grid. A fixed contact is sorted once, so
  /// what only a sort needs (the arena's bytes too: a tank can have more wall than fluid
  /// particles, and the arena would keep their size) and its table over itself (no pass walks
  /// contact–contact pairs) are freed. Call before the first update.
  Contact<D>& add_contact(std::string name, ContactRole role, ContactMotion motion, ParticleSet<D> particles,
                          WallFields<D> fields) {
    auto& contact = *contacts_.emplace_back(
        std::make_unique<Contact<D>>(std::move(name), role, motion, std::move(particles), std::move(fields),
                                     fluid_grid_.domain(), fluid_grid_.support_radius(), fluid_grid_.skin()));
    contact.grid_.update(contact.particles_, arena_);
    contact.positions_ = std::as_const(contact.particles_)[contact.fields_.position];
    if (!contact.moves()) {
      contact.grid_.release_update_memory();
      arena_.release();
    }
    return contact;
  }

  std::size_t contact_count() const { return contacts_.size(); }
  Contact<D>& contact(std::size_t k) { return *contacts_[k]; }
  const Contact<D>& contact(std::size_t k) const { return *contacts_[k]; }

  /// When update lists the fluid–fluid and fluid → contact pairs: at once, or (with a skin) in
  /// the next walk_fluid_pairs, which then refines the candidates and hands out the pairs in one
  /// walk. No other walk may run between that update and that walk_fluid_pairs.
  enum class Listing { now, in_next_pair_walk };

  /// Re-sorts the fluid (and the moving contacts), relinks them and lists the neighbours (see
  /// the class for what a skin changes, and Listing); returns the fluid particles removed. The
  /// passes' positions must stay those of this call until the next one. The sort and reorder
  /// workspace lives in an arena kept from step to step.
  std::size_t update(ParticleSet<D>& fluid, Listing listing = Listing::now) {
    const bool skin = fluid_grid_.skin() > 0;
    std::size_t removed = 0;
    for (auto& contact : contacts_) contact->positions_ = std::as_const(contact->particles_)[contact->fields_.position];
    if (!skin || !candidates_hold(fluid)) removed = rebuild(fluid);
    refine(fluid, listing);
    return removed;
  }

  /// What the next step reads of the neighbour relations, under "neighbors/": every contact's
  /// particles (the walls' extrapolated state, the moving ones' sorted order), the positions of
  /// the last build (with a skin), the build and removal counts.
  void save(StateArchive& archive) const {
    for (std::size_t k = 0; k < contacts_.size(); ++k) {
      const Contact<D>& contact = *contacts_[k];
      save_particles(archive, contact_path(k), contact.particles_);
      if (!contact.built_x_.empty()) archive.put_reals(contact_path(k) + "/.built_position", contact.built_x_);
    }
    archive.put_reals("neighbors/fluid_built_position", built_x_);
    archive.put_counts("neighbors/counts", {builds_, fluid_grid_.removed_total()});
  }

  /// The state save() put, for `fluid` restored as it was then (same scene, same order). The lists
  /// come back by a rebuild at the positions of the last build (with a skin): the sort of the set,
  /// already in the order of those positions, is the identity (stable), so the grid and candidate
  /// lists are those of that build, refined at the present positions as the last update did.
  /// Without a skin every update rebuilds, so the lists are rebuilt (at the present positions) only
  /// when `next_step` walks them before its update (the incompressible schemes' solves).
  enum class NextStep { updates_first, walks_first };
  void restore(const StateArchive& archive, ParticleSet<D>& fluid, NextStep next_step) {
    for (std::size_t k = 0; k < contacts_.size(); ++k) {
      Contact<D>& contact = *contacts_[k];
      restore_particles(archive, contact_path(k), contact.particles_);
      contact.positions_ = std::as_const(contact.particles_)[contact.fields_.position];
    }
    const bool skin = fluid_grid_.skin() > 0;
    if (skin) {
      std::vector<std::vector<Real>> present;  // the positions now, put back after the rebuild
      present.push_back(swap_positions(fluid, archive.reals("neighbors/fluid_built_position")));
      for (std::size_t k = 0; k < contacts_.size(); ++k)
        if (contacts_[k]->moves())
          present.push_back(
              swap_positions(contacts_[k]->particles_, archive.reals(contact_path(k) + "/.built_position")));
      rebuild(fluid);
      std::size_t kept = 0;
      swap_positions(fluid, present[kept++]);
      for (auto& contact : contacts_)
        if (contact->moves()) swap_positions(contact->particles_, present[kept++]);
      refine(fluid, Listing::now);
    } else if (next_step == NextStep::walks_first) {
      rebuild(fluid);
      refine(fluid, Listing::now);
    }
    const std::span<const std::uint64_t> counts = archive.counts("neighbors/counts");
    builds_ = counts[0];
    fluid_grid_.restore_removed_total(counts[1]);
  }

  /// Calls on_fluid(i, runs) for every fluid particle i, and then on_contact(i, k, runs) for
  /// every contact k, where runs(f) calls f(run) for the NeighborRuns of i's fluid (contact)
  /// neighbours with their indices and r², in the order of the other walks (x_ij and gradients
  /// are not all set). After update(…, Listing::in_next_pair_walk) it lists those pairs as it
  /// goes, reading each candidate's position once for the list and the pass
  /// (NeighborList::refine); the fluid and each contact are then walked one after the other,
  /// every particle each time, so on_fluid and on_contact keep what they carry over between
  /// them in particle i's own fields.
  template <class OnFluid, class OnContact>
  void walk_fluid_pairs(const ConstVectorView<D>& fluid_x, OnFluid&& on_fluid, OnContact&& on_contact) {
    if (listing_pending_) {
      fluid_list_.refine(fluid_candidates_, fluid_x, fluid_x, on_fluid);
      for (std::size_t k = 0; k < contacts_.size(); ++k) {
        Contact<D>& c = *contacts_[k];
        c.fluid_to_contact_list_.refine(c.fluid_to_contact_candidates_, fluid_x, c.positions(),
                                        [&](std::size_t i, const auto& runs) { on_contact(i, k, runs); });
      }
      listing_pending_ = false;
      return;
    }
    for_each_particle(fluid_grid_.particle_count(), [&](std::size_t i) {
      on_fluid(i, [&](auto&& f) { fluid_list_.for_each_run(i, fluid_x, fluid_x, f); });
      for (std::size_t k = 0; k < contacts_.size(); ++k)
        on_contact(i, k, [&](auto&& f) { contacts_[k]->for_each_run(i, fluid_x, f); });
    });
  }

  /// Caches `kernel`'s gradient ∇W of every fluid–fluid and fluid → contact pair at the
  /// positions of the last update (NeighborList::cache_gradients), for the runs walked until the
  /// next update, which drops them; passes that take those runs must use the same kernel.
  void cache_gradients(const RuntimeKernel<D>& kernel, const ConstVectorView<D>& fluid_x) {
    // Instantiated per kernel, so that its derivative is computed in the pair loop.
    kernel.visit([&](const auto& concrete) {
      const auto derivative_over_r = [&](Real r) { return concrete.derivative_over_r(r); };
      fluid_list_.cache_gradients(fluid_x, fluid_x, derivative_over_r);
      for (auto& contact : contacts_)
        contact->fluid_to_contact_list_.cache_gradients(fluid_x, contact->positions(), derivative_over_r);
    });
  }

  /// `count` Reals of the update's sort and reorder arena, which no update needs between two
  /// calls of update: scratch for one pass, valid until the next call of this or of update.
  std::span<Real> pass_scratch(std::size_t count) {
    arena_.reset(ScratchArena::aligned(count * sizeof(Real)));
    return arena_.take<Real>(count);
  }

  /// The number of particles over every contact.
  std::size_t contact_particle_count() const {
    std::size_t count = 0;
    for (const auto& contact : contacts_) count += contact->particles().size();
    return count;
  }

  /// Whether some contact is viscous (Contact::viscous: no-slip walls).
  bool has_viscous_contact() const {
    for (const auto& contact : contacts_)
      if (contact->viscous()) return true;
    return false;
  }

  /// Whether the last update left the fluid–fluid and fluid → contact lists to walk_fluid_pairs.
  bool listing_pending() const { return listing_pending_; }

  /// Updates that re-sorted the fluid and rebuilt the lists, the first included.
  std::size_t builds() const { return builds_; }

  /// Calls f(j, x_ij, r²) for every fluid neighbour j of fluid particle i (NeighborList::for_each).
  template <class F>
  void for_each_fluid_neighbor(std::size_t i, const ConstVectorView<D>& fluid_x, F&& f) const {
    fluid_list_.for_each(i, fluid_x, fluid_x, f);
  }
  /// The same walk in runs of NeighborRun (NeighborList::for_each_run; `Offsets` false: a pass
  /// that needs only the gradients, where they are cached).
  template <bool Offsets = true, class F>
  void for_each_fluid_run(std::size_t i, const ConstVectorView<D>& fluid_x, F&& f) const {
    fluid_list_.template for_each_run<Offsets>(i, fluid_x, fluid_x, f);
  }

  const NeighborGrid<D>& fluid_grid() const { return fluid_grid_; }
  std::size_t bytes() const {
    MemoryUsage usage;
    add_memory(usage);
    return usage.total();
  }

  /// Adds one item per buffer of the grids, cross tables, lists and contact fields.
  void add_memory(MemoryUsage& usage) const {
    const bool skin = fluid_grid_.skin() > 0;
    usage.add("arena.sort and reorder", arena_.bytes());  // and the passes' scratch
    fluid_grid_.add_memory(usage, "fluid grid");
    fluid_list_.add_memory(usage, "fluid list");
    if (skin) {
      fluid_candidates_.add_memory(usage, "fluid candidates");
      usage.add("fluid candidates.positions at build", built_x_);
    }
    for (const auto& contact : contacts_) contact->add_memory(usage, skin);
  }

 private:
  // Re-sorts the fluid and the moving contacts and rebuilds the cross tables and the lists (the
  // candidates, with a skin); returns the fluid particles removed.
  std::size_t rebuild(ParticleSet<D>& fluid) {
    const bool skin = fluid_grid_.skin() > 0;
    const std::size_t removed = fluid_grid_.update(fluid, arena_);
    const auto fluid_x = std::as_const(fluid)[fluid.position()];
    for (auto& contact : contacts_) {
      if (contact->moves()) contact->grid_.update(contact->particles_, arena_);
      contact->positions_ = std::as_const(contact->particles_)[contact->fields_.position];
      contact->fluid_to_contact_.build(fluid_grid_, contact->grid_);
      contact->contact_to_fluid_.build(contact->grid_, fluid_grid_);
    }
    (skin ? fluid_candidates_ : fluid_list_).build(fluid_grid_, fluid_x, fluid_grid_.own_neighbors(), fluid_x);
    for (auto& contact : contacts_) {
      const auto contact_x = contact->positions();
      (skin ? contact->fluid_to_contact_candidates_ : contact->fluid_to_contact_list_)
          .build(fluid_grid_, fluid_x, contact->fluid_to_contact_, contact_x);
      (skin ? contact->contact_to_fluid_candidates_ : contact->contact_to_fluid_list_)
          .build(contact->grid_, contact_x, contact->contact_to_fluid_, fluid_x);
    }
    ++builds_;
    if (skin) {
      keep_positions(fluid_x, fluid.size(), built_x_);
      for (auto& contact : contacts_)
        if (contact->moves()) keep_positions(contact->positions(), contact->particles_.size(), contact->built_x_);
    }
    return removed;
  }

  // With a skin: the lists from the candidates at the present positions, now or (Listing) in the
  // next walk_fluid_pairs.
  void refine(const ParticleSet<D>& fluid, Listing listing) {
    const bool skin = fluid_grid_.skin() > 0;
    const auto fluid_x = fluid[fluid.position()];
    listing_pending_ = skin && listing == Listing::in_next_pair_walk;
    if (skin && !listing_pending_) {
      fluid_list_.refine(fluid_candidates_, fluid_x, fluid_x);
      for (auto& contact : contacts_)
        contact->fluid_to_contact_list_.refine(contact->fluid_to_contact_candidates_, fluid_x, contact->positions());
    }
    if (skin) {
      for (auto& contact : contacts_)
        contact->contact_to_fluid_list_.refine(contact->contact_to_fluid_candidates_, contact->positions(), fluid_x);
    }
  }

  static std::string contact_path(std::size_t k) { return "neighbors/contact_" + std::to_string(k); }

  // Gives `set` the positions `positions` (by component, [d * n + i]) and returns those it had.
  static std::vector<Real> swap_positions(ParticleSet<D>& set, std::span<const Real> positions) {
    const std::size_t n = set.size();
    if (positions.size() != D * n)
      throw std::runtime_error("checkpoint: the positions of the last neighbour build are " +
                               std::to_string(positions.size()) + " values for " + std::to_string(n) + " particles");
    std::vector<Real> before;
    keep_positions(std::as_const(set)[set.position()], n, before);
    const VectorView<D> x = set[set.position()];
    for (int d = 0; d < D; ++d) std::copy_n(positions.begin() + d * n, n, x.component[d]);
    return before;
  }

  // Positions by component, [d * n + i].
  static void keep_positions(const ConstVectorView<D>& x, std::size_t n, std::vector<Real>& kept) {
    kept.resize(D * n);
    for_each_particle(n, [&](std::size_t i) {
      for (int d = 0; d < D; ++d) kept[d * n + i] = x.component[d][i];
    });
  }

  // Whether all n particles of `x` are inside the domain box and none has moved more than half
  // the skin since `kept`.
  bool within_half_skin(const ConstVectorView<D>& x, std::size_t n, const std::vector<Real>& kept) const {
    const GridDomain<D>& domain = fluid_grid_.domain();
    const Real half_skin = fluid_grid_.skin() / 2;
    return reduce(
        n, true,
        [&](std::size_t i) {
          Real moved2 = 0;
          bool inside = true;
          for (int d = 0; d < D; ++d) {
            const Real xd = x.component[d][i];
            inside = inside && xd >= domain.lower[d] && xd < domain.upper[d];
            const Real moved = xd - kept[d * n + i];
            moved2 += moved * moved;
          }
          return inside && moved2 <= half_skin * half_skin;
        },
        [](bool a, bool b) { return a && b; });
  }

  bool candidates_hold(const ParticleSet<D>& fluid) const {
    const std::size_t n = fluid.size();
    if (builds_ == 0 || n != fluid_grid_.particle_count()) return false;
    if (!within_half_skin(fluid[fluid.position()], n, built_x_)) return false;
    for (const auto& contact : contacts_) {
      if (!contact->moves()) continue;
      const std::size_t m = contact->particles_.size();
      if (m != contact->grid_.particle_count() || !within_half_skin(contact->positions(), m, contact->built_x_))
        return false;
    }
    return true;
  }

  ScratchArena arena_;
  NeighborGrid<D> fluid_grid_;
  // With a skin only: the list of radius support + skin the walked list is refined from.
  NeighborList<D> fluid_candidates_;
  NeighborList<D> fluid_list_;
  // Each contact keeps its address: its lists point at its grid.
  std::vector<std::unique_ptr<Contact<D>>> contacts_;
  std::vector<Real> built_x_;  // with a skin: the fluid's positions at the last build, by component
  std::size_t builds_ = 0;
  bool listing_pending_ = false;  // update left the fluid and fluid → contact lists to walk_fluid_pairs
};

}  // namespace tide
