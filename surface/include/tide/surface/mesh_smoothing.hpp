#pragma once

// Smoothing that keeps a reconstructed surface's volume: Taubin's λ|μ filter (G. Taubin 1995,
// "A signal processing approach to fair surface design", SIGGRAPH '95, Sec. 4): each iteration
// moves every vertex by λ times the umbrella operator Δx_i = (mean of its neighbours) − x_i, then
// by μ times the new one, μ < −λ < 0. The first step shrinks like Laplacian smoothing, the second
// inflates back; together they damp the short wavelengths (the bumps the particle lattice leaves)
// and pass the long ones (the surface's shape), so the volume hardly changes.

#include "tide/core/triangle_mesh.hpp"

namespace tide::surface {

struct TaubinSettings {
  int iterations = 10;
  double lambda = 0.5;
  /// Taubin's pass-band frequency k_PB = 1/λ + 1/μ = 0.1 with λ = 0.5 (his Sec. 4 suggests 0.01–0.1).
  double mu = -0.5263157894736842;
};

/// Smooths `mesh` in place; the triangles are unchanged. Each vertex gathers its neighbours in a
/// fixed order: the same result for any thread count.
void smooth_taubin(scene::TriangleMesh& mesh, const TaubinSettings& settings = {});

}  // namespace tide::surface
