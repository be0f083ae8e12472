#include "tide/render/density_heatmap.hpp"

#include <algorithm>
#include <cmath>

#include "tide/core/kernels/wendland_c2.hpp"

namespace tide::render {

std::vector<double> density_on_pixels(const Camera& camera, std::span<const double> positions,
                                      double smoothing_length) {
  const PixelRegion& region = camera.region;
  std::vector<double> density(static_cast<std::size_t>(region.width) * static_cast<std::size_t>(region.height), 0.0);
  const WendlandC2Kernel<2> kernel(static_cast<Real>(smoothing_length));
  const double support = static_cast<double>(kernel.support_radius());
  const double reach = support * camera.pixels_per_metre;
  for (std::size_t i = 0; i + 1 < positions.size(); i += 2) {
    const Point3 centre = camera.project({positions[i], positions[i + 1], 0});
    const int left = std::max(region.left, static_cast<int>(std::floor(centre[0] - reach)));
    const int right = std::min(region.left + region.width - 1, static_cast<int>(std::ceil(centre[0] + reach)));
    const int top = std::max(region.top, static_cast<int>(std::floor(centre[1] - reach)));
    const int bottom = std::min(region.top + region.height - 1, static_cast<int>(std::ceil(centre[1] + reach)));
    for (int y = top; y <= bottom; ++y) {
      for (int x = left; x <= right; ++x) {
        // The pixel's centre is (x + ½, y + ½) in picture coordinates.
        const double distance = std::hypot(x + 0.5 - centre[0], y + 0.5 - centre[1]) / camera.pixels_per_metre;
        if (distance >= support) continue;
        density[static_cast<std::size_t>(y - region.top) * static_cast<std::size_t>(region.width) +
                static_cast<std::size_t>(x - region.left)] +=
            static_cast<double>(kernel.value(static_cast<Real>(distance)));
      }
    }
  }
  return density;
}

void draw_density_heatmap(Image& image, const Camera& camera, std::span<const double> positions,
                          double smoothing_length, const ColourScale& scale) {
  const std::vector<double> density = density_on_pixels(camera, positions, smoothing_length);
  const PixelRegion& region = camera.region;
  for (int y = 0; y < region.height; ++y)
    for (int x = 0; x < region.width; ++x)
      image.set(region.left + x, region.top + y,
                scale.of(density[static_cast<std::size_t>(y) * static_cast<std::size_t>(region.width) +
                                 static_cast<std::size_t>(x)]));
}

}  // namespace tide::render
