#pragma once

// Probes: what a pressure sensor or a wave gauge would read in a WCSPH run, interpolated from the
// particles around one point. Each reading walks the neighbour grid's cells around its points, so
// it costs O(neighbours) per point, never O(particles), and reads the state without changing it.

#include <cmath>
#include <type_traits>
#include <variant>
#include <vector>

#include "tide/core/scene.hpp"
#include "tide/solvers/simulation.hpp"

namespace tide {

/// The Shepard-normalised kernel interpolation at `point` of a quantity of the fluid particles,
///   q(x) = Σ_f q_f V_f W(x − x_f) / Σ_f V_f W(x − x_f),   V_f = m_f / ρ_f,
/// over the fluid particles within the kernel support of `point` (Shepard 1968; the SPH
/// interpolant of Monaghan 1992, normalised). `quantity(j, x − x_j)` gives q_j, a Real or a
/// Vector<D>; `no_fluid` is returned where no fluid particle is within reach.
template <int D, class Value, class Quantity>
Value shepard_interpolation(const Simulation<D>& simulation, const Vector<D>& point, Quantity&& quantity,
                            Value no_fluid) {
  const auto& fluid = simulation.fluid();
  const auto& f = simulation.fluid_fields();
  const auto mass = fluid[f.mass];
  const auto density = fluid[f.density];
  Value weighted;
  if constexpr (std::is_arithmetic_v<Value>) {
    weighted = 0;
  } else {
    weighted = Value::Zero();
  }
  Real weight_sum = 0;
  std::visit(
      [&](const auto& kernel) {
        simulation.interactions().fluid_grid().for_each_neighbor_of(
            point, fluid[f.position], [&](Index j, const Vector<D>& x_pj, Real r2) {
              const Real weight = mass[j] / density[j] * kernel.value(std::sqrt(r2));
              weighted += weight * quantity(j, x_pj);
              weight_sum += weight;
            });
      },
      simulation.kernel());
  if (!(weight_sum > 0)) return no_fluid;
  return weighted / weight_sum;
}

/// The pressure at `point`: the Shepard interpolation of the fluid particles' pressures, each
/// moved hydrostatically from its own position to the point (the wall-pressure extrapolation of
/// Adami, Hu & Adams 2012, eq. 27, used for a probe):
///   p(x) = Σ_f (p_f + ρ_f g·(x − x_f)) V_f W(x − x_f) / Σ_f V_f W(x − x_f),   V_f = m_f / ρ_f.
/// Only fluid particles count. A point on a wall is the usual place of a sensor; the wall
/// particles there hold pressures already extrapolated from these same fluid particles, so
/// adding them would count the fluid twice and weight it by how many wall layers lie in the
/// support. The hydrostatic shift makes the reading exact in water at rest even where the wall
/// cuts the support off on one side. Without fluid in the support the reading is the pressure
/// of the equation of state at rest density (0, or the background pressure); negative readings
/// are clamped to 0 where the scene clamps negative pressure.
template <int D>
Real probe_pressure(const Simulation<D>& simulation, const Vector<D>& point);

/// What a transducer whose sensing face is `sensor`, centred on `centre`, reads: the mean pressure
/// over the face, the force on it over its area, p̄ = (1/A) ∫_A p dA, by the midpoint rule over
/// sensor_footprint's points with p the probe_pressure at each. Where part of the face is dry
/// (no fluid within a kernel support), that part reads the pressure at rest, 0, as on a real
/// sensor. A face wider than the particle spacing averages the particle-scale noise of the
/// reading across its area, as a transducer's finite face does.
template <int D>
Real sensor_pressure(const Simulation<D>& simulation, const Vector<D>& centre, const scene::ProbeSensor& sensor);

/// The fluid colour at `point`: the share of the kernel's volume there that holds fluid,
///   c(x) = Σ_f V_f W(x − x_f) / (1 − Σ_w V_w W(x − x_w)),   V = m / ρ0,
/// 1 inside the fluid, about ½ at its free surface, 0 in empty space. The denominator removes
/// the part of the support that lies inside walls, so the fluid beside a wall is 1 too. Rest
/// volumes are used because summation density is low at a free surface (its kernel is
/// truncated) and m/ρ would overstate the volume of exactly the particles that place the surface.
template <int D>
Real fluid_colour(const Simulation<D>& simulation, const Vector<D>& point);

/// The height of the free surface above `base` along the up direction (−gravity, or the last
/// axis without gravity): the highest point of that line inside the domain where the fluid
/// colour is at least ½ (the free surface of a colour function, as in Brackbill, Kothe & Zemach
/// 1992), found by sampling the line every h/4 from the top down and interpolating linearly
/// between the two samples around ½; 0 when no point of the line is in the fluid.
template <int D>
Real probe_water_height(const Simulation<D>& simulation, const Vector<D>& base);

/// Every probe of `probes` read from the current state, in order: pressures in Pa, heights in m.
template <int D>
std::vector<double> read_probes(const Simulation<D>& simulation, const std::vector<scene::Probe>& probes);

extern template Real probe_pressure<2>(const Simulation<2>&, const Vector<2>&);
extern template Real probe_pressure<3>(const Simulation<3>&, const Vector<3>&);
extern template Real sensor_pressure<2>(const Simulation<2>&, const Vector<2>&, const scene::ProbeSensor&);
extern template Real sensor_pressure<3>(const Simulation<3>&, const Vector<3>&, const scene::ProbeSensor&);
extern template Real fluid_colour<2>(const Simulation<2>&, const Vector<2>&);
extern template Real fluid_colour<3>(const Simulation<3>&, const Vector<3>&);
extern template Real probe_water_height<2>(const Simulation<2>&, const Vector<2>&);
extern template Real probe_water_height<3>(const Simulation<3>&, const Vector<3>&);
extern template std::vector<double> read_probes<2>(const Simulation<2>&, const std::vector<scene::Probe>&);
extern template std::vector<double> read_probes<3>(const Simulation<3>&, const std::vector<scene::Probe>&);

}  // namespace tide
