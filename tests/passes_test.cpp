// Each pass of solvers/passes alone, on small particle lattices, against what the SPH sums give
// analytically there. Δx is a power of two and particles sit at (k + 1/2) Δx, so positions and
// their differences are exact and the pass sees the lattice offsets x_ij = −k Δx that the test's
// references are summed over: pass and reference differ only by the rounding of their sums. The
// tolerances bound that rounding: a sum of n terms computed in any order is off by at most
// (n − 1) ε Σ|terms| (Higham, "Accuracy and Stability of Numerical Algorithms", eq. 4.4), and each
// term carries a few more ε from its products.

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <iterator>
#include <limits>
#include <span>
#include <string>
#include <utility>
#include <vector>

#include "passes/continuity.hpp"
#include "passes/density_summation.hpp"
#include "passes/kernel_correction.hpp"
#include "passes/momentum.hpp"
#include "passes/neighbor_walk.hpp"
#include "passes/particle_shifting.hpp"
#include "passes/riemann.hpp"
#include "passes/wall_state.hpp"
#include "tide/core/kernels/wendland_c2.hpp"
#include "tide/core/parallel.hpp"
#include "tide/solvers/interactions.hpp"
#include "tide/solvers/particle_fields.hpp"

namespace tide {
namespace {

constexpr Real spacing = Real(0.125);  // Δx, a power of two
constexpr Real rest_density = 1000;
constexpr Real epsilon = std::numeric_limits<Real>::epsilon();
constexpr int wall_layers = 3;  // 3 Δx of wall: more than the support, 2.6 Δx

template <int D>
using Matrix = Eigen::Matrix<Real, D, D>;

template <int D>
WendlandC2Kernel<D> test_kernel() {
  return WendlandC2Kernel<D>(Real(1.3) * spacing);
}

// Calls f(k) for every integer point k with first ≤ k < first + count.
template <int D, class F>
void for_each_index(const std::array<int, D>& first, const std::array<int, D>& count, F&& f) {
  std::array<int, D> k{};
  while (true) {
    std::array<int, D> point;
    for (int d = 0; d < D; ++d) point[d] = first[d] + k[d];
    f(point);
    int d = 0;
    while (d < D && ++k[d] == count[d]) k[d++] = 0;
    if (d == D) return;
  }
}

template <int D>
Vector<D> lattice_point(const std::array<int, D>& k) {
  Vector<D> x;
  for (int d = 0; d < D; ++d) x[d] = (Real(k[d]) + Real(0.5)) * spacing;
  return x;
}

template <int D>
ParticleSet<D> lattice_set(const std::array<int, D>& first, const std::array<int, D>& count) {
  std::vector<Vector<D>> points;
  for_each_index<D>(first, count, [&](const std::array<int, D>& k) { points.push_back(lattice_point<D>(k)); });
  ParticleSet<D> set;
  set.append(points.size());
  for (std::size_t i = 0; i < points.size(); ++i) set[set.position()].set(i, points[i]);
  return set;
}

// The sums over the lattice neighbours j = i + k of one particle with a full support.
template <int D>
struct LatticeSums {
  int neighbors = 0;                           // lattice points inside the support, the particle itself included
  Real kernel_sum = 0;                         // Σ_k W(|k| Δx)
  Real gradient_sum = 0;                       // Σ_k |∇W_ij|
  Matrix<D> first_moment = Matrix<D>::Zero();  // Σ_k ∇W_ij ⊗ x_ji

  // The mass that gives a particle with a full support the summation density ρ0.
  Real mass() const { return rest_density / kernel_sum; }
  // B = (m/ρ0) Σ_k ∇W_ij ⊗ x_ji: the identity for an exact quadrature, and off it by the kernel's
  // discretisation error on the lattice.
  Matrix<D> moment() const { return first_moment / kernel_sum; }
};

template <int D>
LatticeSums<D> lattice_sums(const WendlandC2Kernel<D>& kernel) {
  const int reach = static_cast<int>(std::ceil(kernel.support_radius() / spacing));
  std::array<int, D> first, count;
  first.fill(-reach);
  count.fill(2 * reach + 1);
  LatticeSums<D> sums;
  for_each_index<D>(first, count, [&](const std::array<int, D>& k) {
    Vector<D> x_ji;
    for (int d = 0; d < D; ++d) x_ji[d] = Real(k[d]) * spacing;
    const Real r = std::sqrt(squared_norm<D>(x_ji));
    if (r >= kernel.support_radius()) return;
    const Vector<D> grad_w = kernel.gradient(-x_ji, r);
    ++sums.neighbors;
    sums.kernel_sum += kernel.value(r);
    sums.gradient_sum += grad_w.norm();
    sums.first_moment += grad_w * x_ji.transpose();
  });
  return sums;
}

template <int D>
Real lattice_mass(const WendlandC2Kernel<D>& kernel) {
  return lattice_sums<D>(kernel).mass();
}

template <int D>
FluidFields<D> add_fluid_fields(ParticleSet<D>& fluid, Real mass) {
  FluidFields<D> f;
  f.position = fluid.position();
  f.velocity = fluid.add_vector("velocity");
  f.acceleration = fluid.add_vector("acceleration");
  f.mass = fluid.add_scalar("mass");
  f.density = fluid.add_scalar("density");
  f.pressure = fluid.add_scalar("pressure");
  f.density_rate = fluid.add_scalar("density_rate");
  for (Real& m : fluid[f.mass]) m = mass;
  for (Real& rho : fluid[f.density]) rho = rest_density;
  return f;
}

enum class WallVelocity { none, no_slip, moving, accelerating };

template <int D>
WallFields<D> add_wall_fields(ParticleSet<D>& walls, Real mass, WallVelocity velocity) {
  WallFields<D> w;
  w.position = walls.position();
  if (velocity != WallVelocity::none) w.velocity = walls.add_vector("velocity");
  if (velocity == WallVelocity::moving || velocity == WallVelocity::accelerating)
    w.surface_velocity = walls.add_vector("surface_velocity");
  if (velocity == WallVelocity::accelerating) w.acceleration = walls.add_vector("acceleration");
  w.mass = walls.add_scalar("mass");
  w.density = walls.add_scalar("density");
  w.pressure = walls.add_scalar("pressure");
  for (Real& m : walls[w.mass]) m = mass;
  for (Real& rho : walls[w.density]) rho = rest_density;
  return w;
}

// `columns` lattice columns across every axis but the last, periodic there: a fluid layer of
// `rows` from y = 0 up, and wall_layers rows of wall particles below it, which continue the
// lattice. The fluid is sorted into the returned interactions.
template <int D>
struct Layer {
  ParticleSet<D> fluid;
  FluidFields<D> f;
  Interactions<D> interactions;
  Real top;  // the highest fluid particle's y

