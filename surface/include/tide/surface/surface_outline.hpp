#pragma once

// The free-surface outline of a 2D fluid from its particles: the colour field (colour_field.hpp)
// cut at half its interior value by marching squares (marching_cases.hpp), the 2D counterpart of
// surface_mesh.hpp.

#include <array>
#include <span>
#include <vector>

#include "tide/surface/colour_field.hpp"

namespace tide::surface {

/// Closed polylines (the first point is not repeated at the end), each counter-clockwise round the
/// fluid: an outer boundary has positive signed area, a hole's boundary negative.
struct Outline {
  std::vector<std::vector<std::array<double, 2>>> loops;
};

/// The curves c = iso_level of `grid`, which must be zero outside its stored blocks. Loops start at
/// their lowest grid edge and are listed in the order of those edges: the same for any thread count.
Outline marching_squares(const SparseGrid<2>& grid, double iso_level);

/// The outline of the fluid of particles at `positions` (x, y of each in turn).
Outline reconstruct_outline(std::span<const double> positions, const FieldSettings& settings,
                            double iso_fraction = 0.5);

/// Σ over loops of the shoelace area: the area enclosed, holes subtracted.
double enclosed_area(const Outline& outline);

}  // namespace tide::surface
