#pragma once

// A frame (frame.hpp) and the numbers the page and the tests read (status.hpp), taken from a
// running 2D simulation.

#include "tide/serve/frame.hpp"
#include "tide/solvers/simulation.hpp"

namespace tide::serve {

/// The particles of `simulation` now, coloured by `colour`: speed from 0 to the first
/// material's max_speed (2 m/s without one), density within 3% of the rest density, pressure from
/// 0 to the highest now. The fluid's walls are the contacts that stay still, the obstacle those
/// that move.
Frame snapshot(const Simulation<2>& simulation, ColourField colour);

/// Means over the fluid, for the status the page and the tests read.
struct FluidSummary {
  double mean_x = 0, mean_y = 0;          // m
  double mean_speed = 0, max_speed = 0;   // m/s
  double obstacle_x = 0, obstacle_y = 0;  // m, the centroid of the moving walls' particles (0 without)
};

FluidSummary summarise(const Frame& frame, const Simulation<2>& simulation);

}  // namespace tide::serve