  Layer(const WendlandC2Kernel<D>& kernel, int columns, int rows, WallVelocity wall_velocity)
      : fluid(lattice_set<D>(first_of(0), count_of(columns, rows))),
        f(add_fluid_fields<D>(fluid, lattice_mass<D>(kernel))),
        interactions(domain(columns, rows), kernel.support_radius()),
        top((Real(rows) - Real(0.5)) * spacing) {
    ParticleSet<D> walls = lattice_set<D>(first_of(-wall_layers), count_of(columns, wall_layers));
    const WallFields<D> w = add_wall_fields<D>(walls, lattice_mass<D>(kernel), wall_velocity);
    interactions.add_contact("walls", ContactRole::wall, ContactMotion::fixed, std::move(walls), w);
    interactions.update(fluid);
  }
  Contact<D>& walls() { return interactions.contact(0); }
  // Whether the support of a particle at x is clear of the free surface (walls continue the
  // lattice below, the periodic axes across).
  bool below_surface(const Vector<D>& x, Real support) const { return top - x[D - 1] >= support; }

  static std::array<int, D> first_of(int row) {
    std::array<int, D> first{};
    first[D - 1] = row;
    return first;
  }
  static std::array<int, D> count_of(int columns, int rows) {
    std::array<int, D> count;
    count.fill(columns);
    count[D - 1] = rows;
    return count;
  }
  static GridDomain<D> domain(int columns, int rows) {
    GridDomain<D> domain;
    for (int d = 0; d + 1 < D; ++d) {
      domain.upper[d] = Real(columns) * spacing;
      domain.periodic[d] = true;
    }
    domain.lower[D - 1] = Real(-wall_layers - 1) * spacing;
    domain.upper[D - 1] = Real(rows + 1) * spacing;
    return domain;
  }
};

// A box of n^D fluid particles, [0, n Δx)^D, with no contact, sorted into its interactions.
template <int D>
struct Box {
  ParticleSet<D> fluid;
  FluidFields<D> f;
  Interactions<D> interactions;
  int n;

  Box(const WendlandC2Kernel<D>& kernel, int n)
      : fluid(lattice_set<D>({}, count_of(n))),
        f(add_fluid_fields<D>(fluid, lattice_mass<D>(kernel))),
        interactions(domain(n), kernel.support_radius()),
        n(n) {
    interactions.update(fluid);
  }
  // Whether the support of a particle at x lies inside the box.
  bool in_bulk(const Vector<D>& x, Real support) const {
    for (int d = 0; d < D; ++d)
      if (x[d] < support || x[d] > Real(n) * spacing - support) return false;
    return true;
  }

