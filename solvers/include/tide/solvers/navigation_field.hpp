#pragma once

#include <array>
#include <cstddef>
#include <limits>
#include <vector>

#include "tide/core/types.hpp"

namespace tide {

/// The walking distance to the nearest exit on a grid over the floor plane, and the direction
/// that shortens it fastest: the desired direction of every agent (docs/crowds.md,
/// "Navigation"). Computed once per scene by fast marching (Sethian 1996): the first-order upwind
/// solution of the eikonal equation |∇T| = 1 from T = 0 in the exit cells, around blocked cells.
class NavigationField {
 public:
  struct Grid {
    std::array<double, 2> lower{};  // corner of cell (0, 0), m
    double cell = 0;                // m
    std::array<std::size_t, 2> cells{};
    std::array<bool, 2> periodic{};
  };

  /// `blocked` and `goal`, one flag per cell (x fastest), say which cells no one may enter (walls
  /// and a body radius around them) and which lie in an exit.
  NavigationField(const Grid& grid, std::vector<bool> blocked, const std::vector<bool>& goal);

  static constexpr double unreachable = std::numeric_limits<double>::infinity();

  /// The distance to the nearest exit from the cell holding `x` (unreachable from a blocked cell,
  /// outside the grid, or where no exit can be reached).
  double distance(const Vector<2>& x) const;
  /// Whether the cell holding `x` is blocked or outside the grid.
  bool blocked(const Vector<2>& x) const;
  /// The unit direction of −∇T at `x`, interpolated bilinearly between the centres of the four
  /// nearest open cells; zero where all four are blocked.
  Vector<2> direction(const Vector<2>& x) const;

  const Grid& grid() const { return grid_; }

 private:
  // The cell holding x; false outside the grid (after wrapping periodic axes).
  bool cell_of(const Vector<2>& x, std::array<std::size_t, 2>& cell) const;
  // The cell index of (cx + dx, cy + dy), wrapped on periodic axes; false outside the grid.
  bool neighbor(std::size_t cx, std::size_t cy, int dx, int dy, std::size_t& index) const;
  void march(const std::vector<bool>& goal);
  void set_directions();

  Grid grid_;
  std::vector<bool> blocked_;
  std::vector<double> distance_;
  std::vector<std::array<double, 2>> direction_;  // per cell, unit or zero
};

}  // namespace tide
