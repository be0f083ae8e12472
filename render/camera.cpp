#include "tide/render/camera.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace tide::render {
namespace {

double dot(const Point3& a, const Point3& b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }

Point3 cross(const Point3& a, const Point3& b) {
  return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}

Point3 normalised(const Point3& a) {
  const double length = std::sqrt(dot(a, a));
  return {a[0] / length, a[1] / length, a[2] / length};
}

/// Centres the camera on the box and scales it so that the box's eight corners fill `region`
/// (5% margin) along whichever picture axis they fill first.
Camera framed(Camera camera, const Point3& lowest, const Point3& highest) {
  const Point3 middle = {(lowest[0] + highest[0]) / 2, (lowest[1] + highest[1]) / 2, (lowest[2] + highest[2]) / 2};
  double half_width = 0, half_height = 0;
  for (int corner = 0; corner < 8; ++corner) {
    const Point3 p = {corner & 1 ? highest[0] : lowest[0], corner & 2 ? highest[1] : lowest[1],
                      corner & 4 ? highest[2] : lowest[2]};
    const Point3 offset = {p[0] - middle[0], p[1] - middle[1], p[2] - middle[2]};
    half_width = std::max(half_width, std::abs(dot(offset, camera.right)));
    half_height = std::max(half_height, std::abs(dot(offset, camera.up)));
  }
  const double tiny = std::numeric_limits<double>::min();
  camera.centre = middle;
  camera.pixels_per_metre = 0.95 * std::min(camera.region.width / (2 * std::max(half_width, tiny)),
                                            camera.region.height / (2 * std::max(half_height, tiny)));
  return camera;
}

}  // namespace

Point3 Camera::project(const Point3& p) const {
  const Point3 offset = {p[0] - centre[0], p[1] - centre[1], p[2] - centre[2]};
  return {region.left + region.width / 2.0 + pixels_per_metre * dot(offset, right),
          region.top + region.height / 2.0 - pixels_per_metre * dot(offset, up), dot(offset, forward)};
}

Camera camera_2d(const Point3& lowest, const Point3& highest, const PixelRegion& region) {
  Camera camera;
  camera.right = {1, 0, 0};
  camera.up = {0, 1, 0};
  camera.forward = {0, 0, -1};
  camera.region = region;
  return framed(camera, {lowest[0], lowest[1], 0}, {highest[0], highest[1], 0});
}

Camera camera_3d(const Point3& lowest, const Point3& highest, const PixelRegion& region) {
  Camera camera;
  camera.forward = normalised({-0.6, 1.0, -0.7});
  camera.right = normalised(cross(camera.forward, {0, 0, 1}));
  camera.up = cross(camera.right, camera.forward);
  camera.region = region;
  return framed(camera, lowest, highest);
}

}  // namespace tide::render
