#include "tide/solvers/sensor_footprint.hpp"

#include <algorithm>
#include <cmath>

#include <Eigen/Geometry>

#include "tide/solvers/particle_sampling.hpp"

namespace tide {

template <int D>
std::vector<Vector<D>> sensor_footprint(const Vector<D>& centre, const scene::ProbeSensor& sensor, Real spacing) {
  const Vector<D> normal = to_vector<D>(sensor.normal).normalized();
  const Real diameter = static_cast<Real>(sensor.diameter);
  const int m = std::max(1, static_cast<int>(std::ceil(diameter / (spacing / 2))));
  const Real step = diameter / static_cast<Real>(m);
  // The offset of the k-th of m midpoints from the centre, along one direction of the face.
  const auto offset = [&](int k) { return (static_cast<Real>(k) + Real(0.5)) * step - diameter / 2; };
  std::vector<Vector<D>> points;
  if constexpr (D == 2) {
    const Vector<2> tangent(-normal[1], normal[0]);
    for (int k = 0; k < m; ++k) points.push_back(centre + offset(k) * tangent);
  } else {
    // Two unit tangents: the normal crossed with the axis least aligned with it, then with that.
    Eigen::Index least = 0;
    normal.cwiseAbs().minCoeff(&least);
    const Vector<3> first = normal.cross(Vector<3>::Unit(least)).normalized();
    const Vector<3> second = normal.cross(first);
    for (int a = 0; a < m; ++a) {
      for (int b = 0; b < m; ++b) {
        if (std::hypot(offset(a), offset(b)) <= diameter / 2)
          points.push_back(centre + offset(a) * first + offset(b) * second);
      }
    }
  }
  return points;
}

template std::vector<Vector<2>> sensor_footprint<2>(const Vector<2>&, const scene::ProbeSensor&, Real);
template std::vector<Vector<3>> sensor_footprint<3>(const Vector<3>&, const scene::ProbeSensor&, Real);

}  // namespace tide
