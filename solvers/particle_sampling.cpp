#include "tide/solvers/particle_sampling.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <variant>

namespace tide {
namespace {

template <int D, class F>
void for_each_lattice_point(const Vector<D>& anchor, Real spacing, const Vector<D>& lower, const Vector<D>& upper,
                            F&& f) {
  std::array<long, D> first, last, index;
  for (int d = 0; d < D; ++d) {
    first[d] = static_cast<long>(std::floor((lower[d] - anchor[d]) / spacing - Real(0.5)));
    last[d] = static_cast<long>(std::ceil((upper[d] - anchor[d]) / spacing - Real(0.5)));
    index[d] = first[d];
  }
  while (true) {
    Vector<D> p;
    bool inside = true;
    for (int d = 0; d < D; ++d) {
      p[d] = anchor[d] + (Real(index[d]) + Real(0.5)) * spacing;
      inside = inside && p[d] >= lower[d] && p[d] < upper[d];
    }
    if (inside) f(p);
    int d = 0;
    for (; d < D; ++d) {
      if (++index[d] <= last[d]) break;
      index[d] = first[d];
    }
    if (d == D) return;
  }
}

template <int D>
bool inside_box(const Vector<D>& p, const scene::Box& box) {
  for (int d = 0; d < D; ++d)
    if (!(p[d] >= Real(box.min[d]) && p[d] < Real(box.max[d]))) return false;
  return true;
}

template <int D>
Real depth_in_box(const Vector<D>& p, const scene::Box& box) {
  Real depth = std::numeric_limits<Real>::max();
  for (int d = 0; d < D; ++d) depth = std::min({depth, p[d] - Real(box.min[d]), Real(box.max[d]) - p[d]});
  return depth;
}

// Signed depth of p inside a solid obstacle (positive inside).
template <int D>
Real depth_in_obstacle(const Vector<D>& p, const std::variant<scene::Box, scene::Ball, scene::Plane>& obstacle) {
  if (const auto* box = std::get_if<scene::Box>(&obstacle)) return depth_in_box<D>(p, *box);
  if (const auto* ball = std::get_if<scene::Ball>(&obstacle))
    return Real(ball->radius) - (p - to_vector<D>(ball->centre)).norm();
  const auto& plane = std::get<scene::Plane>(obstacle);
  const Vector<D> normal = to_vector<D>(plane.normal).normalized();
  return -(p - to_vector<D>(plane.point)).dot(normal);
}

template <int D>
void obstacle_bounds(const scene::Scene& scene, const std::variant<scene::Box, scene::Ball, scene::Plane>& obstacle,
                     Vector<D>& lower, Vector<D>& upper) {
  if (const auto* box = std::get_if<scene::Box>(&obstacle)) {
    lower = to_vector<D>(box->min);
    upper = to_vector<D>(box->max);
  } else if (const auto* ball = std::get_if<scene::Ball>(&obstacle)) {
    lower = to_vector<D>(ball->centre) - Vector<D>::Constant(Real(ball->radius));
    upper = to_vector<D>(ball->centre) + Vector<D>::Constant(Real(ball->radius));
  } else {
    lower = to_vector<D>(scene.domain.box.min);
    upper = to_vector<D>(scene.domain.box.max);
  }
}

}  // namespace

template <int D>
Vector<D> lattice_anchor(const scene::Scene& scene) {
  return to_vector<D>(scene.walls.container ? scene.walls.container->inner.min : scene.domain.box.min);
}

template <int D>
std::vector<Vector<D>> sample_fluid(const scene::Scene& scene) {
  const Real spacing = static_cast<Real>(scene.particle_spacing);
  const Vector<D> anchor = lattice_anchor<D>(scene);
  std::vector<Vector<D>> points;
  for (const scene::FluidBlock& block : scene.fluid) {
    Vector<D> lower, upper;
    if (const auto* box = std::get_if<scene::Box>(&block.shape)) {
      lower = to_vector<D>(box->min);
      upper = to_vector<D>(box->max);
    } else {
      const auto& ball = std::get<scene::Ball>(block.shape);
      lower = to_vector<D>(ball.centre) - Vector<D>::Constant(Real(ball.radius));
      upper = to_vector<D>(ball.centre) + Vector<D>::Constant(Real(ball.radius));
    }
    for_each_lattice_point<D>(anchor, spacing, lower, upper, [&](const Vector<D>& p) {
      if (const auto* ball = std::get_if<scene::Ball>(&block.shape)) {
        if (!((p - to_vector<D>(ball->centre)).norm() < Real(ball->radius))) return;
      }
      if (scene.walls.container && !inside_box<D>(p, scene.walls.container->inner)) return;
      for (const auto& obstacle : scene.walls.obstacles)
        if (depth_in_obstacle<D>(p, obstacle) > 0) return;
      points.push_back(p);
    });
  }
  return points;
}

template <int D>
std::vector<Vector<D>> sample_walls(const scene::Scene& scene) {
  const Real spacing = static_cast<Real>(scene.particle_spacing);
  const Real thickness = spacing * static_cast<Real>(scene.walls.layers);
  const Vector<D> anchor = lattice_anchor<D>(scene);
  std::vector<Vector<D>> points;
  if (scene.walls.container) {
    const auto& container = *scene.walls.container;
    const Vector<D> inner_lower = to_vector<D>(container.inner.min);
    const Vector<D> inner_upper = to_vector<D>(container.inner.max);
    Vector<D> outer_upper = inner_upper + Vector<D>::Constant(thickness);
    if (container.open_top) outer_upper[D - 1] = inner_upper[D - 1];
    for_each_lattice_point<D>(anchor, spacing, inner_lower - Vector<D>::Constant(thickness), outer_upper,
                              [&](const Vector<D>& p) {
                                if (!inside_box<D>(p, container.inner)) points.push_back(p);
                              });
  }
  const auto& obstacles = scene.walls.obstacles;
  for (std::size_t k = 0; k < obstacles.size(); ++k) {
    Vector<D> lower, upper;
    obstacle_bounds<D>(scene, obstacles[k], lower, upper);
    for_each_lattice_point<D>(anchor, spacing, lower, upper, [&](const Vector<D>& p) {
      const Real depth = depth_in_obstacle<D>(p, obstacles[k]);
      if (!(depth > 0 && depth <= thickness)) return;
      // A point already made by the container or an earlier obstacle is not made twice.
      if (scene.walls.container && !inside_box<D>(p, scene.walls.container->inner)) return;
      for (std::size_t earlier = 0; earlier < k; ++earlier) {
        const Real earlier_depth = depth_in_obstacle<D>(p, obstacles[earlier]);
        if (earlier_depth > 0 && earlier_depth <= thickness) return;
      }
      points.push_back(p);
    });
  }
  return points;
}

template Vector<2> lattice_anchor<2>(const scene::Scene&);
template Vector<3> lattice_anchor<3>(const scene::Scene&);
template std::vector<Vector<2>> sample_fluid<2>(const scene::Scene&);
template std::vector<Vector<3>> sample_fluid<3>(const scene::Scene&);
template std::vector<Vector<2>> sample_walls<2>(const scene::Scene&);
template std::vector<Vector<3>> sample_walls<3>(const scene::Scene&);

}  // namespace tide
