#pragma once

// What the stress cases share: scene building blocks, stepping with a per-step observer, the
// measurements (energies, density and pressure extremes, particle pairing) and row building.

#include <chrono>
#include <cmath>
#include <exception>
#include <limits>
#include <string>
#include <vector>

#include "tide/core/scene.hpp"
#include "tide/solvers/instability.hpp"
#include "tide/solvers/wcsph.hpp"
#include "tide/stress/case.hpp"

namespace tide::stress {

constexpr double standard_gravity = 9.81;
constexpr double water_density = 1000;

/// A 2D scene of water (ρ0 = 1000) in an open-top container `width` × `height` (inner box from
/// the origin) with Wendland C2 at h = 1.7 Δx (Dehnen & Aly 2012: no pairing at h/Δx ≥ 1.5),
/// c0 = 10 `max_speed`, and the wall layers and domain to match. Add fluid blocks to it.
scene::Scene container_scene(const std::string& name, double spacing, double width, double height, double max_speed);

/// A water column `column_height` high and half as wide at the left of a tank four times as wide
/// as the column and 1.5 × as high (the Martin & Moyce 1952 proportions), U = sqrt(2 g H), with
/// artificial viscosity α = 0.1: the front's impact on the far wall is a water hammer, a shock,
/// which artificial viscosity exists to capture (at the default α = 0.02 the pressure overshoots
/// the water hammer's by up to 2×; docs/stability.md).
scene::Scene dam_break_scene(const std::string& name, double spacing, double column_height);

/// The fastest a dam-break front can reach the far wall: Ritter's (1892) inviscid shallow-water
/// front speed 2 sqrt(g H), √2 times the free fall U = sqrt(2 g H) of the column's top.
double dam_break_front_speed(double column_height);

/// The largest state an impact at speed U can build in a fluid of sound speed c0 and Tait
/// exponent γ: the water hammer of fluid stopped at once by a wall, a shock running back at
/// U_s = c0 + (γ + 1) U / 4 (the weak-shock speed, c0 plus half the Tait fluid's nonlinearity
/// (γ + 1)/2 times U). Rankine–Hugoniot across it: p = ρ0 U_s U, ρ/ρ0 − 1 = U / (U_s − U); the
/// fastest a free surface can be thrown by that pressure is sqrt(2 p/ρ0) (Bernoulli).
struct WaterHammer {
  double pressure = 0;       // Pa
  double density_error = 0;  // ρ/ρ0 − 1
  double speed = 0;          // m/s
};
WaterHammer water_hammer(double speed, double sound_speed, double tait_exponent, double rest_density);

/// Simulated seconds, wall seconds and the time-step limits that bound the steps of a run.
struct RunStats {
  double simulated_seconds = 0;
  double wall_seconds = 0;
  TimeStepTally limits;
  std::string limits_text() const;  // e.g. "acoustic 100%" or "viscous 97%, acoustic 3%"
};

/// Steps `simulation` until its time reaches `end`, calling `observe(simulation)` after each step.
template <int D, class Observer>
RunStats run_until(Wcsph<D>& simulation, double end, Observer&& observe) {
  RunStats stats;
  const double start_time = simulation.time();
  const auto start = std::chrono::steady_clock::now();
  while (simulation.time() < end * (1 - 1e-12)) {
    stats.limits.add(simulation.step().time_step.limit);
    observe(simulation);
  }
  stats.wall_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  stats.simulated_seconds = simulation.time() - start_time;
  return stats;
}

/// Σ ½ m |v|² over the fluid, J (per metre in 2D).
template <int D>
double kinetic_energy(const Wcsph<D>& simulation);

/// Σ m (e(ρ) − g·x) over the fluid: the elastic energy stored by the equation of state,
/// e(ρ) = ∫_{ρ0}^{ρ} p/ρ'² dρ' (the work of compression per unit mass), plus the potential energy
/// in gravity `gravity`. With the kinetic energy, the total an inviscid WCSPH flow conserves.
template <int D>
double internal_and_potential_energy(const Wcsph<D>& simulation, const scene::Vec& gravity);

/// max |ρ/ρ0 − 1| over the fluid, or with summation density (`method`) max (ρ/ρ0 − 1): summation
/// density is naturally low where a free surface truncates the kernel, so there only compression
/// counts (the rule of the solver's own density band).
template <int D>
double max_density_error(const Wcsph<D>& simulation, scene::DensityMethod method);

/// max p over the fluid, Pa.
template <int D>
double max_pressure(const Wcsph<D>& simulation);

/// How close the particles within `radius` of the origin have come to each other: the fraction
/// of them whose nearest neighbour is nearer than half the initial spacing Δx (a regular
/// distribution has none; tensile clumping pairs them up), and the smallest pair distance over Δx.
struct Pairing {
  double close_fraction = 0;
  double min_distance = std::numeric_limits<double>::infinity();
};

template <int D>
Pairing pairing(const Wcsph<D>& simulation, double spacing, double radius);

/// The rows of one run: `run(rows)` runs the scene and fills in each row's value and run
/// statistics. An error (an instability, a bad set-up) fails every row with its message instead.
template <class Run>
std::vector<Row> measured(std::vector<Row> rows, Run&& run) {
  try {
    run(rows);
  } catch (const std::exception& error) {
    for (Row& row : rows) {
      row.value = std::numeric_limits<double>::quiet_NaN();
      row.failure = error.what();
    }
  }
  return rows;
}

/// Sets the run statistics of every row, and adds the binding time-step limits to its note.
void record_run(std::vector<Row>& rows, const RunStats& stats);

/// "1e-06" style: six significant digits, for settings and notes.
std::string format_number(double value);

// Each case, built in its own file.
Case long_rest_case();
Case tension_case();
Case violent_impact_case();
Case extremes_case();
Case time_step_case();
Case conservation_case();

}  // namespace tide::stress
