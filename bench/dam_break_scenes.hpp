#pragma once

// The dam-break scenes the benchmarks run (step_bench, memory_report): as scenes/dam_break_2d.json
// and scenes/dam_break_3d.json with only the spacing changed.

#include <cstddef>

#include "tide/core/scene.hpp"

namespace tide::bench {

/// The shipped dam-break scene of dimension D with `k` particles across the column width (2D:
/// k x 2k particles; 3D: a cube of k^3 particles, side k x `spacing_3d`).
scene::Scene dam_break(int dimension, double k, double spacing_3d, scene::Scheme scheme);

/// About n fluid particles: 2D k x 2k with 2k^2 = n, 3D a 1 m cube of k^3.
scene::Scene sized_dam_break(int dimension, std::size_t n, scene::Scheme scheme);

/// Issue 8's reference: SPlisHSPlasH's 3D dam break, 39^3 particles at 0.025 m.
scene::Scene reference_3d(scene::Scheme scheme);

}  // namespace tide::bench