  static std::array<int, D> count_of(int n) {
    std::array<int, D> count;
    count.fill(n);
    return count;
  }
  static GridDomain<D> domain(int n) {
    GridDomain<D> domain;
    domain.lower.setConstant(-spacing);
    domain.upper.setConstant(Real(n + 1) * spacing);
    return domain;
  }
};

// Calls check(i) for every fluid particle i that `keep`s, up to the first fatal failure, and
// expects there to be some.
template <int D, class Keep, class Check>
void check_particles(const ParticleSet<D>& fluid, const FluidFields<D>& f, Keep&& keep, Check&& check) {
  const auto x = fluid[f.position];
  std::size_t checked = 0;
  for (std::size_t i = 0; i < fluid.size(); ++i) {
    if (!keep(x[i])) continue;
    check(i);
    if (::testing::Test::HasFatalFailure()) return;
    ++checked;
  }
  EXPECT_GT(checked, 0u);
}

template <int D>
void check_density_periodic(int n) {
  const auto kernel = test_kernel<D>();
  std::array<int, D> count;
  count.fill(n);
  ParticleSet<D> fluid = lattice_set<D>({}, count);
  const FluidFields<D> f = add_fluid_fields<D>(fluid, lattice_mass<D>(kernel));
  GridDomain<D> domain;
  domain.upper.setConstant(Real(n) * spacing);
  domain.periodic.fill(true);
  Interactions<D> interactions(domain, kernel.support_radius());
  interactions.update(fluid);
  for (Real& rho : fluid[f.density]) rho = 0;
  passes::density_summation<D>(kernel, fluid, f, interactions, [](std::size_t, Real) {});
  // m = ρ0 / Σ W and Σ_j m W_ij, each a sum of n positive terms: (2n + 2) ε ρ0 with the divisions
  // and products.
  const Real tolerance = Real(2 * lattice_sums<D>(kernel).neighbors + 2) * epsilon * rest_density;
  for (const Real rho : std::as_const(fluid)[f.density]) ASSERT_NEAR(rho, rest_density, tolerance);
}

// A fully periodic lattice: every particle has a full support and gets ρ0.
TEST(DensitySummation, PeriodicLatticeGivesRestDensity) {
  check_density_periodic<2>(16);
  check_density_periodic<3>(10);
}

template <int D>
void check_density_over_wall(int columns) {
  const auto kernel = test_kernel<D>();
  Layer<D> layer(kernel, columns, 8, WallVelocity::none);
  passes::density_summation<D>(kernel, layer.fluid, layer.f, layer.interactions, [](std::size_t, Real) {});
  const Real tolerance = Real(2 * lattice_sums<D>(kernel).neighbors + 2) * epsilon * rest_density;
  const auto density = std::as_const(layer.fluid)[layer.f.density];
  check_particles<D>(
      layer.fluid, layer.f, [&](const Vector<D>& x) { return layer.below_surface(x, kernel.support_radius()); },
      [&](std::size_t i) { ASSERT_NEAR(density[i], rest_density, tolerance) << "particle " << i; });
}

// Wall particles continue the lattice: the fluid beside them has a full support too.
TEST(DensitySummation, WallContinuesTheLattice) {
  check_density_over_wall<2>(16);
  check_density_over_wall<3>(10);
}

template <int D>
void check_momentum_linear_pressure(int n) {
  const auto kernel = test_kernel<D>();
  const LatticeSums<D> sums = lattice_sums<D>(kernel);
  Box<D> box(kernel, n);
  ParticleSet<D>& fluid = box.fluid;
  const FluidFields<D>& f = box.f;
  const Real p0 = 200;
  Vector<D> gradient;
  for (int d = 0; d < D; ++d) gradient[d] = Real(60 - 70 * d);  // Pa/m, not along an axis
  const auto x = std::as_const(fluid)[f.position];
  auto pressure = fluid[f.pressure];
  for (std::size_t i = 0; i < fluid.size(); ++i) pressure[i] = p0 + gradient.dot(x[i]);
  const passes::ViscositySettings viscosity{scene::ViscosityModel::artificial, 0, 0, 0, 0, kernel.smoothing_length()};
  std::vector<Real> scratch(fluid.size());
  passes::momentum<D, scene::ViscosityModel::artificial, true, false>(kernel, viscosity, {}, fluid, f, box.interactions,
                                                                      Vector<D>::Zero(), scratch);

  // a_i = −Σ_j m (p_i + p_j)/ρ0² ∇W_ij; Σ_j ∇W_ij = 0 on the lattice, so with p_j = p_i + G·x_ji
  // a_i = −(1/ρ0) B G, B = (m/ρ0) Σ_j ∇W_ij ⊗ x_ji: −∇p/ρ up to B, the lattice's first moment.
  const Matrix<D> moment = sums.moment();
  const Vector<D> expected = -moment * gradient / rest_density;
  // B is the identity up to the kernel's discretisation error at h = 1.3 Δx: B = 0.964 I in 2D,
  // 0.970 I in 3D.
  EXPECT_TRUE(moment.isApprox(Matrix<D>::Identity(), Real(0.05))) << moment;
  Real p_max = 0;
  for (const Real p : std::as_const(pressure)) p_max = std::max(p_max, std::abs(p));
  // n terms m (p_i/ρ² + p_j/ρ²) ∇W_ij of at most 2 m p_max/ρ0² |∇W_ij|, each with 4 roundings.
  const Real tolerance =
      Real(sums.neighbors + 4) * epsilon * 2 * sums.mass() * p_max / (rest_density * rest_density) * sums.gradient_sum;
  const auto a = std::as_const(fluid)[f.acceleration];
  check_particles<D>(
      fluid, f, [&](const Vector<D>& x_i) { return box.in_bulk(x_i, kernel.support_radius()); },
      [&](std::size_t i) {
        for (int d = 0; d < D; ++d) ASSERT_NEAR(a[i][d], expected[d], tolerance) << "x " << x[i].transpose();
      });
}

// At rest under a linear pressure field, without gravity: a = −∇p/ρ in the bulk.
TEST(Momentum, LinearPressureGivesItsGradient) {
  check_momentum_linear_pressure<2>(12);
  check_momentum_linear_pressure<3>(8);
}

template <int D>
void check_continuity_linear_velocity(int n) {
  const auto kernel = test_kernel<D>();
  const LatticeSums<D> sums = lattice_sums<D>(kernel);
  Box<D> box(kernel, n);
  ParticleSet<D>& fluid = box.fluid;
  const FluidFields<D>& f = box.f;
  Matrix<D> velocity_gradient;  // A, 1/s: a divergence, a shear and a rotation
  for (int r = 0; r < D; ++r)
    for (int c = 0; c < D; ++c) velocity_gradient(r, c) = Real(r == c ? 1 + r : 2 * r - c);
  Vector<D> offset = Vector<D>::Constant(Real(0.5));
  const auto x = std::as_const(fluid)[f.position];
  auto v = fluid[f.velocity];
  Real v_max = 0;
  for (std::size_t i = 0; i < fluid.size(); ++i) {
    v.set(i, offset + velocity_gradient * x[i]);
    v_max = std::max(v_max, v[i].norm());
  }
  passes::continuity<D>(kernel, fluid, f, box.interactions, nullptr);

  // Σ_j m (v_i − v_j)·∇W_ij with v_i − v_j = A x_ij: −ρ0 A:B, B = (m/ρ0) Σ_j ∇W_ij ⊗ x_ji,
  // −ρ0 ∇·v up to the lattice's first moment.
  const Real expected = -rest_density * (velocity_gradient.array() * sums.moment().array()).sum();
  // n terms m (v_i − v_j)·∇W_ij, with v_i and v_j each rounded to ε |v|.
  const Real tolerance = Real(sums.neighbors + 4) * epsilon * 2 * sums.mass() * v_max * sums.gradient_sum;
  const auto rate = std::as_const(fluid)[f.density_rate];
  check_particles<D>(
      fluid, f, [&](const Vector<D>& x_i) { return box.in_bulk(x_i, kernel.support_radius()); },
      [&](std::size_t i) { ASSERT_NEAR(rate[i], expected, tolerance) << "x " << x[i].transpose(); });
}

TEST(Continuity, LinearVelocityGivesMinusDensityTimesDivergence) {
  check_continuity_linear_velocity<2>(12);
  check_continuity_linear_velocity<3>(8);
}

template <int D>
void check_continuity_uniform_velocity(int columns) {
  const auto kernel = test_kernel<D>();
  Layer<D> layer(kernel, columns, 6, WallVelocity::moving);
  Vector<D> velocity;
  for (int d = 0; d < D; ++d) velocity[d] = Real(0.75 - d);  // with a component into the wall
  auto v = layer.fluid[layer.f.velocity];
  for (std::size_t i = 0; i < layer.fluid.size(); ++i) v.set(i, velocity);
  ParticleSet<D>& walls = layer.walls().particles();
  const auto surface_velocity = walls[*layer.walls().fields().surface_velocity];
  const auto rates = [&](const Vector<D>& wall_velocity) {
    for (std::size_t b = 0; b < walls.size(); ++b) surface_velocity.set(b, wall_velocity);
    passes::continuity<D>(kernel, layer.fluid, layer.f, layer.interactions, nullptr);
    const auto rate = std::as_const(layer.fluid)[layer.f.density_rate];
    return std::vector<Real>(rate.begin(), rate.end());
  };
  // v_i − v_j is exactly zero for every pair, wall pairs with v_i − v_s included.
  for (const Real rate : rates(velocity)) ASSERT_EQ(rate, 0);
  // Walls at rest are seen: the fluid moving into them compresses beside them.
  const std::vector<Real> at_rest = rates(Vector<D>::Zero());
  EXPECT_GT(*std::max_element(at_rest.begin(), at_rest.end()), 0);
}

// Fluid and walls moving together: no compression anywhere, beside the walls included.
TEST(Continuity, UniformVelocityWithMovingWallsGivesZero) {
  check_continuity_uniform_velocity<2>(16);
  check_continuity_uniform_velocity<3>(10);
}

template <int D>
void check_wall_state_hydrostatic(int columns) {
  const auto kernel = test_kernel<D>();
  const int rows = 8;
  Layer<D> layer(kernel, columns, rows, WallVelocity::no_slip);
  const Real g = Real(9.81);
  const Real height = Real(rows) * spacing;  // H, where p = 0
  Vector<D> gravity = Vector<D>::Zero();
  gravity[D - 1] = -g;
  Vector<D> fluid_velocity;
  for (int d = 0; d < D; ++d) fluid_velocity[d] = Real(0.3 + 0.2 * d);
  const auto x = std::as_const(layer.fluid)[layer.f.position];
  auto pressure = layer.fluid[layer.f.pressure];
  auto v = layer.fluid[layer.f.velocity];
  for (std::size_t i = 0; i < layer.fluid.size(); ++i) {
    pressure[i] = rest_density * g * (height - x[i][D - 1]);
    v.set(i, fluid_velocity);
  }
  const passes::WallPressureExtrapolation<D> rule{nullptr, gravity, true};
  passes::wall_state<D>(kernel, layer.walls(), layer.fluid, layer.f, &rule);

  // Adami et al. 2012, eq. 27: p_w = Σ_f (p_f + ρ_f g·x_wf) W_wf / Σ_f W_wf, and p_f + ρ0 g·x_wf =
  // ρ0 g (H − y_f) − ρ0 g (y_w − y_f) = ρ0 g (H − y_w) for every f. Two sums of n terms of at most
  // ρ0 g (H + support) W, over a third: 2 (n + 3) ε ρ0 g (H + support).
  const int n = lattice_sums<D>(kernel).neighbors;
  const Real support = kernel.support_radius();
  const Real pressure_tolerance = Real(2 * (n + 3)) * epsilon * rest_density * g * (height + support);
  // v_w = −Σ_f v_f W_wf / Σ_f W_wf = −U: a weighted mean of equal values, two sums of n terms.
  const Real velocity_tolerance = Real(2 * (n + 2)) * epsilon * fluid_velocity.norm();
  const ParticleSet<D>& walls = layer.walls().particles();
  const WallFields<D>& w = layer.walls().fields();
  const auto wall_x = walls[w.position];
  const auto wall_pressure = walls[w.pressure];
  const auto wall_velocity = walls[*w.velocity];
  std::size_t beside_fluid = 0;
  for (std::size_t b = 0; b < walls.size(); ++b) {
    const Real y = wall_x[b][D - 1];
    if (spacing / 2 - y < support) {  // the lowest fluid row, y = Δx/2, is within the support
      ASSERT_NEAR(wall_pressure[b], rest_density * g * (height - y), pressure_tolerance) << "y " << y;
      for (int d = 0; d < D; ++d) ASSERT_NEAR(wall_velocity[b][d], -fluid_velocity[d], velocity_tolerance);
      ++beside_fluid;
    } else {  // no fluid neighbour: no pressure, and the wall's own velocity (at rest)
      ASSERT_EQ(wall_pressure[b], 0) << "y " << y;
      ASSERT_TRUE(wall_velocity[b].isZero(0)) << "y " << y;
    }
  }
  EXPECT_GT(beside_fluid, 0u);
  EXPECT_LT(beside_fluid, walls.size());
}

// Walls under fluid at hydrostatic rest carry the hydrostatic pressure at their own position,
// and mirror the fluid's velocity (no slip at a wall at rest).
TEST(WallState, HydrostaticPressureAndNoSlipMirror) {
  check_wall_state_hydrostatic<2>(16);
  check_wall_state_hydrostatic<3>(10);
}

// Walls accelerating upwards at a under fluid at rest relative to them: in their frame the fluid
// is hydrostatic under g + a, p_f = ρ0 (g + a)(H − y_f), and eq. 27 of Adami et al. 2012 with
// g − a_w gives p_w = ρ0 (g + a)(H − y_w). Without the acceleration term the walls would read
// ρ0 g (H − y_w) plus ρ0 a times the weighted mean depth, off by ρ0 a Δx at least.
template <int D>
void check_wall_state_accelerating(int columns) {
  const auto kernel = test_kernel<D>();
  const int rows = 8;
  Layer<D> layer(kernel, columns, rows, WallVelocity::accelerating);
  const Real g = Real(9.81), a = Real(4.5);
  const Real height = Real(rows) * spacing;
  Vector<D> gravity = Vector<D>::Zero();
  gravity[D - 1] = -g;
  const auto x = std::as_const(layer.fluid)[layer.f.position];
  auto pressure = layer.fluid[layer.f.pressure];
  for (std::size_t i = 0; i < layer.fluid.size(); ++i) pressure[i] = rest_density * (g + a) * (height - x[i][D - 1]);
  ParticleSet<D>& walls = layer.walls().particles();
  const WallFields<D>& w = layer.walls().fields();
  auto acceleration = walls[*w.acceleration];
  for (std::size_t b = 0; b < walls.size(); ++b) acceleration.component[D - 1][b] = a;
  const passes::WallPressureExtrapolation<D> rule{nullptr, gravity, true};
  passes::wall_state<D>(kernel, layer.walls(), layer.fluid, layer.f, &rule);

  // The tolerance of HydrostaticPressureAndNoSlipMirror with g + a for g.
  const int n = lattice_sums<D>(kernel).neighbors;
  const Real support = kernel.support_radius();
  const Real tolerance = Real(2 * (n + 3)) * epsilon * rest_density * (g + a) * (height + support);
  const auto wall_x = std::as_const(walls)[w.position];
  const auto wall_pressure = std::as_const(walls)[w.pressure];
  std::size_t beside_fluid = 0;
  for (std::size_t b = 0; b < walls.size(); ++b) {
    const Real y = wall_x[b][D - 1];
    if (spacing / 2 - y >= support) continue;
    ASSERT_NEAR(wall_pressure[b], rest_density * (g + a) * (height - y), tolerance) << "y " << y;
    ++beside_fluid;
  }
  EXPECT_GT(beside_fluid, 0u);
}

TEST(WallState, AcceleratingWallsFeelGravityMinusTheirAcceleration) {
  check_wall_state_accelerating<2>(16);
  check_wall_state_accelerating<3>(10);
}

template <int D>
void check_position_divergence_and_shift(int columns) {
  const auto kernel = test_kernel<D>();
  Layer<D> layer(kernel, columns, 8, WallVelocity::none);
  std::vector<Real> divergence(layer.fluid.size());
  passes::position_divergence<D>(kernel, layer.fluid, layer.f, layer.interactions, divergence);
  ParticleSet<D>& fluid = layer.fluid;
  const VectorField shift_field = fluid.add_vector("shift");
  const auto shift = fluid[shift_field];
  const passes::ShiftingSettings settings{kernel.smoothing_length() * kernel.smoothing_length() / 2,
                                          kernel.value(spacing), Real(D) - Real(0.5), Real(D) / 2};
  passes::particle_shifting<D>(kernel, settings, fluid, layer.f, layer.interactions, divergence, shift);

  // ∇·r = −Σ_j V_j x_ij·∇W_ij = tr B with V = m/ρ0: D up to the lattice's first moment.
  const LatticeSums<D> sums = lattice_sums<D>(kernel);
  const Real volume = sums.mass() / rest_density;
  const Real expected = sums.moment().trace();
  const Real support = kernel.support_radius();
  // n terms V |x_ij| |∇W_ij|, |x_ij| < support, each with a few roundings.
  const Real divergence_tolerance = Real(sums.neighbors + 4) * epsilon * volume * support * sums.gradient_sum;
  // Σ_j V_j [1 + R (W/W(Δx))⁴] ∇W_ij vanishes on the symmetric lattice: its rounding only, n terms
  // of at most (1 + R) V |∇W|, times the diffusion.
  const Real shift_tolerance =
      Real(sums.neighbors + 8) * epsilon * settings.diffusion * Real(1.2) * volume * sums.gradient_sum;
  check_particles<D>(
      fluid, layer.f, [&](const Vector<D>& x) { return layer.below_surface(x, support); },
      [&](std::size_t i) {
        ASSERT_NEAR(divergence[i], expected, divergence_tolerance) << "particle " << i;
        for (int d = 0; d < D; ++d) ASSERT_NEAR(shift[i][d], 0, shift_tolerance) << "particle " << i;
      });
}

// A uniform lattice over a wall: ∇·r = D and no shift, beside the wall included.
TEST(ParticleShifting, UniformLatticeOverWallIsNotShifted) {
  check_position_divergence_and_shift<2>(16);
  check_position_divergence_and_shift<3>(10);
}

// One neighbour a walk handed to the pass: its source (−1: the fluid; else the contact's
// number), its id and x_ij.
struct Visit {
  int source = 0;
  Index id = 0;
  std::array<Real, 2> x_ij{};
  bool operator==(const Visit&) const = default;
};

struct VisitOutput {
  std::span<std::vector<Visit>> values;
  void set(std::size_t i, std::vector<Visit> visits) const { values[i] = std::move(visits); }
};

// Every particle of `set` within the support of x, by id, with x − x_j.
std::vector<Visit> brute_force(const Vector<2>& x, const ParticleSet<2>& set, int source, Real support) {
  std::vector<Visit> visits;
  const auto xs = set[set.position()];
  const auto ids = set[set.id()];
  for (std::size_t j = 0; j < set.size(); ++j) {
    const Vector<2> x_ij = x - xs[j];
    if (squared_norm<2>(x_ij) < support * support) visits.push_back({source, ids[j], {x_ij[0], x_ij[1]}});
  }
  return visits;
}

std::vector<Visit> sorted_by_id(std::vector<Visit> visits) {
  std::sort(visits.begin(), visits.end(), [](const Visit& a, const Visit& b) { return a.id < b.id; });
  return visits;
}

// for_each_fluid_particle hands each particle its fluid neighbours (itself included), then each
// contact's in the order they were added, every one within the support exactly once; the result
// is the same on 1 and 2 threads. The fluid layer is thin enough that particles in its middle
// row see both contacts, a floor and a lid.
TEST(NeighborWalk, FluidThenEachContactInOrderOnAnyThreadCount) {
  const auto kernel = test_kernel<2>();
  const Real support = kernel.support_radius();
  const int columns = 96, rows = 3;  // more particles than one parallel block (256)
  ParticleSet<2> fluid = lattice_set<2>({0, 0}, {columns, rows});
  GridDomain<2> domain;
  domain.lower = Vector<2>(-spacing, Real(-wall_layers - 1) * spacing);
  domain.upper = Vector<2>(Real(columns + 1) * spacing, Real(rows + wall_layers + 1) * spacing);
  Interactions<2> interactions(domain, support);
  for (const auto& [name, row] : {std::pair{"floor", -wall_layers}, std::pair{"lid", rows}}) {
    ParticleSet<2> walls = lattice_set<2>({0, row}, {columns, wall_layers});
    const WallFields<2> w = add_wall_fields<2>(walls, 1, WallVelocity::none);
    interactions.add_contact(name, ContactRole::wall, ContactMotion::fixed, std::move(walls), w);
  }
  interactions.update(fluid);
  const auto x = std::as_const(fluid)[fluid.position()];
  const auto ids = std::as_const(fluid)[fluid.id()];

  const auto walk = [&](int threads) {
    const ThreadLimit limit(threads);
    std::vector<std::vector<Visit>> visits(fluid.size());
    passes::for_each_fluid_particle<2>(
        interactions, x, VisitOutput{visits}, [&](std::size_t, const passes::FluidNeighbors<2>& neighbors) {
          std::vector<Visit> mine;
          neighbors.fluid_pairs([&](Index j, const Vector<2>& x_ij, Real) {
            mine.push_back({-1, ids[j], {x_ij[0], x_ij[1]}});
          });
          neighbors.contacts([&](const passes::ContactNeighbors<2>& contact) {
            const auto contact_ids = contact.contact().particles()[contact.contact().particles().id()];
            contact.pairs([&](Index b, const Vector<2>& x_ib, Real) {
              mine.push_back({static_cast<int>(contact.number()), contact_ids[b], {x_ib[0], x_ib[1]}});
            });
          });
          return mine;
        });
    return visits;
  };
  const std::vector<std::vector<Visit>> one_thread = walk(1);
  EXPECT_EQ(walk(2), one_thread);

  std::size_t pairs = 0, beside_both = 0;
  for (std::size_t i = 0; i < fluid.size(); ++i) {
    const std::vector<Visit>& visits = one_thread[i];
    ASSERT_TRUE(std::is_sorted(visits.begin(), visits.end(),
                               [](const Visit& a, const Visit& b) { return a.source < b.source; }));
    for (int source = -1; source < 2; ++source) {
      std::vector<Visit> from_source;
      std::copy_if(visits.begin(), visits.end(), std::back_inserter(from_source),
                   [&](const Visit& v) { return v.source == source; });
      const ParticleSet<2>& set = source < 0 ? fluid : interactions.contact(source).particles();
      ASSERT_EQ(sorted_by_id(from_source), sorted_by_id(brute_force(x[i], set, source, support)))
          << "particle id " << ids[i] << ", source " << source;
    }
    pairs += visits.size();
    beside_both += visits.back().source == 1 &&
                   std::any_of(visits.begin(), visits.end(), [](const Visit& v) { return v.source == 0; });
  }
  EXPECT_EQ(interactions.contact(0).name(), "floor");
  EXPECT_EQ(interactions.contact(1).name(), "lid");
  EXPECT_GT(pairs, fluid.size());
  EXPECT_GT(beside_both, 0u);
}

template <int D>
void check_kernel_correction_linear_field(int n) {
  const auto kernel = test_kernel<D>();
  Box<D> box(kernel, n);
  const ParticleSet<D>& fluid = box.fluid;
  const FluidFields<D>& f = box.f;
  std::vector<Real> table(fluid.size() * D * D);
  passes::kernel_gradient_correction<D>(kernel, fluid, box.f, box.interactions, table);
  Vector<D> gradient;
  for (int d = 0; d < D; ++d) gradient[d] = Real(3 - 2 * d);  // a linear field φ = G·x, not along an axis
  const auto x = fluid[f.position];
  const Real volume = lattice_mass<D>(kernel) / rest_density;
  std::size_t corrected_at_surface = 0;
  for (std::size_t i = 0; i < fluid.size(); ++i) {
    const Matrix<D> l = passes::correction_at<D>(table, static_cast<Index>(i));
    if (l == Matrix<D>::Identity()) {
      // Uncorrected only where the support is nearly empty: a corner of the box, not its bulk.
      ASSERT_FALSE(box.in_bulk(x[i], kernel.support_radius())) << "x " << x[i].transpose();
      continue;
    }
    // Σ_j V_j (φ_j − φ_i) L_i ∇W_ij = G exactly (Bonet & Lok 1999), at a face of the box too.
    Vector<D> sum = Vector<D>::Zero();
    Real scale = 0;  // Σ_j |V_j (φ_j − φ_i) L_i ∇W_ij|, the size of the terms
    int terms = 0;
    for (std::size_t j = 0; j < fluid.size(); ++j) {
      const Vector<D> x_ij = x[i] - x[j];
      const Real r = x_ij.norm();
      if (j == i || r >= kernel.support_radius()) continue;
      const Vector<D> term = volume * gradient.dot(-x_ij) * (l * kernel.gradient(x_ij, r));
      sum += term;
      scale += term.norm();
      ++terms;
    }
    // The inverse of M_i carries about cond(M_i) ε (cond ≤ 10 where det M ≥ 0.1 on this lattice),
    // then n terms of a few roundings each: 40 n ε of the terms' size.
    const Real tolerance = Real(40 * terms) * epsilon * scale;
    for (int d = 0; d < D; ++d) ASSERT_NEAR(sum[d], gradient[d], tolerance) << "x " << x[i].transpose();
    corrected_at_surface += !box.in_bulk(x[i], kernel.support_radius());
  }
  EXPECT_GT(corrected_at_surface, 0u);
}

// The renormalised gradient differentiates a linear field exactly wherever the support is filled
// enough to be inverted, up to the faces of a box of fluid where the plain gradient is off by half.
TEST(KernelCorrection, RenormalisedGradientIsExactForALinearField) {
  check_kernel_correction_linear_field<2>(10);
  check_kernel_correction_linear_field<3>(7);
}

template <int D>
void check_riemann_momentum_linear_pressure(int n, bool corrected) {
  const auto kernel = test_kernel<D>();
  const LatticeSums<D> sums = lattice_sums<D>(kernel);
  Box<D> box(kernel, n);
  ParticleSet<D>& fluid = box.fluid;
  const FluidFields<D>& f = box.f;
  Vector<D> gradient;
  for (int d = 0; d < D; ++d) gradient[d] = Real(60 - 70 * d);  // Pa/m, not along an axis
  const auto x = std::as_const(fluid)[f.position];
  auto pressure = fluid[f.pressure];
  for (std::size_t i = 0; i < fluid.size(); ++i) pressure[i] = 200 + gradient.dot(x[i]);
  const passes::ViscositySettings viscosity{scene::ViscosityModel::artificial, 0, 0, 0, 0, kernel.smoothing_length()};
  const passes::RiemannSettings<D> riemann{Real(20), rest_density, Vector<D>::Zero()};
  std::vector<Real> table(fluid.size() * D * D);
  if (corrected) {
    passes::kernel_gradient_correction<D>(kernel, fluid, f, box.interactions, table);
    passes::riemann_momentum<D, scene::ViscosityModel::artificial, true>(kernel, viscosity, riemann, fluid, f,
                                                                         box.interactions, table);
  } else {
    passes::riemann_momentum<D, scene::ViscosityModel::artificial, false>(kernel, viscosity, riemann, fluid, f,
                                                                          box.interactions, {});
  }
  // At rest P* = (p_i + p_j)/2: a_i = −Σ_j m (p_i + p_j)/ρ0² ∇W_ij = −(1/ρ0) B G as for momentum()
  // (B = 0.964 I in 2D, 0.970 I in 3D, the lattice's first moment); with the correction L = B⁻¹
  // wherever the support lies in the bulk, so a_i = −G/ρ0 exactly.
  const Vector<D> expected =
      corrected ? Vector<D>(-gradient / rest_density) : Vector<D>(-sums.moment() * gradient / rest_density);
  Real p_max = 0;
  for (const Real p : std::as_const(pressure)) p_max = std::max(p_max, std::abs(p));
  // n terms 2 m P*/ρ0² ∇W_ij of at most 2 m p_max/ρ0² |∇W_ij|, each with 6 roundings, and with
  // the correction the inverse of B (cond ≈ 1).
  const Real tolerance =
      Real(sums.neighbors + 6) * epsilon * 4 * sums.mass() * p_max / (rest_density * rest_density) * sums.gradient_sum;
  const auto a = std::as_const(fluid)[f.acceleration];
  // Corrected, L_j must be B⁻¹ too: the neighbours' supports in the bulk as well.
  const Real reach = (corrected ? 2 : 1) * kernel.support_radius();
  check_particles<D>(
      fluid, f, [&](const Vector<D>& x_i) { return box.in_bulk(x_i, reach); },
      [&](std::size_t i) {
        for (int d = 0; d < D; ++d) ASSERT_NEAR(a[i][d], expected[d], tolerance) << "x " << x[i].transpose();
      });
}

// Riemann-solver momentum at rest under a linear pressure: the gradient of the lattice, and with
// the kernel gradient correction the exact one.
TEST(RiemannMomentum, LinearPressureAtRestGivesItsGradient) {
  for (const bool corrected : {false, true}) {
    // Corrected, the particles checked lie two supports (5.2 Δx) inside the box.
    check_riemann_momentum_linear_pressure<2>(12, corrected);
    check_riemann_momentum_linear_pressure<3>(corrected ? 12 : 9, corrected);
  }
}

template <int D>
void check_riemann_continuity_hydrostatic(int columns) {
  const auto kernel = test_kernel<D>();
  const int rows = 8;
  Layer<D> layer(kernel, columns, rows, WallVelocity::none);
  const Real g = Real(9.81);
  const Real height = Real(rows) * spacing;
  Vector<D> gravity = Vector<D>::Zero();
  gravity[D - 1] = -g;
  // The hydrostatic pressure in the fluid and, continued, in the walls (as their extrapolation
  // gives it: WallState.HydrostaticPressureAndNoSlipMirror).
  const auto hydrostatic = [&](ParticleSet<D>& set, ScalarField field) {
    const auto x = std::as_const(set)[set.position()];
    auto p = set[field];
    for (std::size_t i = 0; i < set.size(); ++i) p[i] = rest_density * g * (height - x[i][D - 1]);
  };
  hydrostatic(layer.fluid, layer.f.pressure);
  hydrostatic(layer.walls().particles(), layer.walls().fields().pressure);
  const Real sound_speed = 20;
  passes::riemann_continuity<D>(kernel, {sound_speed, rest_density, gravity}, layer.fluid, layer.f, layer.interactions);
  // At rest the pairs' p_i − p_j is the hydrostatic ρ0 g·x_ij, which the pass takes out: each term
  // is a difference of two values of at most ρ0 g (H + support), rounded, over ρ̄ c0.
  const int n = lattice_sums<D>(kernel).neighbors;
  const Real support = kernel.support_radius();
  const Real tolerance = Real(4 * n) * epsilon * rest_density * g * (height + support) / sound_speed *
                         lattice_sums<D>(kernel).gradient_sum * lattice_mass<D>(kernel) / rest_density;
  for (const Real rate : std::as_const(layer.fluid)[layer.f.density_rate]) ASSERT_NEAR(rate, 0, tolerance);
  // Without gravity in the pass, the same pressures diffuse: the rate is far from 0 at the free
  // surface and beside the wall, where the linear pressure's pairs do not cancel (measured in
  // float: 316 kg/m³/s, 740 times the rounding bound above; in double the bound is 10⁹ times
  // smaller), so 100 times the bound tells the correction's work from rounding in both.
  passes::riemann_continuity<D>(kernel, {sound_speed, rest_density, Vector<D>::Zero()}, layer.fluid, layer.f,
                                layer.interactions);
  Real largest = 0;
  for (const Real rate : std::as_const(layer.fluid)[layer.f.density_rate]) largest = std::max(largest, std::abs(rate));
  EXPECT_GT(largest, 100 * tolerance);
}

// Riemann-solver continuity of a layer at hydrostatic rest over a wall: no density change, so the
// Riemann term's diffusion does not flatten the hydrostatic profile.
TEST(RiemannContinuity, HydrostaticRestGivesNoDensityChange) {
  check_riemann_continuity_hydrostatic<2>(16);
  check_riemann_continuity_hydrostatic<3>(10);
}

template <int D>
void check_riemann_continuity_linear_velocity(int n) {
  const auto kernel = test_kernel<D>();
  Box<D> box(kernel, n);
  ParticleSet<D>& fluid = box.fluid;
  const FluidFields<D>& f = box.f;
  const auto x = std::as_const(fluid)[f.position];
  auto v = fluid[f.velocity];
  Real v_max = 0;
  for (std::size_t i = 0; i < fluid.size(); ++i) {
    Vector<D> velocity;
    for (int d = 0; d < D; ++d) velocity[d] = Real(0.5) + Real(1 + d) * x[i][d] - Real(2) * x[i][(d + 1) % D];
    v.set(i, velocity);
    v_max = std::max(v_max, velocity.norm());
  }
  for (Real& p : fluid[f.pressure]) p = 300;
  passes::continuity<D>(kernel, fluid, f, box.interactions, nullptr);
  const std::vector<Real> plain(std::as_const(fluid)[f.density_rate].begin(),
                                std::as_const(fluid)[f.density_rate].end());
  passes::riemann_continuity<D>(kernel, {Real(20), rest_density, Vector<D>::Zero()}, fluid, f, box.interactions);
  // Uniform ρ and p: 2 ρ_i Σ_j (m/ρ_j)(v_i − v*_ij)·∇W_ij = Σ_j m v_ij·∇W_ij, Monaghan's, in the
  // whole box, its faces included; n terms m v_ij·∇W_ij with a few roundings each.
  const LatticeSums<D> sums = lattice_sums<D>(kernel);
  const Real tolerance = Real(sums.neighbors + 6) * epsilon * 4 * sums.mass() * v_max * sums.gradient_sum;
  const auto rate = std::as_const(fluid)[f.density_rate];
  for (std::size_t i = 0; i < fluid.size(); ++i) ASSERT_NEAR(rate[i], plain[i], tolerance) << "particle " << i;
}

// With uniform density and pressure the Riemann continuity equation is Monaghan's.
TEST(RiemannContinuity, UniformPressureGivesTheVelocityDivergence) {
  check_riemann_continuity_linear_velocity<2>(10);
  check_riemann_continuity_linear_velocity<3>(7);
}

}  // namespace
}  // namespace tide
