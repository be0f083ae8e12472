#pragma once

#include <cstddef>
#include <span>
#include <utility>
#include <vector>

#include "tide/core/memory_usage.hpp"
#include "tide/core/parallel.hpp"
#include "tide/neighbor/neighbor_grid.hpp"
#include "tide/neighbor/neighbor_list.hpp"

namespace tide {

/// The neighbour tables a fluid-with-walls pass needs: fluid–fluid from the fluid grid, and the
/// two cross tables fluid → walls and walls → fluid (both grids share domain, support and skin).
/// Each is walked through a NeighborList, so the distance filter of the cell walk runs once per
/// step, not once per pass and solver sweep.
///
/// Without a skin, every fluid update re-sorts the fluid and rebuilds the lists. With a skin s,
/// an update re-sorts the fluid and rebuilds the candidate lists (radius support + s) only when
/// they no longer hold every pair inside the support: the fluid has as many particles as at the
/// last build, all inside the domain box (a particle outside is removed, or wrapped on a periodic
/// axis, only by a rebuild), and none has moved more than s/2 since (two particles close in by s
/// at most; the walls do not move). Every update then refines the candidates into the lists the
/// passes walk.
template <int D>
class FluidWallNeighbors {
 public:
  FluidWallNeighbors(const GridDomain<D>& domain, Real support_radius, Real skin = 0)
      : fluid_grid_(domain, support_radius, SortAlgorithm::radix, CellLookup::automatic, skin),
        wall_grid_(domain, support_radius, SortAlgorithm::radix, CellLookup::automatic, skin) {}

  /// Sorts the walls once; they do not move, so what only a sort needs (the arena's bytes too:
  /// a tank can have more wall than fluid particles, and the arena would keep their size) and
  /// the walls' table over themselves (no pass walks wall-wall pairs) are freed.
  void set_walls(ParticleSet<D>& walls) {
    wall_grid_.update(walls, arena_);
    wall_grid_.release_update_memory();
    arena_.release();
  }

  /// When update_fluid lists the fluid–fluid and fluid → wall pairs: at once, or (with a skin)
  /// in the next walk_fluid_pairs, which then refines the candidates and hands out the pairs in
  /// one walk. No other walk may run between that update and that walk_fluid_pairs.
  enum class Listing { now, in_next_pair_walk };

  /// Re-sorts the fluid, relinks it with the walls (`walls` as last passed to set_walls) and
  /// lists the neighbours (see the class for what a skin changes, and Listing); returns the
  /// particles removed. The passes' positions must stay those of this call until the next one.
  /// The sort and reorder workspace lives in an arena kept from step to step.
  std::size_t update_fluid(ParticleSet<D>& fluid, const ParticleSet<D>& walls, Listing listing = Listing::now) {
    const bool skin = fluid_grid_.skin() > 0;
    std::size_t removed = 0;
    const auto fluid_x = std::as_const(fluid)[fluid.position()];
    const auto wall_x = walls[walls.position()];
    if (!skin || !candidates_hold(fluid)) {
      removed = fluid_grid_.update(fluid, arena_);
      fluid_to_walls_.build(fluid_grid_, wall_grid_);
      walls_to_fluid_.build(wall_grid_, fluid_grid_);
      (skin ? fluid_candidates_ : fluid_list_).build(fluid_grid_, fluid_x, fluid_grid_.own_neighbors(), fluid_x);
      (skin ? fluid_to_walls_candidates_ : fluid_to_walls_list_).build(fluid_grid_, fluid_x, fluid_to_walls_, wall_x);
      (skin ? walls_to_fluid_candidates_ : walls_to_fluid_list_).build(wall_grid_, wall_x, walls_to_fluid_, fluid_x);
      ++builds_;
      if (skin) {
        built_x_.resize(D * fluid.size());
        for_each_particle(fluid.size(), [&](std::size_t i) {
          for (int d = 0; d < D; ++d) built_x_[d * fluid.size() + i] = fluid_x.component[d][i];
        });
      }
    }
    listing_pending_ = skin && listing == Listing::in_next_pair_walk;
    if (skin && !listing_pending_) {
      fluid_list_.refine(fluid_candidates_, fluid_x, fluid_x);
      fluid_to_walls_list_.refine(fluid_to_walls_candidates_, fluid_x, wall_x);
    }
    if (skin) walls_to_fluid_list_.refine(walls_to_fluid_candidates_, wall_x, fluid_x);
    return removed;
  }

  /// Calls on_fluid(i, runs) and then on_wall(i, runs) for every fluid particle i, where runs(f)
  /// calls f(run) for the NeighborRuns of i's fluid (wall) neighbours with their indices and r²,
  /// in the order of the other walks (x_ij and gradients are not all set). After
  /// update_fluid(…, Listing::in_next_pair_walk) it lists those pairs as it goes, reading each
  /// candidate's position once for the list and the pass (NeighborList::refine).
  template <class OnFluid, class OnWall>
  void walk_fluid_pairs(const ConstVectorView<D>& fluid_x, const ConstVectorView<D>& wall_x, OnFluid&& on_fluid,
                        OnWall&& on_wall) {
    if (listing_pending_) {
      fluid_list_.refine(fluid_candidates_, fluid_x, fluid_x, on_fluid);
      fluid_to_walls_list_.refine(fluid_to_walls_candidates_, fluid_x, wall_x, on_wall);
      listing_pending_ = false;
      return;
    }
    for_each_particle(fluid_grid_.particle_count(), [&](std::size_t i) {
      on_fluid(i, [&](auto&& f) { fluid_list_.for_each_run(i, fluid_x, fluid_x, f); });
      on_wall(i, [&](auto&& f) { fluid_to_walls_list_.for_each_run(i, fluid_x, wall_x, f); });
    });
  }

