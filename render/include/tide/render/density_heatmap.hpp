#pragma once

// A crowd's density as a heat map: the kernel-summed number density of 2D points sampled at every
// pixel of a picture region, coloured by a fixed scale, so that frames of one run compare.

#include <span>
#include <vector>

#include "tide/render/camera.hpp"
#include "tide/render/image.hpp"
#include "tide/render/particle_splats.hpp"

namespace tide::render {

/// n(x) = Σ_j W(|x − x_j|, h) at the centre of each pixel of camera.region (row by row from its
/// top-left), with the Wendland C2 kernel the crowd scenes use: persons/m² for a crowd, the SPH
/// number density of its agents (Monaghan 1992, eq. 2.7, with a mass of one). `positions` holds
/// x, y of each point; each point adds its kernel to the pixels within its support, in point
/// order, so the sums are the same on every run.
std::vector<double> density_on_pixels(const Camera& camera, std::span<const double> positions, double smoothing_length);

/// Colours each pixel of camera.region by scale.of(n) of density_on_pixels.
void draw_density_heatmap(Image& image, const Camera& camera, std::span<const double> positions,
                          double smoothing_length, const ColourScale& scale);

}  // namespace tide::render
