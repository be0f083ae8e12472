#include "tide/solvers/mass_properties.hpp"

#include <Eigen/Geometry>
#include <array>
#include <cmath>
#include <numbers>
#include <stdexcept>

#include "tide/solvers/mesh_depth.hpp"
#include "tide/solvers/rigid_motion.hpp"

namespace tide {
namespace {

using Vector3 = Eigen::Vector3d;
using Matrix3 = Eigen::Matrix3d;

// The inertia tensor of second moments C = ∫ ρ x xᵀ dV about the centre: I = tr(C) 1 − C.
Matrix3 inertia_from_second_moments(const Matrix3& second_moments) {
  return second_moments.trace() * Matrix3::Identity() - second_moments;
}

// Mass properties from the integrals over the solid of 1, x and x xᵀ (about `origin`), times ρ.
MassProperties from_moments(double volume, const Vector3& first, const Matrix3& second, const Vector3& origin,
                            double density) {
  if (!(volume > 0)) throw std::invalid_argument("a body needs a positive volume");
  MassProperties properties;
  properties.mass = density * volume;
  const Vector3 centre = first / volume;  // relative to origin
  properties.centre = origin + centre;
  properties.inertia = inertia_from_second_moments(density * (second - volume * centre * centre.transpose()));
  return properties;
}

}  // namespace

MassProperties mass_properties(const scene::Box& box, double density, int dimension) {
  const Vector3 extent = to_eigen(box.max) - to_eigen(box.min);
  MassProperties properties;
  properties.centre = (to_eigen(box.min) + to_eigen(box.max)) / 2;
  if (dimension == 2) {
    properties.centre.z() = 0;
    properties.mass = density * extent.x() * extent.y();
    properties.inertia(2, 2) = properties.mass * (extent.x() * extent.x() + extent.y() * extent.y()) / 12;
    return properties;
  }
  properties.mass = density * extent.prod();
  const Vector3 squared = extent.cwiseProduct(extent);
  properties.inertia.diagonal() << squared.y() + squared.z(), squared.x() + squared.z(), squared.x() + squared.y();
  properties.inertia *= properties.mass / 12;
  return properties;
}

MassProperties mass_properties(const scene::Ball& ball, double density, int dimension) {
  const double r = ball.radius;
  MassProperties properties;
  properties.centre = to_eigen(ball.centre);
  if (dimension == 2) {
    properties.centre.z() = 0;
    properties.mass = density * std::numbers::pi * r * r;
    properties.inertia(2, 2) = properties.mass * r * r / 2;
    return properties;
  }
  properties.mass = density * 4 * std::numbers::pi * r * r * r / 3;
  properties.inertia = Matrix3::Identity() * (2 * properties.mass * r * r / 5);
  return properties;
}

MassProperties mass_properties(const scene::Mesh& mesh, double density, int dimension) {
  const scene::TriangleMesh& surface = *mesh.surface;
  // About the middle of the bounds, so the moments do not lose digits to a mesh far from 0.
  Vector3 origin = (to_eigen(mesh.bounds.min) + to_eigen(mesh.bounds.max)) / 2;
  double volume = 0;
  Vector3 first = Vector3::Zero();
  Matrix3 second = Matrix3::Zero();
  if (dimension == 2) {
    origin.z() = 0;
    // Each segment pq of the section, oriented with the solid on its left, closes a signed
    // triangle with the origin: area s/2 with s = p × q, ∫x dA = s (p + q)/6 and
    // ∫x_i x_j dA = s (2 p_i p_j + p_i q_j + q_i p_j + 2 q_i q_j)/24.
    for (const auto& t : surface.triangles) {
      const auto segment = triangle_section(surface, t);
      if (!segment) continue;
      const Vector3 a = to_eigen(surface.vertices[t[0]]), b = to_eigen(surface.vertices[t[1]]),
                    c = to_eigen(surface.vertices[t[2]]);
      const Eigen::Vector2d outward = (b - a).cross(c - a).head<2>();
      Eigen::Vector2d p = (*segment)[0] - origin.head<2>(), q = (*segment)[1] - origin.head<2>();
      const Eigen::Vector2d along = q - p;
      if (along.y() * outward.x() - along.x() * outward.y() < 0) std::swap(p, q);  // outward on the right
      const double s = p.x() * q.y() - p.y() * q.x();
      volume += s / 2;
      first.head<2>() += s * (p + q) / 6;
      second.topLeftCorner<2, 2>() +=
          s * (2 * p * p.transpose() + p * q.transpose() + q * p.transpose() + 2 * q * q.transpose()) / 24;
    }
    MassProperties properties = from_moments(volume, first, second, origin, density);
    // The extrusion's inertia about z only: x² + y² over the section.
    const double about_z = properties.inertia(2, 2);
    properties.inertia.setZero();
    properties.inertia(2, 2) = about_z;
    return properties;
  }
  // Each triangle abc (counter-clockwise seen from outside) closes a signed tetrahedron with the
  // origin: volume s/6 with s = a · (b × c), ∫x dV = s (a + b + c)/24 and
  // ∫x xᵀ dV = s (a aᵀ + b bᵀ + c cᵀ + (a + b + c)(a + b + c)ᵀ)/120 (Tonon 2004, eq. 2–4).
  for (const auto& t : surface.triangles) {
    const Vector3 a = to_eigen(surface.vertices[t[0]]) - origin, b = to_eigen(surface.vertices[t[1]]) - origin,
                  c = to_eigen(surface.vertices[t[2]]) - origin;
    const double s = a.dot(b.cross(c));
    const Vector3 sum = a + b + c;
    volume += s / 6;
    first += s * sum / 24;
    second += s * (a * a.transpose() + b * b.transpose() + c * c.transpose() + sum * sum.transpose()) / 120;
  }
  return from_moments(volume, first, second, origin, density);
}

Eigen::Matrix3d inertia_about(const MassProperties& properties, const Eigen::Vector3d& point) {
  const Vector3 d = properties.centre - point;
  return properties.inertia + properties.mass * (d.squaredNorm() * Matrix3::Identity() - d * d.transpose());
}

}  // namespace tide
