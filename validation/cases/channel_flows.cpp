// Start-up of plane Poiseuille and Couette flow between two no-slip plates, periodic along the
// plates, against their series solutions. Morris, Fox & Zhu 1997 (J. Comput. Phys. 136, Sec. 4):
// plates L = 1 mm apart, ν = 1e-6 m²/s, ρ0 = 1000 kg/m³; Poiseuille driven by F = 2e-4 m/s²
// (peak speed 2.5e-5 m/s), Couette by the upper plate moving at 2.5e-5 m/s; profiles compared
// at t = 0.0225, 0.045, 0.1125, 0.225 s and near steady state (1 s).

#include <array>
#include <cmath>
#include <numbers>

#include "case_support.hpp"

namespace tide::validation {
namespace {

constexpr double gap = 1e-3;
constexpr double viscosity = 1e-6;
constexpr double peak_speed = 2.5e-5;
constexpr double force = 8 * viscosity * peak_speed / (gap * gap);  // F = 8 ν u0 / L²
constexpr std::array<double, 5> check_times{0.0225, 0.045, 0.1125, 0.225, 1.0};

// Poiseuille start-up (Morris et al. 1997, eq. 21).
double poiseuille_speed(double y, double t) {
  double u = force / (2 * viscosity) * y * (gap - y);
  for (int n = 0; n < 200; ++n) {
    const double k = 2 * n + 1;
    u -= 4 * force * gap * gap / (viscosity * std::pow(std::numbers::pi, 3) * k * k * k) *
         std::sin(k * std::numbers::pi * y / gap) *
         std::exp(-k * k * std::numbers::pi * std::numbers::pi * viscosity * t / (gap * gap));
  }
  return u;
}

// Couette start-up (Morris et al. 1997, eq. 22).
double couette_speed(double y, double t) {
  double u = peak_speed * y / gap;
  for (int n = 1; n < 200; ++n) {
    u += 2 * peak_speed / (n * std::numbers::pi) * (n % 2 == 0 ? 1 : -1) * std::sin(n * std::numbers::pi * y / gap) *
         std::exp(-n * n * std::numbers::pi * std::numbers::pi * viscosity * t / (gap * gap));
  }
  return u;
}

// The channel: `cells` particles across the gap, half as many along it (periodic), plates as
// plane obstacles, laminar viscosity, no pressure clamp (no free surface).
scene::Scene channel_scene(int cells, const Variant& variant, bool moving_upper_plate) {
  scene::Scene s;
  s.source = moving_upper_plate ? "couette channel" : "poiseuille channel";
  s.dimension = 2;
  s.particle_spacing = gap / cells;
  s.materials.push_back({"water", 1000, viscosity, std::nullopt, peak_speed});
  // Half the gap along the channel, and at least the 3 kernel supports a periodic axis needs.
  const double length = s.particle_spacing * std::max(cells / 2, 12);
  s.fluid.push_back({0, scene::Box{{0, 0, 0}, {length, gap, 0}}});
  apply_variant(s, variant);
  const double thickness = s.walls.layers * s.particle_spacing;
  s.walls.obstacles.push_back({scene::Plane{{0, 0, 0}, {0, 1, 0}}, {}, std::nullopt, std::nullopt, std::nullopt});
  s.walls.obstacles.push_back({scene::Plane{{0, gap, 0}, {0, -1, 0}},
                               moving_upper_plate ? scene::Vec{peak_speed, 0, 0} : scene::Vec{}, std::nullopt,
                               std::nullopt, std::nullopt});
  s.domain.box = {{0, -thickness, 0}, {length, gap + thickness, 0}};
  s.domain.periodic = {true, false, false};
  s.gravity = {moving_upper_plate ? 0 : force, 0, 0};
  s.solver.viscosity = scene::ViscosityModel::laminar;
  s.solver.clamp_negative_pressure = false;
  return s;
}

RunRecord run_channel(const std::string& name, int cells, const Variant& variant, bool couette) {
  const scene::Scene s = channel_scene(cells, variant, couette);
  const auto simulation_owner = make_simulation<2>(s);
  Simulation<2>& simulation = *simulation_owner;
  double wall_seconds = 0;
  double error_sum = 0;
  double steady_error = 0;
  for (double t : check_times) {
    wall_seconds += run_until(simulation, t, [](const Simulation<2>&) {});
    const auto x = simulation.fluid()[simulation.fluid_fields().position];
    const auto v = simulation.fluid()[simulation.fluid_fields().velocity];
    RelativeL2 error;
    for (std::size_t i = 0; i < simulation.fluid().size(); ++i) {
      const double y = x[i][1];
      error.add(v[i][0], couette ? couette_speed(y, simulation.time()) : poiseuille_speed(y, simulation.time()));
    }
    error_sum += error.value();
    steady_error = error.value();
  }
  return make_record(name, variant, cells, simulation, wall_seconds,
                     {{"velocity_l2_error", error_sum / check_times.size()}, {"velocity_l2_error_1s", steady_error}});
}

Case channel_case(bool couette) {
  Case c;
  c.name = couette ? "couette" : "poiseuille";
  c.title = couette ? "Couette flow start-up" : "Poiseuille flow start-up";
  c.reference = std::string("the series solution of the start-up flow (Morris, Fox & Zhu 1997, eq. ") +
                (couette ? "22" : "21") + "), plates 1 mm apart, ν = 1e-6 m²/s";
  c.resolution_meaning = "particles across the channel";
  c.metric_notes = {
      "velocity_l2_error: ‖u − u_exact‖₂ / ‖u_exact‖₂ over all particles, averaged over t = 0.0225, 0.045, "
      "0.1125, 0.225 and 1 s",
      "velocity_l2_error_1s: the same at t = 1 s (steady state within 0.01%)"};
  c.resolutions = {10, 20, 40};
  c.test_resolution = 10;
  c.run = [name = c.name, couette](int cells, const Variant& variant) {
    return run_channel(name, cells, variant, couette);
  };
  return c;
}

}  // namespace

Case poiseuille_case() { return channel_case(false); }
Case couette_case() { return channel_case(true); }

}  // namespace tide::validation
