#include "tide/render/particle_splats.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

#include "lighting.hpp"

namespace tide::render {
namespace {

template <class ColourOf>
void draw_discs(Image& image, const Camera& camera, int dimension, std::span<const double> positions, std::size_t count,
                const ColourOf& colour_of, double radius, std::vector<double>& depth) {
  const double radius_pixels = std::max(1.0, radius * camera.pixels_per_metre);
  const int reach = static_cast<int>(std::ceil(radius_pixels));
  const PixelRegion& region = camera.region;
  for (std::size_t i = 0; i < count; ++i) {
    const Point3 p = {positions[i * dimension], positions[i * dimension + 1],
                      dimension == 3 ? positions[i * dimension + 2] : 0.0};
    const Point3 pixel = camera.project(p);
    const Colour colour = colour_of(i);
    const int cx = static_cast<int>(std::floor(pixel[0])), cy = static_cast<int>(std::floor(pixel[1]));
    for (int y = std::max(cy - reach, region.top); y <= std::min(cy + reach, region.top + region.height - 1); ++y) {
      for (int x = std::max(cx - reach, region.left); x <= std::min(cx + reach, region.left + region.width - 1); ++x) {
        const double sx = (x + 0.5 - pixel[0]) / radius_pixels, sy = (pixel[1] - y - 0.5) / radius_pixels;
        const double squared = sx * sx + sy * sy;
        if (squared > 1) continue;
        if (dimension == 2) {
          image.at(x, y) = colour;
          continue;
        }
        // The sphere's surface at this pixel: its normal (sx, sy, sz) faces the viewer.
        const double sz = std::sqrt(1 - squared);
        const double surface_depth = pixel[2] - sz * radius;
        double& nearest = depth[static_cast<std::size_t>(y - region.top) * region.width + (x - region.left)];
        if (surface_depth >= nearest) continue;
        nearest = surface_depth;
        image.at(x, y) = lit(colour, sx * light_direction[0] + sy * light_direction[1] + sz * light_direction[2]);
      }
    }
  }
}

}  // namespace

std::vector<double> empty_depth(const Camera& camera) {
  return std::vector<double>(static_cast<std::size_t>(camera.region.width) * camera.region.height,
                             std::numeric_limits<double>::infinity());
}

void draw_particles(Image& image, const Camera& camera, int dimension, std::span<const double> positions,
                    std::span<const double> values, const ColourScale& scale, double radius) {
  std::vector<double> depth = dimension == 3 ? empty_depth(camera) : std::vector<double>();
  draw_particles(image, camera, dimension, positions, values, scale, radius, depth);
}

void draw_particles(Image& image, const Camera& camera, int dimension, std::span<const double> positions,
                    std::span<const double> values, const ColourScale& scale, double radius,
                    std::vector<double>& depth) {
  draw_discs(
      image, camera, dimension, positions, values.size(), [&](std::size_t i) { return scale.of(values[i]); }, radius,
      depth);
}

void draw_particles(Image& image, const Camera& camera, int dimension, std::span<const double> positions, Colour colour,
                    double radius, std::vector<double>& depth) {
  draw_discs(
      image, camera, dimension, positions, positions.size() / static_cast<std::size_t>(dimension),
      [&](std::size_t) { return colour; }, radius, depth);
}

}  // namespace tide::render
