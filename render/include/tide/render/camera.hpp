#pragma once

// Orthographic cameras that frame a box of the scene in a region of the picture: the 2D one looks
// down the z axis (x right, y up), the 3D one at a box whose up is +z from the front, to the
// right and above, the view the dam-break figures of the SPH literature take.

#include <array>

namespace tide::render {

using Point3 = std::array<double, 3>;

/// A rectangle of the picture, in pixels: left and top edge, width and height.
struct PixelRegion {
  int left = 0;
  int top = 0;
  int width = 0;
  int height = 0;
};

struct Camera {
  Point3 right{};    // unit vector along the picture's x axis
  Point3 up{};       // unit vector along the picture's y axis, upwards
  Point3 forward{};  // unit vector into the picture
  Point3 centre{};   // the scene point at the centre of `region`
  double pixels_per_metre = 1;
  PixelRegion region;

  /// Picture x and y (pixels, y downwards) and depth (m along `forward`) of scene point p.
  Point3 project(const Point3& p) const;
};

/// Frames the box [lowest, highest] (z ignored) in `region`, x right and y up, aspect kept.
Camera camera_2d(const Point3& lowest, const Point3& highest, const PixelRegion& region);

/// Frames the box [lowest, highest] in `region`, seen from direction (0.6, −1, 0.7) with +z up.
Camera camera_3d(const Point3& lowest, const Point3& highest, const PixelRegion& region);

}  // namespace tide::render
