#pragma once

// What the multiphase tests measure of a 2D run (multiphase_test.cpp,
// multiphase_incompressible_test.cpp), for any scheme.

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <numbers>
#include <string>
#include <utility>
#include <vector>

#include "tide/solvers/simulation.hpp"

namespace tide::test {

struct DropletState {
  double inside_pressure = 0;   // mean over particles deeper than 2h inside the interface
  double outside_pressure = 0;  // mean over particles farther than 2h outside it
  double max_speed = 0;
};

inline DropletState measure_droplet(const Simulation<2>& simulation, double radius) {
  const auto& fluid = simulation.fluid();
  const auto& f = simulation.fluid_fields();
  const auto x = fluid[f.position];
  const auto p = fluid[f.pressure];
  const double band = 2 * simulation.smoothing_length();
  DropletState state;
  int inside = 0, outside = 0;
  for (std::size_t i = 0; i < fluid.size(); ++i) {
    const double r = (x[i] - Vector<2>(0.5, 0.5)).norm();
    if (r < radius - band) {
      state.inside_pressure += p[i];
      ++inside;
    } else if (r > radius + band) {
      state.outside_pressure += p[i];
      ++outside;
    }
  }
  state.inside_pressure /= inside;
  state.outside_pressure /= outside;
  state.max_speed = simulation.max_speed();
  return state;
}

// Mass and particle count of each of two phases, summed in id order so that the sum does not
// depend on the Morton order of the particles.
inline std::pair<std::array<double, 2>, std::array<std::size_t, 2>> phase_totals(const Simulation<2>& simulation) {
  const auto& fluid = simulation.fluid();
  const auto& f = simulation.fluid_fields();
  std::array<double, 2> mass{};
  std::array<std::size_t, 2> count{};
  std::vector<std::pair<Index, std::size_t>> by_id;
  for (std::size_t i = 0; i < fluid.size(); ++i) by_id.emplace_back(fluid[fluid.id()][i], i);
  std::sort(by_id.begin(), by_id.end());
  for (const auto& [id, i] : by_id) {
    mass[fluid[f.phase][i]] += fluid[f.mass][i];
    ++count[fluid[f.phase][i]];
  }
  return {mass, count};
}

// Half the distance between the highest light particle and the lowest heavy one: the amplitude of
// the Rayleigh–Taylor interface (bubble tip minus spike tip, over 2).
inline double interface_amplitude(const Simulation<2>& simulation) {
  const auto& fluid = simulation.fluid();
  const auto& f = simulation.fluid_fields();
  const auto x = fluid[f.position];
  const auto phase = fluid[f.phase];
  double spike = 2, bubble = 0;
  for (std::size_t i = 0; i < fluid.size(); ++i) {
    if (phase[i] == 0) spike = std::min(spike, double(x[i][1]));
    if (phase[i] == 1) bubble = std::max(bubble, double(x[i][1]));
  }
  return (bubble - spike) / 2;
}

// Runs the Rayleigh–Taylor scene (multiphase_scenes.hpp, density ratio 1.8, Δx = 0.04) in
// `simulation` to t = 2 and checks it against linear theory (Chandrasekhar 1961, ch. X) for the
// mode k = 2π: inviscid n = sqrt(A k g) = 1.340 /s with the Atwood number A = 0.8/2.8, and with
// equal kinematic viscosities ν = 2/420 the estimate n = sqrt(A k g + ν² k⁴) − ν k² = 1.165 /s;
// from rest the amplitude grows as a0 cosh(n t). The initial amplitude k a0 = 0.88 is not small,
// so nonlinear saturation slows the growth below the linear rate: theory gives an upper bound,
// a(t) ≤ a0 cosh(n t) with the inviscid rate, sampled every 0.25 s, and the effective rate over the
// first second, acosh(a(1)/a0), must stay above half the viscous rate (a driven instability, not
// one damped out by numerical dissipation). The amplitude must grow at every sample, the fastest
// particle stay below the free-fall speed over the box height sqrt(2 g Ly) = 2 m/s, and each
// phase keep its particles and mass exactly. `label` names the run in the messages.
inline void expect_rayleigh_taylor_growth(Simulation<2>& simulation, const std::string& label) {
  const auto before = phase_totals(simulation);
  const double a0 = interface_amplitude(simulation);
  const double atwood = 0.8 / 2.8, k = 2 * std::numbers::pi, nu = 2.0 / 420;
  const double inviscid_rate = std::sqrt(atwood * k);
  const double viscous_rate = std::sqrt(atwood * k + nu * nu * k * k * k * k) - nu * k * k;
  double previous = a0, speed = 0, at_one_second = 0;
  for (double sample = 0.25; sample <= 2.0; sample += 0.25) {
    while (simulation.time() < sample) {
      simulation.step();
      speed = std::max(speed, double(simulation.max_speed()));
    }
    const double amplitude = interface_amplitude(simulation);
    EXPECT_LE(amplitude, a0 * std::cosh(inviscid_rate * simulation.time())) << label << ", t = " << simulation.time();
    EXPECT_GT(amplitude, previous) << label << ", t = " << simulation.time();
    previous = amplitude;
    if (sample == 1.0) at_one_second = std::acosh(amplitude / a0) / simulation.time();
  }
  EXPECT_GT(at_one_second, viscous_rate / 2) << label;
  EXPECT_LT(speed, 2.0) << label;
  EXPECT_EQ(before, phase_totals(simulation)) << label;
}

}  // namespace tide::test
