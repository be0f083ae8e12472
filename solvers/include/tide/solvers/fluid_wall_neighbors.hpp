#pragma once

#include <utility>

#include "tide/core/memory_usage.hpp"
#include "tide/neighbor/neighbor_grid.hpp"
#include "tide/neighbor/neighbor_list.hpp"

namespace tide {

/// The neighbour tables a fluid-with-walls pass needs: fluid–fluid from the fluid grid, and the
/// two cross tables fluid → walls and walls → fluid (both grids share domain and support). Each
/// is walked through a NeighborList built once per fluid update, so the distance filter runs
/// once per step, not once per pass and solver sweep.
template <int D>
class FluidWallNeighbors {
 public:
  FluidWallNeighbors(const GridDomain<D>& domain, Real support_radius)
      : fluid_grid_(domain, support_radius), wall_grid_(domain, support_radius) {}

  /// Sorts the walls once; they do not move, so what only a sort needs (the arena's bytes too:
  /// a tank can have more wall than fluid particles, and the arena would keep their size) and
  /// the walls' table over themselves (no pass walks wall-wall pairs) are freed.
  void set_walls(ParticleSet<D>& walls) {
    wall_grid_.update(walls, arena_);
    wall_grid_.release_update_memory();
    arena_.release();
  }

  /// Re-sorts the fluid, relinks it with the walls (`walls` as last passed to set_walls) and
  /// lists the neighbours; returns the particles removed. The passes' positions must stay those
  /// of this call until the next one. The sort and reorder workspace lives in an arena kept
  /// from step to step.
  std::size_t update_fluid(ParticleSet<D>& fluid, const ParticleSet<D>& walls) {
    const std::size_t removed = fluid_grid_.update(fluid, arena_);
    fluid_to_walls_.build(fluid_grid_, wall_grid_);
    walls_to_fluid_.build(wall_grid_, fluid_grid_);
    const auto fluid_x = std::as_const(fluid)[fluid.position()];
    const auto wall_x = walls[walls.position()];
    fluid_list_.build(fluid_grid_, fluid_x, fluid_grid_.own_neighbors(), fluid_x);
    fluid_to_walls_list_.build(fluid_grid_, fluid_x, fluid_to_walls_, wall_x);
    walls_to_fluid_list_.build(wall_grid_, wall_x, walls_to_fluid_, fluid_x);
    return removed;
  }

  template <class F>
  void for_each_fluid_neighbor(std::size_t i, const ConstVectorView<D>& fluid_x, F&& f) const {
    fluid_list_.for_each(i, fluid_x, fluid_x, f);
  }
  template <class F>
  void for_each_wall_neighbor(std::size_t i, const ConstVectorView<D>& fluid_x, const ConstVectorView<D>& wall_x,
                              F&& f) const {
    fluid_to_walls_list_.for_each(i, fluid_x, wall_x, f);
  }
  /// The same walks in runs of NeighborRun (see NeighborList::for_each_run).
  template <class F>
  void for_each_fluid_run(std::size_t i, const ConstVectorView<D>& fluid_x, F&& f) const {
    fluid_list_.for_each_run(i, fluid_x, fluid_x, f);
  }
  template <class F>
  void for_each_wall_run(std::size_t i, const ConstVectorView<D>& fluid_x, const ConstVectorView<D>& wall_x,
                         F&& f) const {
    fluid_to_walls_list_.for_each_run(i, fluid_x, wall_x, f);
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
  ScratchArena arena_;
  NeighborGrid<D> fluid_grid_;
  NeighborGrid<D> wall_grid_;
  CrossNeighbors<D> fluid_to_walls_;
  CrossNeighbors<D> walls_to_fluid_;
  NeighborList<D> fluid_list_;
  NeighborList<D> fluid_to_walls_list_;
  NeighborList<D> walls_to_fluid_list_;
};

template <int D>
std::size_t FluidWallNeighbors<D>::bytes() const {
  MemoryUsage usage;
  add_memory(usage);
  return usage.total();
}

template <int D>
void FluidWallNeighbors<D>::add_memory(MemoryUsage& usage) const {
  usage.add("arena.sort and reorder", arena_.bytes());
  fluid_grid_.add_memory(usage, "fluid grid");
  wall_grid_.add_memory(usage, "wall grid");
  fluid_to_walls_.add_memory(usage, "fluid-wall table");
  walls_to_fluid_.add_memory(usage, "wall-fluid table");
  fluid_list_.add_memory(usage, "fluid list");
  fluid_to_walls_list_.add_memory(usage, "fluid-wall list");
  walls_to_fluid_list_.add_memory(usage, "wall-fluid list");
}

}  // namespace tide
