#include "case_support.hpp"

#include <algorithm>
#include <array>
#include <cstdio>

namespace tide::stress {

scene::Scene container_scene(const std::string& name, double spacing, double width, double height, double max_speed) {
  scene::Scene s;
  s.source = name;
  s.dimension = 2;
  s.particle_spacing = spacing;
  s.kernel = KernelType::wendland_c2;
  s.smoothing_ratio = 1.7;
  s.materials.push_back({"water", water_density, 1e-6, std::nullopt, max_speed});
  s.walls.container = scene::Container{scene::Box{{0, 0, 0}, {width, height, 0}}, true};
  s.walls.layers = scene::required_wall_layers(s.kernel, s.smoothing_ratio);
  const double wall = s.walls.layers * spacing;
  s.domain.box = {{-wall, -wall, 0}, {width + wall, 2 * height + wall, 0}};
  s.gravity = {0, -standard_gravity, 0};
  return s;
}

scene::Scene dam_break_scene(const std::string& name, double spacing, double column_height) {
  scene::Scene s = container_scene(name, spacing, 2 * column_height, 1.5 * column_height,
                                   std::sqrt(2 * standard_gravity * column_height));
  s.fluid.push_back({0, scene::Box{{0, 0, 0}, {column_height / 2, column_height, 0}}});
  s.solver.alpha = 0.1;
  return s;
}

double dam_break_front_speed(double column_height) { return 2 * std::sqrt(standard_gravity * column_height); }

WaterHammer water_hammer(double speed, double sound_speed, double tait_exponent, double rest_density) {
  const double shock_speed = sound_speed + (tait_exponent + 1) * speed / 4;
  WaterHammer hammer;
  hammer.pressure = rest_density * shock_speed * speed;
  hammer.density_error = speed / (shock_speed - speed);
  hammer.speed = std::sqrt(2 * hammer.pressure / rest_density);
  return hammer;
}

std::string RunStats::limits_text() const {
  std::string text;
  for (std::size_t k = 0; k < time_step_limit_count; ++k) {
    if (limits.counts[k] == 0) continue;
    const double share = 100.0 * static_cast<double>(limits.counts[k]) / static_cast<double>(limits.total());
    std::array<char, 48> part{};
    std::snprintf(part.data(), part.size(), "%s%s %.0f%%", text.empty() ? "" : ", ",
                  std::string(time_step_limit_name(static_cast<TimeStepLimit>(k))).c_str(), share);
    text += part.data();
  }
  return text;
}

void record_run(std::vector<Row>& rows, const RunStats& stats) {
  for (Row& row : rows) {
    row.simulated_seconds = stats.simulated_seconds;
    row.wall_seconds = stats.wall_seconds;
    row.note += (row.note.empty() ? "" : "; ") + std::string("time step: ") + stats.limits_text();
  }
}

template <int D>
double kinetic_energy(const Wcsph<D>& simulation) {
  const auto& fluid = simulation.fluid();
  const auto v = fluid[simulation.fluid_fields().velocity];
  const auto m = fluid[simulation.fluid_fields().mass];
  double energy = 0;
  for (std::size_t i = 0; i < fluid.size(); ++i) energy += 0.5 * m[i] * static_cast<double>(v[i].squaredNorm());
  return energy;
}

namespace {

// e(ρ) = ∫_{ρ0}^{ρ} p(ρ')/ρ'² dρ' by Simpson's rule on 16 intervals: exact to round-off for the
// gentle integrand over the few per cent a weakly compressible density varies.
double elastic_energy_per_mass(const EquationOfState& eos, double rho) {
  constexpr int intervals = 16;
  const double rho0 = eos.rest_density();
  const double step = (rho - rho0) / intervals;
  const auto integrand = [&](double r) { return static_cast<double>(eos.pressure(static_cast<Real>(r))) / (r * r); };
  double sum = integrand(rho0) + integrand(rho);
  for (int k = 1; k < intervals; ++k) sum += (k % 2 == 1 ? 4 : 2) * integrand(rho0 + k * step);
  return sum * step / 3;
}

}  // namespace

template <int D>
double internal_and_potential_energy(const Wcsph<D>& simulation, const scene::Vec& gravity) {
  const auto& fluid = simulation.fluid();
  const auto& f = simulation.fluid_fields();
  const auto x = fluid[f.position];
  const auto m = fluid[f.mass];
  const auto rho = fluid[f.density];
  double energy = 0;
  for (std::size_t i = 0; i < fluid.size(); ++i) {
    double height_work = 0;
    for (int d = 0; d < D; ++d) height_work -= gravity[static_cast<std::size_t>(d)] * static_cast<double>(x[i][d]);
    energy += m[i] * (elastic_energy_per_mass(simulation.equation_of_state(), rho[i]) + height_work);
  }
  return energy;
}

template <int D>
double max_density_error(const Wcsph<D>& simulation, scene::DensityMethod method) {
  const auto rho = simulation.fluid()[simulation.fluid_fields().density];
  const double rho0 = simulation.equation_of_state().rest_density();
  const bool compression_only = method == scene::DensityMethod::summation;
  double error = 0;
  for (const Real value : rho)
    error = std::max(error, compression_only ? value / rho0 - 1 : std::abs(value / rho0 - 1));
  return error;
}

template <int D>
double max_pressure(const Wcsph<D>& simulation) {
  const auto p = simulation.fluid()[simulation.fluid_fields().pressure];
  double highest = 0;
  for (const Real value : p) highest = std::max(highest, static_cast<double>(value));
  return highest;
}

template <int D>
Pairing pairing(const Wcsph<D>& simulation, double spacing, double radius) {
  const auto& fluid = simulation.fluid();
  const auto x = fluid[simulation.fluid_fields().position];
  Pairing result;
  std::size_t close = 0, counted = 0;
  for (std::size_t i = 0; i < fluid.size(); ++i) {
    if (static_cast<double>(x[i].norm()) >= radius) continue;
    ++counted;
    double nearest2 = std::numeric_limits<double>::infinity();
    simulation.interactions().fluid_grid().for_each_neighbor(i, x, [&](Index j, const Vector<D>&, Real r2) {
      if (j != i) nearest2 = std::min(nearest2, static_cast<double>(r2));
    });
    const double nearest = std::sqrt(nearest2) / spacing;
    result.min_distance = std::min(result.min_distance, nearest);
    if (nearest < 0.5) ++close;
  }
  result.close_fraction = counted == 0 ? 0 : static_cast<double>(close) / static_cast<double>(counted);
  return result;
}

std::string format_number(double value) {
  std::array<char, 32> text{};
  std::snprintf(text.data(), text.size(), "%g", value);
  return text.data();
}

template double kinetic_energy<2>(const Wcsph<2>&);
template double internal_and_potential_energy<2>(const Wcsph<2>&, const scene::Vec&);
template double max_density_error<2>(const Wcsph<2>&, scene::DensityMethod);
template double max_pressure<2>(const Wcsph<2>&);
template Pairing pairing<2>(const Wcsph<2>&, double, double);

}  // namespace tide::stress
