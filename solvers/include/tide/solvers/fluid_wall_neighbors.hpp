#pragma once

#include "tide/neighbor/neighbor_grid.hpp"

namespace tide {

/// The neighbour tables a fluid-with-walls pass needs: fluid–fluid from the fluid grid, and the
/// two cross tables fluid → walls and walls → fluid (both grids share domain and support).
template <int D>
class FluidWallNeighbors {
 public:
  FluidWallNeighbors(const GridDomain<D>& domain, Real support_radius)
      : fluid_grid_(domain, support_radius), wall_grid_(domain, support_radius) {}

  /// Sorts the walls once; they do not move.
  void set_walls(ParticleSet<D>& walls) { wall_grid_.update(walls); }

  /// Re-sorts the fluid and relinks it with the walls; returns the particles removed.
  std::size_t update_fluid(ParticleSet<D>& fluid) {
    const std::size_t removed = fluid_grid_.update(fluid);
    fluid_to_walls_.build(fluid_grid_, wall_grid_);
    walls_to_fluid_.build(wall_grid_, fluid_grid_);
    return removed;
  }

  template <class F>
  void for_each_fluid_neighbor(std::size_t i, const ConstVectorView<D>& fluid_x, F&& f) const {
    fluid_grid_.for_each_neighbor(i, fluid_x, f);
  }
  template <class F>
  void for_each_wall_neighbor(std::size_t i, const ConstVectorView<D>& fluid_x, const ConstVectorView<D>& wall_x,
                              F&& f) const {
    fluid_to_walls_.for_each_in_cell(fluid_grid_.particle_cell(i), fluid_x[i], wall_x, f);
  }
  template <class F>
  void for_each_fluid_neighbor_of_wall(std::size_t b, const ConstVectorView<D>& wall_x,
                                       const ConstVectorView<D>& fluid_x, F&& f) const {
    walls_to_fluid_.for_each_in_cell(wall_grid_.particle_cell(b), wall_x[b], fluid_x, f);
  }

  const NeighborGrid<D>& fluid_grid() const { return fluid_grid_; }
  const NeighborGrid<D>& wall_grid() const { return wall_grid_; }
  std::size_t bytes() const;

 private:
  NeighborGrid<D> fluid_grid_;
  NeighborGrid<D> wall_grid_;
  CrossNeighbors<D> fluid_to_walls_;
  CrossNeighbors<D> walls_to_fluid_;
};

template <int D>
std::size_t FluidWallNeighbors<D>::bytes() const {
  return fluid_to_walls_.bytes() + walls_to_fluid_.bytes() +
         fluid_grid_.bytes_per_particle() * fluid_grid_.particle_count() +
         wall_grid_.bytes_per_particle() * wall_grid_.particle_count();
}

}  // namespace tide
