#pragma once

// Particles drawn as discs of their own size, coloured by a field or in one colour: flat in 2D,
// shaded as spheres (Lambert's cosine law with an ambient term) and depth-tested in 3D.

#include <span>
#include <vector>

#include "tide/render/camera.hpp"
#include "tide/render/colormap.hpp"
#include "tide/render/image.hpp"

namespace tide::render {

/// Maps field values to colours: low → the colour map's start, high → its end.
struct ColourScale {
  Colormap colormap;
  double low = 0;
  double high = 1;

  Colour of(double value) const { return colormap.at(high > low ? (value - low) / (high - low) : 0.5); }
};

/// The depth (m along camera.forward) of the nearest thing drawn so far at each pixel of
/// camera.region, row by row: what 3D drawings share so that they hide one another correctly.
std::vector<double> empty_depth(const Camera& camera);

/// Draws particle i at `positions` [i·D, i·D + D) with colour scale.of(values[i]) as a disc of
/// `radius` m (at least one pixel), inside camera.region only. 2D discs are drawn in particle
/// order; 3D spheres keep the nearest at each pixel, the earlier particle on a tie, so the picture
/// is the same whatever order equal depths come in.
void draw_particles(Image& image, const Camera& camera, int dimension, std::span<const double> positions,
                    std::span<const double> values, const ColourScale& scale, double radius);

/// The same, in 3D against `depth` (empty_depth) and updating it.
void draw_particles(Image& image, const Camera& camera, int dimension, std::span<const double> positions,
                    std::span<const double> values, const ColourScale& scale, double radius,
                    std::vector<double>& depth);

/// Every particle in `colour` (walls, bodies), otherwise as draw_particles.
void draw_particles(Image& image, const Camera& camera, int dimension, std::span<const double> positions, Colour colour,
                    double radius, std::vector<double>& depth);

}  // namespace tide::render
