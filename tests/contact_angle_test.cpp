// The contact angle the pairwise model's wall strengths set (Tartakovsky & Meakin 2005), checked
// against Young's law on the particle lattice itself: the interface energies are measured as pair
// sums over lattice-sampled drops on the discrete wall, not taken from the mean-field integral
// the strengths were derived from.

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <numbers>
#include <variant>
#include <vector>

#include "multiphase_scenes.hpp"
#include "tide/solvers/wcsph.hpp"

namespace tide {
namespace {

// The pair potential of a unit-strength pairwise force F = cos(3πr/(2R)), zero at the support R:
// φ(r) = −(2R/(3π)) (1 + sin(3πr/(2R))).
double pair_potential(double r, double support) {
  const double wave = 1.5 * std::numbers::pi / support;
  return -(1 + std::sin(wave * r)) / wave;
}

// Σ φ over the pairs of a drop (phase 0) in ambient fluid (phase 1) on walls, by kind of pair:
// drop–drop, drop–ambient, ambient–ambient, drop–wall, ambient–wall; and the drop's particle count.
struct PairEnergies {
  std::array<double, 5> sum{};
  int drop_particles = 0;
};

// The least-squares slope of y against x.
double slope(const std::vector<double>& x, const std::vector<double>& y) {
  const double n = static_cast<double>(x.size());
  double mean_x = 0, mean_y = 0;
  for (std::size_t k = 0; k < x.size(); ++k) {
    mean_x += x[k] / n;
    mean_y += y[k] / n;
  }
  double covariance = 0, variance = 0;
  for (std::size_t k = 0; k < x.size(); ++k) {
    covariance += (x[k] - mean_x) * (y[k] - mean_y);
    variance += (x[k] - mean_x) * (x[k] - mean_x);
  }
  return covariance / variance;
}

PairEnergies pair_energies(const Wcsph<2>& simulation) {
  const auto& fluid = simulation.fluid();
  const auto& f = simulation.fluid_fields();
  const auto x = fluid[f.position];
  const auto phase = fluid[f.phase];
  const ParticleSet<2>& walls = simulation.interactions().contact(0).particles();
  const auto wall_x = simulation.interactions().contact(0).positions();
  const double support = std::visit([](const auto& k) { return double(k.support_radius()); }, simulation.kernel());
  const auto near = [&](const Vector<2>& a, const Vector<2>& b) {
    return std::abs(a[0] - b[0]) < support && std::abs(a[1] - b[1]) < support;
  };
  PairEnergies e;
  for (std::size_t i = 0; i < fluid.size(); ++i) {
    if (phase[i] == 0) ++e.drop_particles;
    for (std::size_t j = i + 1; j < fluid.size(); ++j) {
      if (!near(x[i], x[j])) continue;
      const double r = (x[i] - x[j]).norm();
      if (r < support) e.sum[phase[i] + phase[j]] += pair_potential(r, support);
    }
    for (std::size_t j = 0; j < walls.size(); ++j) {
      if (!near(x[i], wall_x[j])) continue;
      const double r = (x[i] - wall_x[j]).norm();
      if (r < support) e.sum[3 + phase[i]] += pair_potential(r, support);
    }
  }
  return e;
}

// Young's law on the lattice. Drops of the area of a half-disc of radius 16Δx (Δx = 1/40) are
// sampled as circular caps of angle θ = 20°, 22°, …, 160° on the floor of a box of ambient fluid.
// With the strengths the rule gives for a target angle, the fluid pair energy of each drop is
// fitted against the cap's arc length L(θ) and the wall pair energy against its base width w(θ)
// (a circular cap of the drop's sampled area n Δx²); the slopes are the interface energies
// σ_ab and σ_aw − σ_bw as the discrete lattice and the 4 wall layers actually present have them,
// and Young's law cos θ_Y = (σ_bw − σ_aw)/σ_ab (Young 1805; de Gennes 1985, Sec. II.A) gives the
// angle at which the drop's energy is least. This checks the rule (surface_tension_setup.cpp)
// apart from the dynamics: with these strengths a drop run from a half-disc stops up to 25° short
// of the target through contact-line pinning, cured by unlike_attraction false and a wider support
// (contact_line_test.cpp; docs/multiphase.md, "Contact angle").
// Measured (double): θ_Y = 30.98°, 90° (exact: s_aw = s_bw) and 149.02° for the targets 30°, 90°,
// 150°; σ_ab = 0.903 and σ_aw − σ_bw = ∓0.774, both about 0.9 of the flat-plane values the rule
// is built on (σ = 1, σ cos θ = 0.866), so their ratio keeps the angle. The same fit gives
// 25.5°/154.5° with 8Δx drops, 29.9°/150.1° with 12Δx and 31.1°/148.9° with 24Δx: the 8Δx caps
// are too coarse for a smooth L(θ), from 12Δx on the angle stays within about 1° of the target.
// The bound 3° is three times that deviation.
TEST(MultiphaseContactAngle, PairwiseWallStrengthsGiveYoungsAngleOnTheLattice) {
  const double spacing = 1.0 / 40, radius = 16 * spacing, width = 2.2, height = 0.7;
  struct Cap {
    double angle = 0;
    PairEnergies energies;
  };
  std::vector<Cap> caps;
  for (int degrees = 20; degrees <= 160; degrees += 2) {
    const double angle = degrees * std::numbers::pi / 180;
    caps.push_back(
        {angle, pair_energies(Wcsph<2>(test::sessile_drop_scene(spacing, radius, degrees, 90, width, height)))});
  }
  for (const double target : {30.0, 90.0, 150.0}) {
    const Wcsph<2> rule(test::sessile_drop_scene(spacing, radius, 90, target, width, height));
    const std::array<double, 5> strength{rule.pair_strength(0, 0), rule.pair_strength(0, 1), rule.pair_strength(1, 1),
                                         rule.wall_strength(0), rule.wall_strength(1)};
    std::vector<double> arc, fluid_energy, base, wall_energy;
    for (const Cap& cap : caps) {
      const double a = cap.angle;
      const double area = cap.energies.drop_particles * spacing * spacing;
      const double circle = std::sqrt(area / (a - std::sin(a) * std::cos(a)));
      const std::array<double, 5>& sum = cap.energies.sum;
      arc.push_back(2 * circle * a);
      base.push_back(2 * circle * std::sin(a));
      fluid_energy.push_back(strength[0] * sum[0] + strength[1] * sum[1] + strength[2] * sum[2]);
      wall_energy.push_back(strength[3] * sum[3] + strength[4] * sum[4]);
    }
    const double tension = slope(arc, fluid_energy);  // σ_ab
    const double wetting = slope(base, wall_energy);  // σ_aw − σ_bw
    const double young = std::acos(-wetting / tension) * 180 / std::numbers::pi;
    EXPECT_NEAR(young, target, 3.0) << "target " << target;
  }
}

}  // namespace
}  // namespace tide
