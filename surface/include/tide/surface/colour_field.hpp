#pragma once

// The colour field of a particle set on a sparse grid: c(x) = Σ_j V_j W(|x − x_j|, h), with the
// particle volume V_j = Δx^D and the cubic spline W (Monaghan 1992), the SPH interpolant of the
// indicator function of the fluid (Müller et al. 2003, "Particle-based fluid simulation for
// interactive applications", Eq. 15; splashsurf maps the SPH density onto its sparse grid alike).
// Inside the fluid c is the kernel's lattice sum, ≈ 1; the fluid's surface is the level at half
// that value (surface_mesh.hpp, surface_outline.hpp).

#include <cstddef>
#include <span>

#include "tide/surface/sparse_grid.hpp"

namespace tide::surface {

struct FieldSettings {
  /// Δx, the spacing of the particles when the fluid is at rest density, m.
  double particle_spacing = 0;
  /// h / Δx of the cubic spline (support 2h).
  double smoothing_ratio = 1.2;
  /// Grid cell / Δx, rounded so that a whole number of cells spans the support radius.
  double cell_ratio = 0.5;
};

/// c on every grid point within the support radius of some particle: `positions` holds particle
/// i's D coordinates at [i·D, i·D + D). Blocks are one support radius wide, so a point's value
/// gathers the particles of the 3^D blocks around its own, always in the same order: the values do
/// not depend on the thread count. std::invalid_argument for settings that are not positive and
/// finite, or particles spread over more than 2^20 cells along an axis.
template <int D>
SparseGrid<D> colour_field(std::span<const double> positions, const FieldSettings& settings);

/// c at a particle of an unbounded lattice of spacing Δx: the field's value inside the fluid.
template <int D>
double interior_colour(const FieldSettings& settings);

/// The level of the fluid's surface: iso_fraction (in (0, 1); std::invalid_argument otherwise) of
/// the interior value.
template <int D>
double surface_level(const FieldSettings& settings, double iso_fraction);

}  // namespace tide::surface