  /// Caches `kernel`'s gradient ∇W of every fluid–fluid and fluid → wall pair at the positions
  /// of the last update_fluid (NeighborList::cache_gradients), for the runs walked until the
  /// next update, which drops them; passes that take those runs must use the same kernel.
  template <class Kernel>
  void cache_gradients(const Kernel& kernel, const ConstVectorView<D>& fluid_x, const ConstVectorView<D>& wall_x) {
    const auto derivative_over_r = [&](Real r) { return kernel.derivative_over_r(r); };
    fluid_list_.cache_gradients(fluid_x, fluid_x, derivative_over_r);
    fluid_to_walls_list_.cache_gradients(fluid_x, wall_x, derivative_over_r);
  }

  /// `count` Reals of the update's sort and reorder arena, which no update needs between two
  /// calls of update_fluid: scratch for one pass, valid until the next call of this or of
  /// update_fluid.
  std::span<Real> pass_scratch(std::size_t count) {
    arena_.reset(ScratchArena::aligned(count * sizeof(Real)));
    return arena_.take<Real>(count);
  }

  /// Whether the last update left the fluid–fluid and fluid → wall lists to walk_fluid_pairs.
  bool listing_pending() const { return listing_pending_; }

  /// Fluid updates that re-sorted the fluid and rebuilt the lists, the first included.
  std::size_t builds() const { return builds_; }

  template <class F>
  void for_each_fluid_neighbor(std::size_t i, const ConstVectorView<D>& fluid_x, F&& f) const {
    fluid_list_.for_each(i, fluid_x, fluid_x, f);
  }
  template <class F>
  void for_each_wall_neighbor(std::size_t i, const ConstVectorView<D>& fluid_x, const ConstVectorView<D>& wall_x,
                              F&& f) const {
    fluid_to_walls_list_.for_each(i, fluid_x, wall_x, f);
  }
  /// The same walks in runs of NeighborRun (see NeighborList::for_each_run; `Offsets` false: a
  /// pass that needs only the gradients, where they are cached).
  template <bool Offsets = true, class F>
  void for_each_fluid_run(std::size_t i, const ConstVectorView<D>& fluid_x, F&& f) const {
    fluid_list_.template for_each_run<Offsets>(i, fluid_x, fluid_x, f);
  }
  template <bool Offsets = true, class F>
  void for_each_wall_run(std::size_t i, const ConstVectorView<D>& fluid_x, const ConstVectorView<D>& wall_x,
                         F&& f) const {
    fluid_to_walls_list_.template for_each_run<Offsets>(i, fluid_x, wall_x, f);
  }
  template <class F>
  void for_each_fluid_neighbor_of_wall(std::size_t b, const ConstVectorView<D>& wall_x,
                                       const ConstVectorView<D>& fluid_x, F&& f) const {
    walls_to_fluid_list_.for_each(b, wall_x, fluid_x, f);
  }

  const NeighborGrid<D>& fluid_grid() const { return fluid_grid_; }
  const NeighborGrid<D>& wall_grid() const { return wall_grid_; }
  std::size_t bytes() const;

  /// Adds one item per buffer of the grids, cross tables and lists.
  void add_memory(MemoryUsage& usage) const;

 private:
  bool candidates_hold(const ParticleSet<D>& fluid) const {
    const std::size_t n = fluid.size();
    if (builds_ == 0 || n != fluid_grid_.particle_count()) return false;
    const auto x = fluid[fluid.position()];
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
            const Real moved = xd - built_x_[d * n + i];
            moved2 += moved * moved;
          }
          return inside && moved2 <= half_skin * half_skin;
        },
        [](bool a, bool b) { return a && b; });
  }

  ScratchArena arena_;
  NeighborGrid<D> fluid_grid_;
  NeighborGrid<D> wall_grid_;
  CrossNeighbors<D> fluid_to_walls_;
  CrossNeighbors<D> walls_to_fluid_;
  // With a skin only: the lists of radius support + skin the walked lists are refined from.
  NeighborList<D> fluid_candidates_;
  NeighborList<D> fluid_to_walls_candidates_;
  NeighborList<D> walls_to_fluid_candidates_;
  NeighborList<D> fluid_list_;
  NeighborList<D> fluid_to_walls_list_;
  NeighborList<D> walls_to_fluid_list_;
  std::vector<Real> built_x_;  // with a skin: the fluid's positions at the last build, by component
  std::size_t builds_ = 0;
  bool listing_pending_ = false;  // update_fluid left the fluid and fluid → wall lists to walk_fluid_pairs
};

template <int D>
std::size_t FluidWallNeighbors<D>::bytes() const {
  MemoryUsage usage;
  add_memory(usage);
  return usage.total();
}

template <int D>
void FluidWallNeighbors<D>::add_memory(MemoryUsage& usage) const {
  usage.add("arena.sort and reorder", arena_.bytes());  // and the passes' scratch
  fluid_grid_.add_memory(usage, "fluid grid");
  wall_grid_.add_memory(usage, "wall grid");
  fluid_to_walls_.add_memory(usage, "fluid-wall table");
  walls_to_fluid_.add_memory(usage, "wall-fluid table");
  fluid_list_.add_memory(usage, "fluid list");
  fluid_to_walls_list_.add_memory(usage, "fluid-wall list");
  walls_to_fluid_list_.add_memory(usage, "wall-fluid list");
  if (fluid_grid_.skin() == 0) return;
  fluid_candidates_.add_memory(usage, "fluid candidates");
  fluid_to_walls_candidates_.add_memory(usage, "fluid-wall candidates");
  walls_to_fluid_candidates_.add_memory(usage, "wall-fluid candidates");
  usage.add("fluid candidates.positions at build", built_x_);
}

}  // namespace tide
