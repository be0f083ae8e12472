#include <array>
#include <cmath>
#include <string>
#include <variant>
#include <vector>

#include "geometry_checks.hpp"
#include "scene_text.hpp"
#include "tide/core/scene_error.hpp"

namespace tide::io {
namespace {

// The solver places particles at anchor + (k + 1/2)·spacing on every axis (see
// solvers/particle_sampling.hpp); a fluid block holding none of those points would be silently
// empty, so the reader finds one. The loops try three steps from the point just below `lower`
// instead of stepping k: 2^53 spacings or more from the anchor, k + 1 == k and they would not end.

bool axis_holds_lattice_point(double anchor, double spacing, double lower, double upper) {
  const double first = std::floor((lower - anchor) / spacing - 0.5);
  for (int step = 0; step <= 2; ++step) {
    const double point = anchor + (first + step + 0.5) * spacing;
    if (point >= lower && point < upper) return true;
  }
  return false;
}

/// For a range [lower, upper) at most two spacings wide.
std::vector<double> lattice_points_between(double anchor, double spacing, double lower, double upper) {
  std::vector<double> points;
  const double first = std::floor((lower - anchor) / spacing - 0.5);
  for (int step = 0; step <= 2; ++step) {
    const double point = anchor + (first + step + 0.5) * spacing;
    if (point >= lower && point < upper) points.push_back(point);
  }
  return points;
}

bool holds_lattice_point(const scene::Box& box, const scene::Vec& anchor, double spacing, int dimension) {
  for (int d = 0; d < dimension; ++d) {
    if (!axis_holds_lattice_point(anchor[d], spacing, box.min[d], box.max[d])) return false;
  }
  return true;
}

bool holds_lattice_point(const scene::Ball& ball, const scene::Vec& anchor, double spacing, int dimension) {
  // Every point of space lies within half a cell diagonal of a lattice point.
  const double half_diagonal = 0.5 * spacing * std::sqrt(static_cast<double>(dimension));
  if (ball.radius > half_diagonal * (1 + 1e-9)) return true;
  // A smaller ball spans at most two lattice points per axis: try them all.
  std::array<std::vector<double>, 3> candidates{std::vector<double>{0}, std::vector<double>{0}, std::vector<double>{0}};
  for (int d = 0; d < dimension; ++d) {
    candidates[d] =
        lattice_points_between(anchor[d], spacing, ball.centre[d] - ball.radius, ball.centre[d] + ball.radius);
  }
  for (const double x : candidates[0]) {
    for (const double y : candidates[1]) {
      for (const double z : candidates[2]) {
        const double dx = x - ball.centre[0], dy = y - ball.centre[1], dz = z - ball.centre[2];
        if (dx * dx + dy * dy + dz * dz < ball.radius * ball.radius) return true;
      }
    }
  }
  return false;
}

}  // namespace

void check_fluid_lattice_points(const scene::Scene& scene) {
  const scene::Vec& anchor = scene.walls.container ? scene.walls.container->inner.min : scene.domain.box.min;
  const double spacing = scene.particle_spacing;
  for (std::size_t k = 0; k < scene.fluid.size(); ++k) {
    const auto& shape = scene.fluid[k].shape;
    const bool holds_point =
        std::visit([&](const auto& s) { return holds_lattice_point(s, anchor, spacing, scene.dimension); }, shape);
    if (!holds_point) {
      throw scene::SceneError(
          scene.source, "/fluid/" + std::to_string(k) + (std::holds_alternative<scene::Box>(shape) ? "/box" : "/ball"),
          "a shape holding at least one particle position (a lattice point " + format_vector(anchor, scene.dimension) +
              " + (k + 1/2) x " + format_number(spacing) + ")",
          format_shape(shape, scene.dimension));
    }
  }
}

}  // namespace tide::io
