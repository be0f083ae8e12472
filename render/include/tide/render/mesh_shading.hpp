#pragma once

// A triangle mesh drawn shaded: per-vertex normals (the area-weighted mean of the normals of the
// triangles around a vertex) interpolated across each triangle and lit by Lambert's cosine law
// with an ambient term, the light of particle_splats.hpp; a depth buffer keeps the nearest surface.

#include <vector>

#include "tide/core/triangle_mesh.hpp"
#include "tide/render/camera.hpp"
#include "tide/render/image.hpp"

namespace tide::render {

/// Draws `mesh` (counter-clockwise seen from outside, as tide surface writes it) in `colour`,
/// inside camera.region only. Both sides are lit, so an open mesh shows its inside too. A pixel
/// takes the nearest triangle covering its centre, the earlier one on a tie.
void draw_mesh(Image& image, const Camera& camera, const scene::TriangleMesh& mesh, Colour colour);

/// The same against `depth` (particle_splats.hpp's empty_depth, or what particles drew there),
/// updating it.
void draw_mesh(Image& image, const Camera& camera, const scene::TriangleMesh& mesh, Colour colour,
               std::vector<double>& depth);

}  // namespace tide::render
