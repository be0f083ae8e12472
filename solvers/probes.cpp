#include "tide/solvers/probes.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <variant>

#include "tide/solvers/particle_sampling.hpp"
#include "tide/solvers/sensor_footprint.hpp"

namespace tide {
namespace {

/// Σ_j m_j W(x − x_j) over the particles of `set` within the support of `point`.
template <int D, class Kernel>
Real mass_kernel_sum(const Kernel& kernel, const NeighborGrid<D>& grid, const ParticleSet<D>& set,
                     const ConstVectorView<D>& x, const ScalarField& mass, const Vector<D>& point) {
  const auto m = set[mass];
  Real sum = 0;
  grid.for_each_neighbor_of(point, x,
                            [&](Index j, const Vector<D>&, Real r2) { sum += m[j] * kernel.value(std::sqrt(r2)); });
  return sum;
}

/// The unit vector up: against gravity, or the last axis in a scene without gravity.
template <int D>
Vector<D> up_direction(const scene::Scene& scene) {
  const Vector<D> gravity = to_vector<D>(scene.gravity);
  if (gravity.squaredNorm() > 0) return -gravity.normalized();
  Vector<D> up = Vector<D>::Zero();
  up[D - 1] = 1;
  return up;
}

/// How far the ray from `start` along `direction` runs inside the grid's domain box.
template <int D>
Real length_inside(const GridDomain<D>& domain, const Vector<D>& start, const Vector<D>& direction) {
  Real length = std::numeric_limits<Real>::max();
  for (int d = 0; d < D; ++d) {
    if (direction[d] > 0) length = std::min(length, (domain.upper[d] - start[d]) / direction[d]);
    if (direction[d] < 0) length = std::min(length, (domain.lower[d] - start[d]) / direction[d]);
  }
  return std::max(length, Real(0));
}

}  // namespace

template <int D>
Real probe_pressure(const Simulation<D>& simulation, const Vector<D>& point) {
  const auto& fluid = simulation.fluid();
  const auto density = fluid[simulation.fluid_fields().density];
  const auto pressure = fluid[simulation.fluid_fields().pressure];
  const Vector<D> gravity = simulation.gravity();
  // The pressure of fluid at rest density: the equation of state's background pressure.
  const Real at_rest = static_cast<Real>(simulation.scene().solver.background_pressure);
  const Real p = shepard_interpolation<D>(
      simulation, point, [&](Index j, const Vector<D>& x_pj) { return pressure[j] + density[j] * gravity.dot(x_pj); },
      at_rest);
  return simulation.scene().solver.clamp_negative_pressure ? std::max(p, Real(0)) : p;
}

template <int D>
Real sensor_pressure(const Simulation<D>& simulation, const Vector<D>& centre, const scene::ProbeSensor& sensor) {
  const std::vector<Vector<D>> points =
      sensor_footprint<D>(centre, sensor, static_cast<Real>(simulation.scene().particle_spacing));
  Real sum = 0;
  for (const Vector<D>& point : points) sum += probe_pressure<D>(simulation, point);
  return sum / static_cast<Real>(points.size());
}

template <int D>
Real fluid_colour(const Simulation<D>& simulation, const Vector<D>& point) {
  const Real rest_density = simulation.rest_density();
  return std::visit(
      [&](const auto& kernel) {
        const auto& fluid = simulation.fluid();
        const auto& f = simulation.fluid_fields();
        const Interactions<D>& interactions = simulation.interactions();
        const Real fluid_share =
            mass_kernel_sum<D>(kernel, interactions.fluid_grid(), fluid, fluid[f.position], f.mass, point) /
            rest_density;
        if (fluid_share == 0) return Real(0);
        Real wall_share = 0;
        for (std::size_t k = 0; k < interactions.contact_count(); ++k) {
          const Contact<D>& contact = interactions.contact(k);
          if (contact.role() != ContactRole::wall) continue;
          wall_share += mass_kernel_sum<D>(kernel, contact.grid(), contact.particles(), contact.positions(),
                                           contact.fields().mass, point) /
                        rest_density;
        }
        const Real open_share = 1 - wall_share;
        // A point deep inside a wall has no open volume: it holds no fluid.
        return open_share > 0 ? fluid_share / open_share : Real(0);
      },
      simulation.kernel());
}

template <int D>
Real probe_water_height(const Simulation<D>& simulation, const Vector<D>& base) {
  const Vector<D> up = up_direction<D>(simulation.scene());
  const Real step = simulation.smoothing_length() / 4;
  const Real length = length_inside<D>(simulation.interactions().fluid_grid().domain(), base, up);
  const auto top_sample = static_cast<long long>(std::floor(length / step));
  Real colour_above = 0;
  for (long long k = top_sample; k >= 0; --k) {
    const Real colour = fluid_colour<D>(simulation, base + (step * static_cast<Real>(k)) * up);
    if (colour >= Real(0.5)) {
      if (k == top_sample) return step * static_cast<Real>(k);
      // Linear interpolation of the colour between this sample and the one above it.
      return step * (static_cast<Real>(k) + (colour - Real(0.5)) / (colour - colour_above));
    }
    colour_above = colour;
  }
  return 0;
}

template <int D>
std::vector<double> read_probes(const Simulation<D>& simulation, const std::vector<scene::Probe>& probes) {
  std::vector<double> values;
  values.reserve(probes.size());
  for (const scene::Probe& probe : probes) {
    const Vector<D> position = to_vector<D>(probe.position);
    if (probe.type == scene::ProbeType::water_height) {
      values.push_back(probe_water_height<D>(simulation, position));
    } else {
      values.push_back(probe.sensor ? sensor_pressure<D>(simulation, position, *probe.sensor)
                                    : probe_pressure<D>(simulation, position));
    }
  }
  return values;
}

template Real probe_pressure<2>(const Simulation<2>&, const Vector<2>&);
template Real probe_pressure<3>(const Simulation<3>&, const Vector<3>&);
template Real sensor_pressure<2>(const Simulation<2>&, const Vector<2>&, const scene::ProbeSensor&);
template Real sensor_pressure<3>(const Simulation<3>&, const Vector<3>&, const scene::ProbeSensor&);
template Real fluid_colour<2>(const Simulation<2>&, const Vector<2>&);
template Real fluid_colour<3>(const Simulation<3>&, const Vector<3>&);
template Real probe_water_height<2>(const Simulation<2>&, const Vector<2>&);
template Real probe_water_height<3>(const Simulation<3>&, const Vector<3>&);
template std::vector<double> read_probes<2>(const Simulation<2>&, const std::vector<scene::Probe>&);
template std::vector<double> read_probes<3>(const Simulation<3>&, const std::vector<scene::Probe>&);

}  // namespace tide
