#include "tide/solvers/mesh_depth.hpp"

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <optional>

namespace tide {
namespace {

using Point3 = Eigen::Vector3d;
using Point2 = Eigen::Vector2d;

constexpr double outside = -1;

Point3 vertex(const scene::TriangleMesh& mesh, std::uint32_t index) {
  const auto& v = mesh.vertices[index];
  return {v[0], v[1], v[2]};
}

bool within(const scene::Box& box, const double* p, int dimension) {
  for (int d = 0; d < dimension; ++d)
    if (!(p[d] >= box.min[d] && p[d] <= box.max[d])) return false;
  return true;
}

// The point of triangle abc closest to p (Ericson, Real-Time Collision Detection, 2005, §5.1.5).
Point3 closest_on_triangle(const Point3& p, const Point3& a, const Point3& b, const Point3& c) {
  const Point3 ab = b - a, ac = c - a, ap = p - a;
  const double d1 = ab.dot(ap), d2 = ac.dot(ap);
  if (d1 <= 0 && d2 <= 0) return a;
  const Point3 bp = p - b;
  const double d3 = ab.dot(bp), d4 = ac.dot(bp);
  if (d3 >= 0 && d4 <= d3) return b;
  const double vc = d1 * d4 - d3 * d2;
  if (vc <= 0 && d1 >= 0 && d3 <= 0) return a + d1 / (d1 - d3) * ab;
  const Point3 cp = p - c;
  const double d5 = ab.dot(cp), d6 = ac.dot(cp);
  if (d6 >= 0 && d5 <= d6) return c;
  const double vb = d5 * d2 - d1 * d6;
  if (vb <= 0 && d2 >= 0 && d6 <= 0) return a + d2 / (d2 - d6) * ac;
  const double va = d3 * d6 - d5 * d4;
  if (va <= 0 && (d4 - d3) >= 0 && (d5 - d6) >= 0) return b + (d4 - d3) / ((d4 - d3) + (d5 - d6)) * (c - b);
  const double denominator = 1 / (va + vb + vc);
  return a + ab * (vb * denominator) + ac * (vc * denominator);
}

// The solid angle triangle abc subtends at the origin (Van Oosterom & Strackee 1983).
double solid_angle(const Point3& a, const Point3& b, const Point3& c) {
  const double la = a.norm(), lb = b.norm(), lc = c.norm();
  const double numerator = a.dot(b.cross(c));
  const double denominator = la * lb * lc + a.dot(b) * lc + a.dot(c) * lb + b.dot(c) * la;
  return 2 * std::atan2(numerator, denominator);
}

// Where edge ab of a triangle crosses z = 0, computed from the lower vertex index so that the two
// triangles sharing the edge get the same point, bit for bit.
Point2 crossing(const scene::TriangleMesh& mesh, std::uint32_t a, std::uint32_t b) {
  if (b < a) std::swap(a, b);
  const Point3 p = vertex(mesh, a), q = vertex(mesh, b);
  const double t = p.z() / (p.z() - q.z());
  return {p.x() + t * (q.x() - p.x()), p.y() + t * (q.y() - p.y())};
}

double distance_to_segment(const Point2& p, const Point2& a, const Point2& b) {
  const Point2 ab = b - a;
  if (ab.squaredNorm() == 0) return (a - p).norm();
  const double t = std::clamp((p - a).dot(ab) / ab.squaredNorm(), 0.0, 1.0);
  return (a + t * ab - p).norm();
}

}  // namespace

std::optional<std::array<Eigen::Vector2d, 2>> triangle_section(const scene::TriangleMesh& mesh,
                                                               const std::array<std::uint32_t, 3>& t) {
  std::array<Point2, 2> ends;
  int found = 0;
  for (int e = 0; e < 3; ++e) {
    const std::uint32_t a = t[e], b = t[(e + 1) % 3];
    if ((mesh.vertices[a][2] >= 0) != (mesh.vertices[b][2] >= 0)) ends[found++] = crossing(mesh, a, b);
  }
  if (found != 2) return std::nullopt;
  return ends;
}

double depth_in_mesh(const scene::Mesh& mesh, const std::array<double, 3>& p) {
  if (!within(mesh.bounds, p.data(), 3)) return outside;
  const scene::TriangleMesh& surface = *mesh.surface;
  const Point3 x{p[0], p[1], p[2]};
  double angle = 0;
  for (const auto& t : surface.triangles)
    angle += solid_angle(vertex(surface, t[0]) - x, vertex(surface, t[1]) - x, vertex(surface, t[2]) - x);
  const long winding = std::lround(angle / (4 * std::numbers::pi));
  if (winding % 2 == 0) return outside;
  double nearest = std::numeric_limits<double>::infinity();
  for (const auto& t : surface.triangles) {
    const Point3 closest = closest_on_triangle(x, vertex(surface, t[0]), vertex(surface, t[1]), vertex(surface, t[2]));
    nearest = std::min(nearest, (closest - x).norm());
  }
  return nearest;
}

double depth_in_mesh_section(const scene::Mesh& mesh, double x, double y) {
  const double p[2] = {x, y};
  if (!within(mesh.bounds, p, 2)) return outside;
  const Point2 point{x, y};
  bool inside = false;
  double nearest = std::numeric_limits<double>::infinity();
  for (const auto& t : mesh.surface->triangles) {
    const auto segment = triangle_section(*mesh.surface, t);
    if (!segment) continue;
    const Point2& a = (*segment)[0];
    const Point2& b = (*segment)[1];
    if ((a.y() > y) != (b.y() > y) && x < a.x() + (y - a.y()) * (b.x() - a.x()) / (b.y() - a.y())) inside = !inside;
    nearest = std::min(nearest, distance_to_segment(point, a, b));
  }
  return inside ? nearest : outside;
}

}  // namespace tide
