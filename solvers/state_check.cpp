#include "state_check.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "tide/core/parallel.hpp"
#include "tide/solvers/instability.hpp"

namespace tide {
namespace {

// Per-step maxima and the first particle (lowest index) whose state is out of bounds.
struct StateSummary {
  Real max_speed_squared = 0;
  Real max_acceleration_squared = 0;
  std::size_t bad_particle = std::numeric_limits<std::size_t>::max();

  static StateSummary combine(const StateSummary& a, const StateSummary& b) {
    return {std::max(a.max_speed_squared, b.max_speed_squared),
            std::max(a.max_acceleration_squared, b.max_acceleration_squared), std::min(a.bad_particle, b.bad_particle)};
  }
};

}  // namespace

void bound_density_by_phase(StateLimits& limits, Real rest_density, const Phases& phases,
                            std::span<const Index> phase) {
  limits.min_density /= rest_density;
  limits.max_density /= rest_density;
  limits.density_band = "rho/rho0 of its phase " + limits.density_band;
  limits.phase = phase;
  for (const Phase& p : phases.table) limits.inverse_rest_density.push_back(1 / p.rest_density);
}

template <int D>
StateMaxima check_fluid_state(const ParticleSet<D>& fluid, const FluidFields<D>& f, const StateLimits& limits,
                              std::uint64_t step, double time) {
  const auto x = fluid[f.position];
  const auto v = fluid[f.velocity];
  const auto a = fluid[f.acceleration];
  const auto density = fluid[f.density];
  const Real max_speed2 = limits.max_speed * limits.max_speed;
  const bool per_phase = !limits.phase.empty();
  const auto checked_density = [&](std::size_t i) {
    return per_phase ? density[i] * limits.inverse_rest_density[limits.phase[i]] : density[i];
  };
  auto out_of_bounds = [&](std::size_t i, Real speed2) {
    const Real rho = checked_density(i);
    return !std::isfinite(x[i].squaredNorm() + speed2 + a[i].squaredNorm() + rho) || rho > limits.max_density ||
           rho < limits.min_density || speed2 > max_speed2;
  };
  const StateSummary summary = reduce(
      fluid.size(), StateSummary{},
      [&](std::size_t i) {
        const Real speed2 = v[i].squaredNorm();
        return StateSummary{speed2, a[i].squaredNorm(),
                            out_of_bounds(i, speed2) ? i : std::numeric_limits<std::size_t>::max()};
      },
      StateSummary::combine);
  if (summary.bad_particle == std::numeric_limits<std::size_t>::max())
    return {std::sqrt(summary.max_speed_squared), std::sqrt(summary.max_acceleration_squared)};

  const std::size_t i = summary.bad_particle;
  const Index id = fluid[fluid.id()][i];
  const std::string note = limits.note ? limits.note() : std::string();
  if (!std::isfinite(x[i].squaredNorm()))
    throw InstabilityError(id, "position", static_cast<double>(x[i].norm()), step, time, "not finite", note);
  if (!std::isfinite(v[i].squaredNorm()))
    throw InstabilityError(id, "velocity", static_cast<double>(v[i].norm()), step, time, "not finite", note);
  if (!std::isfinite(a[i].squaredNorm()))
    throw InstabilityError(id, "acceleration", static_cast<double>(a[i].norm()), step, time, "not finite", note);
  const Real rho = checked_density(i);
  if (!std::isfinite(rho) || rho > limits.max_density || rho < limits.min_density)
    throw InstabilityError(id, per_phase ? "density / rest density" : "density", static_cast<double>(rho), step, time,
                           limits.density_band, note);
  throw InstabilityError(id, "speed", static_cast<double>(v[i].norm()), step, time, limits.speed_bound, note);
}

template StateMaxima check_fluid_state<2>(const ParticleSet<2>&, const FluidFields<2>&, const StateLimits&,
                                          std::uint64_t, double);
template StateMaxima check_fluid_state<3>(const ParticleSet<3>&, const FluidFields<3>&, const StateLimits&,
                                          std::uint64_t, double);

}  // namespace tide
