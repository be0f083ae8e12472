#include "tide/solvers/particle_sampling.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <variant>

#include "tide/solvers/mesh_depth.hpp"

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
Real depth_in_obstacle(const Vector<D>& p, const scene::Obstacle& obstacle) {
  if (const auto* box = std::get_if<scene::Box>(&obstacle.shape)) return depth_in_box<D>(p, *box);
  if (const auto* ball = std::get_if<scene::Ball>(&obstacle.shape))
    return Real(ball->radius) - (p - to_vector<D>(ball->centre)).norm();
  if (const auto* mesh = std::get_if<scene::Mesh>(&obstacle.shape)) {
    if constexpr (D == 2)
      return static_cast<Real>(depth_in_mesh_section(*mesh, double(p[0]), double(p[1])));
    else
      return static_cast<Real>(depth_in_mesh(*mesh, {double(p[0]), double(p[1]), double(p[2])}));
  }
  const auto& plane = std::get<scene::Plane>(obstacle.shape);
  const Vector<D> normal = to_vector<D>(plane.normal).normalized();
  return -(p - to_vector<D>(plane.point)).dot(normal);
}

template <int D>
void obstacle_bounds(const scene::Scene& scene, const scene::Obstacle& obstacle, Vector<D>& lower, Vector<D>& upper) {
  if (const auto* box = std::get_if<scene::Box>(&obstacle.shape)) {
    lower = to_vector<D>(box->min);
    upper = to_vector<D>(box->max);
  } else if (const auto* ball = std::get_if<scene::Ball>(&obstacle.shape)) {
    lower = to_vector<D>(ball->centre) - Vector<D>::Constant(Real(ball->radius));
    upper = to_vector<D>(ball->centre) + Vector<D>::Constant(Real(ball->radius));
  } else if (const auto* mesh = std::get_if<scene::Mesh>(&obstacle.shape)) {
    lower = to_vector<D>(mesh->bounds.min);
    upper = to_vector<D>(mesh->bounds.max);
  } else {
    lower = to_vector<D>(scene.domain.box.min);
    upper = to_vector<D>(scene.domain.box.max);
  }
}

// The region whose lattice points outside the inner box are the container's wall particles.
template <int D>
void container_bounds(const scene::Container& container, Real thickness, Vector<D>& lower, Vector<D>& upper) {
  lower = to_vector<D>(container.inner.min) - Vector<D>::Constant(thickness);
  upper = to_vector<D>(container.inner.max) + Vector<D>::Constant(thickness);
  if (container.open_top) upper[D - 1] = Real(container.inner.max[D - 1]);
}

template <int D>
bool made_by_container(const Vector<D>& p, const scene::Container& container, Real thickness) {
  Vector<D> lower, upper;
  container_bounds<D>(container, thickness, lower, upper);
  for (int d = 0; d < D; ++d)
    if (!(p[d] >= lower[d] && p[d] < upper[d])) return false;
  return !inside_box<D>(p, container.inner);
}

}  // namespace

template <int D>
Vector<D> initial_velocity(const scene::FluidBlock& block, const Vector<D>& x) {
  if (const auto* uniform = std::get_if<scene::Vec>(&block.velocity)) return to_vector<D>(*uniform);
  if (const auto* rotation = std::get_if<scene::RigidRotation>(&block.velocity)) {
    const Vector<D> r = x - to_vector<D>(rotation->centre);
    const Real omega = static_cast<Real>(rotation->angular_velocity);
    Vector<D> v = Vector<D>::Zero();
    v[0] = -omega * r[1];
    v[1] = omega * r[0];
    return v;
  }
  const auto& vortex = std::get<scene::TaylorGreenVelocity>(block.velocity);
  const Real k = Real(2 * std::numbers::pi / vortex.length);
  const Real u = static_cast<Real>(vortex.amplitude);
  Vector<D> v = Vector<D>::Zero();
  v[0] = -u * std::cos(k * x[0]) * std::sin(k * x[1]);
  v[1] = u * std::sin(k * x[0]) * std::cos(k * x[1]);
  return v;
}

template <int D>
Vector<D> lattice_anchor(const scene::Scene& scene) {
  return to_vector<D>(scene.walls.container ? scene.walls.container->inner.min : scene.domain.box.min);
}

template <int D>
ParticleSamples<D> sample_fluid(const scene::Scene& scene) {
  const Real spacing = static_cast<Real>(scene.particle_spacing);
  const Vector<D> anchor = lattice_anchor<D>(scene);
  ParticleSamples<D> samples;
  const auto inside_block = [](const scene::FluidBlock& block, const Vector<D>& p) {
    if (const auto* ball = std::get_if<scene::Ball>(&block.shape))
      return (p - to_vector<D>(ball->centre)).norm() < Real(ball->radius);
    return inside_box<D>(p, std::get<scene::Box>(block.shape));
  };
  for (std::size_t k = 0; k < scene.fluid.size(); ++k) {
    const scene::FluidBlock& block = scene.fluid[k];
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
      if (!inside_block(block, p)) return;
      for (std::size_t later = k + 1; later < scene.fluid.size(); ++later)
        if (inside_block(scene.fluid[later], p)) return;
      if (scene.walls.container && !inside_box<D>(p, scene.walls.container->inner)) return;
      for (const auto& obstacle : scene.walls.obstacles)
        if (depth_in_obstacle<D>(p, obstacle) > 0) return;
      samples.positions.push_back(p);
      samples.velocities.push_back(initial_velocity<D>(block, p));
      samples.materials.push_back(block.material);
    });
  }
  return samples;
}

template <int D>
ParticleSamples<D> sample_walls(const scene::Scene& scene) {
  const Real spacing = static_cast<Real>(scene.particle_spacing);
  const Real thickness = spacing * static_cast<Real>(scene.walls.layers);
  const Vector<D> anchor = lattice_anchor<D>(scene);
  ParticleSamples<D> samples;
  const auto& container = scene.walls.container;
  if (container) {
    Vector<D> lower, upper;
    container_bounds<D>(*container, thickness, lower, upper);
    for_each_lattice_point<D>(anchor, spacing, lower, upper, [&](const Vector<D>& p) {
      if (inside_box<D>(p, container->inner)) return;
      samples.positions.push_back(p);
      samples.velocities.push_back(Vector<D>::Zero());
      samples.makers.push_back(0);
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
      if (container && made_by_container<D>(p, *container, thickness)) return;
      for (std::size_t earlier = 0; earlier < k; ++earlier) {
        const Real earlier_depth = depth_in_obstacle<D>(p, obstacles[earlier]);
        if (earlier_depth > 0 && earlier_depth <= thickness) return;
      }
      samples.positions.push_back(p);
      samples.velocities.push_back(to_vector<D>(obstacles[k].velocity));
      samples.makers.push_back(k + 1);
    });
  }
  return samples;
}

template Vector<2> lattice_anchor<2>(const scene::Scene&);
template Vector<3> lattice_anchor<3>(const scene::Scene&);
template ParticleSamples<2> sample_fluid<2>(const scene::Scene&);
template ParticleSamples<3> sample_fluid<3>(const scene::Scene&);
template ParticleSamples<2> sample_walls<2>(const scene::Scene&);
template ParticleSamples<3> sample_walls<3>(const scene::Scene&);
template Vector<2> initial_velocity<2>(const scene::FluidBlock&, const Vector<2>&);
template Vector<3> initial_velocity<3>(const scene::FluidBlock&, const Vector<3>&);

}  // namespace tide
