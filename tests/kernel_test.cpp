#include "tide/core/kernels/kernel.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <limits>
#include <numbers>
#include <random>
#include <string>
#include <variant>
#include <vector>

namespace tide {
namespace {

constexpr double pi = std::numbers::pi;

// Machine epsilon of the precision the kernels compute in; every tolerance below is derived from it.
constexpr double real_epsilon = std::numeric_limits<Real>::epsilon();

// Smoothing lengths the tests run at: not powers of two, so rounding of 1/h and of the constants shows.
constexpr std::array<double, 3> smoothing_lengths{0.37, 1.0, 2.9};

// What the tests need to know about a kernel beyond its interface: the formula as printed in its
// paper (in double, with q = r / h, deliberately in the unexpanded, unfactored form so that the
// implementation's rewriting is checked), the piecewise breakpoints in units of h with the support
// last, and the smallest q from which finite differences are meaningful (the spiky gradient is
// discontinuous at the origin and the viscosity kernel diverges there; the others are smooth).
template <class Kernel>
struct KernelFacts;

double cube(double x) { return x * x * x; }
double pow5(double x) { return x * x * x * x * x; }
double positive_part(double x) { return std::max(x, 0.0); }

template <int D>
struct KernelFacts<CubicSplineKernel<D>> {
  static constexpr KernelType type = KernelType::cubic_spline;
  static constexpr std::array<double, 2> breakpoints{1, 2};
  static constexpr double smallest_finite_difference_q = 0.01;
  static double paper_value(double q, double h) {  // Monaghan 1992
    const double sigma = D == 2 ? 10 / (7 * pi) : 1 / pi;
    const double shape = q < 1 ? 1 - 1.5 * q * q + 0.75 * cube(q) : 0.25 * cube(positive_part(2 - q));
    return sigma / std::pow(h, D) * shape;
  }
};

template <int D>
struct KernelFacts<WendlandC2Kernel<D>> {
  static constexpr KernelType type = KernelType::wendland_c2;
  static constexpr std::array<double, 1> breakpoints{2};
  static constexpr double smallest_finite_difference_q = 0.01;
  static double paper_value(double q, double h) {  // Dehnen & Aly 2012, Table 1, with H = 2h
    const double sigma = D == 2 ? 7 / pi : 21 / (2 * pi);
    const double u = q / 2;
    return sigma / std::pow(2 * h, D) * std::pow(positive_part(1 - u), 4) * (1 + 4 * u);
  }
};

template <int D>
struct KernelFacts<WendlandC4Kernel<D>> {
  static constexpr KernelType type = KernelType::wendland_c4;
  static constexpr std::array<double, 1> breakpoints{2};
  static constexpr double smallest_finite_difference_q = 0.01;
  static double paper_value(double q, double h) {  // Dehnen & Aly 2012, Table 1, with H = 2h
    const double sigma = D == 2 ? 9 / pi : 495 / (32 * pi);
    const double u = q / 2;
    return sigma / std::pow(2 * h, D) * std::pow(positive_part(1 - u), 6) * (1 + 6 * u + 35.0 / 3 * u * u);
  }
};

template <int D>
struct KernelFacts<QuinticSplineKernel<D>> {
  static constexpr KernelType type = KernelType::quintic_spline;
  static constexpr std::array<double, 3> breakpoints{1, 2, 3};
  static constexpr double smallest_finite_difference_q = 0.01;
  static double paper_value(double q, double h) {  // Morris et al. 1997
    const double sigma = D == 2 ? 7 / (478 * pi) : 1 / (120 * pi);
    const double shape = pow5(positive_part(3 - q)) - 6 * pow5(positive_part(2 - q)) + 15 * pow5(positive_part(1 - q));
    return sigma / std::pow(h, D) * shape;
  }
};

template <int D>
struct KernelFacts<Poly6Kernel<D>> {
  static constexpr KernelType type = KernelType::poly6;
  static constexpr std::array<double, 1> breakpoints{1};
  static constexpr double smallest_finite_difference_q = 0.01;
  static double paper_value(double q, double h) {  // Müller et al. 2003, in terms of h and r
    const double r = q * h;
    const double coefficient = D == 2 ? 4 / (pi * std::pow(h, 8)) : 315 / (64 * pi * std::pow(h, 9));
    return q < 1 ? coefficient * cube(h * h - r * r) : 0;
  }
};

template <int D>
struct KernelFacts<SpikyKernel<D>> {
  static constexpr KernelType type = KernelType::spiky;
  static constexpr std::array<double, 1> breakpoints{1};
  static constexpr double smallest_finite_difference_q = 0.25;
  static double paper_value(double q, double h) {  // Müller et al. 2003, in terms of h and r
    const double r = q * h;
    const double coefficient = D == 2 ? 10 / (pi * std::pow(h, 5)) : 15 / (pi * std::pow(h, 6));
    return q < 1 ? coefficient * cube(h - r) : 0;
  }
};

template <int D>
struct KernelFacts<ViscosityKernel<D>> {
  static constexpr KernelType type = KernelType::viscosity;
  static constexpr std::array<double, 1> breakpoints{1};
  static constexpr double smallest_finite_difference_q = 0.25;
  static double paper_value(double q, double h) {  // Müller et al. 2003, in terms of h and r
    const double r = q * h;
    const double coefficient = D == 2 ? 10 / (3 * pi * h * h) : 15 / (2 * pi * cube(h));
    return q < 1 ? coefficient * (-cube(r) / (2 * cube(h)) + r * r / (h * h) + h / (2 * r) - 1) : 0;
  }
};

// Gauss–Legendre rule on [−1, 1], nodes by Newton's method on the Legendre polynomial P_n.
struct QuadratureRule {
  std::vector<double> nodes;
  std::vector<double> weights;
};

QuadratureRule gauss_legendre(int n) {
  QuadratureRule rule;
  for (int i = 0; i < n; ++i) {
    double x = std::cos(pi * (i + 0.75) / (n + 0.5));
    double dp = 0;
    for (int iteration = 0; iteration < 100; ++iteration) {
      double p_previous = 1;
      double p = x;
      for (int k = 2; k <= n; ++k) {
        const double p_next = ((2 * k - 1) * x * p - (k - 1) * p_previous) / k;
        p_previous = p;
        p = p_next;
      }
      dp = n * (x * p - p_previous) / (x * x - 1);
      const double correction = p / dp;
      x -= correction;
      if (std::abs(correction) < 1e-16) break;
    }
    rule.nodes.push_back(x);
    rule.weights.push_back(2 / ((1 - x * x) * dp * dp));
  }
  return rule;
}

// ∫ W dV over R^D as a radial integral (2πr dr in 2D, 4πr² dr in 3D), summed in double. Composite
// 10-point Gauss–Legendre on each piece between breakpoints: each piece times the radial measure is
// a polynomial of degree ≤ 12 (the viscosity kernel's 1/r is cancelled by the measure), which the
// rule integrates exactly, so what remains is the kernel's own rounding. No node lies on r = 0.
template <class Kernel>
double integral_over_space(const Kernel& kernel) {
  constexpr int D = Kernel::dimension;
  constexpr int subintervals_per_piece = 4;
  static const QuadratureRule rule = gauss_legendre(10);
  const double h = kernel.smoothing_length();
  double total = 0;
  double piece_start = 0;
  for (const double breakpoint : KernelFacts<Kernel>::breakpoints) {
    const double piece_end = breakpoint * h;
    const double width = (piece_end - piece_start) / subintervals_per_piece;
    for (int s = 0; s < subintervals_per_piece; ++s) {
      const double middle = piece_start + (s + 0.5) * width;
      for (std::size_t k = 0; k < rule.nodes.size(); ++k) {
        const Real r = static_cast<Real>(middle + 0.5 * width * rule.nodes[k]);
        const double measure = D == 2 ? 2 * pi * r : 4 * pi * static_cast<double>(r) * r;
        total += 0.5 * width * rule.weights[k] * measure * static_cast<double>(kernel.value(r));
      }
    }
    piece_start = piece_end;
  }
  return total;
}

// Largest |dW/dr| over [smallest finite-difference q, support]: the scale of the gradient, against
// which finite-difference errors are measured (relative errors blow up where dW/dr crosses zero).
template <class Kernel>
double derivative_scale(const Kernel& kernel) {
  const double start = KernelFacts<Kernel>::smallest_finite_difference_q * kernel.smoothing_length();
  double largest = 0;
  for (int i = 0; i <= 1000; ++i) {
    const Real r = static_cast<Real>(start + (kernel.support_radius() - start) * i / 1000.0);
    largest = std::max(largest, std::abs(static_cast<double>(kernel.derivative(r))));
  }
  return largest;
}

// Random points inside the support (and a little beyond, to cover the edge) at distances where
// finite differences are meaningful for this kernel.
template <class Kernel>
std::vector<Vector<Kernel::dimension>> sample_points(const Kernel& kernel, int count) {
  constexpr int D = Kernel::dimension;
  std::mt19937 generator(20240611);
  std::normal_distribution<double> normal;
  const double start = KernelFacts<Kernel>::smallest_finite_difference_q * kernel.smoothing_length();
  std::uniform_real_distribution<double> distance(start, 1.02 * kernel.support_radius());
  std::vector<Vector<D>> points;
  for (int i = 0; i < count; ++i) {
    Eigen::Matrix<double, D, 1> direction;
    for (int d = 0; d < D; ++d) direction[d] = normal(generator);
    points.push_back((distance(generator) * direction.normalized()).template cast<Real>());
  }
  return points;
}

// Central differences: with step ε the truncation error is ε²/6 · |W'''| and the rounding error
// about ε_machine · |W| / ε; ε = ε_machine^(1/3) · h balances them, leaving a relative error of
// order ε_machine^(2/3) (3.7e-11 in double, 2.4e-5 in float) times a kernel-dependent constant
// (W''' h² / max|W'|, largest for the viscosity kernel at q = 0.25; the worst error seen is
// 17 ε_machine^(2/3) of max|W'|). 100 ε_machine^(2/3) is 3.7e-9 in double and 2.4e-3 in float.
const double finite_difference_step_over_h = std::cbrt(real_epsilon);
const double finite_difference_tolerance = 100 * std::pow(real_epsilon, 2.0 / 3.0);

template <class Kernel>
class KernelTest : public testing::Test {};

using AllKernels = testing::Types<CubicSplineKernel<2>, CubicSplineKernel<3>, WendlandC2Kernel<2>, WendlandC2Kernel<3>,
                                  WendlandC4Kernel<2>, WendlandC4Kernel<3>, QuinticSplineKernel<2>,
                                  QuinticSplineKernel<3>, Poly6Kernel<2>, Poly6Kernel<3>, SpikyKernel<2>,
                                  SpikyKernel<3>, ViscosityKernel<2>, ViscosityKernel<3>>;

struct KernelTestName {
  template <class Kernel>
  static std::string GetName(int) {
    return std::string(kernel_name(KernelFacts<Kernel>::type)) + "_" + std::to_string(Kernel::dimension) + "d";
  }
};

TYPED_TEST_SUITE(KernelTest, AllKernels, KernelTestName);

TYPED_TEST(KernelTest, IntegratesToOne) {
  // The quadrature itself is exact (see integral_over_space), so the error is the kernel's own
  // rounding: each value is off by a few ε_machine relative (constants, 1/h, the polynomial), and
  // the weighted sum by the same relative amount. In double that is ~1e-15; in float a few
  // ε_float = 1.2e-7 (at most 3.3e-7 seen), so the 1e-6 bound (8.4 ε_float) holds in both.
  const double tolerance = 1e-6;
  for (const double h : smoothing_lengths) {
    const TypeParam kernel(static_cast<Real>(h));
    EXPECT_NEAR(integral_over_space(kernel), 1.0, tolerance) << "h = " << h;
  }
}

TYPED_TEST(KernelTest, MatchesThePublishedFormula) {
  using Facts = KernelFacts<TypeParam>;
  for (const double h : smoothing_lengths) {
    const TypeParam kernel(static_cast<Real>(h));
    const double reference_scale = Facts::paper_value(0.5, h);
    for (int i = 0; i <= 400; ++i) {
      const double q = Facts::smallest_finite_difference_q + (Facts::breakpoints.back() * 1.1) * i / 400.0;
      const Real r = static_cast<Real>(q * h);
      const double exact = Facts::paper_value(static_cast<double>(r) / h, h);
      // A few ε_machine of the kernel's value scale; the printed forms cancel by up to a factor 4.
      EXPECT_NEAR(kernel.value(r), exact, 64 * real_epsilon * (std::abs(exact) + reference_scale)) << "q = " << q;
    }
  }
}

TYPED_TEST(KernelTest, DerivativeMatchesCentralDifferencesOfValue) {
  for (const double h : smoothing_lengths) {
    const TypeParam kernel(static_cast<Real>(h));
    const double scale = derivative_scale(kernel);
    const Real step = static_cast<Real>(finite_difference_step_over_h * h);
    for (const auto& x : sample_points(kernel, 300)) {
      const Real r = x.norm();
      const Real above = r + step;
      const Real below = r - step;
      const double numeric = (static_cast<double>(kernel.value(above)) - static_cast<double>(kernel.value(below))) /
                             (static_cast<double>(above) - static_cast<double>(below));
      EXPECT_NEAR(kernel.derivative(r), numeric, finite_difference_tolerance * scale) << "r / h = " << r / h;
    }
  }
}

TYPED_TEST(KernelTest, GradientMatchesCentralDifferencesOfValue) {
  constexpr int D = TypeParam::dimension;
  for (const double h : smoothing_lengths) {
    const TypeParam kernel(static_cast<Real>(h));
    const double scale = derivative_scale(kernel);
    const Real step = static_cast<Real>(finite_difference_step_over_h * h);
    for (const auto& x : sample_points(kernel, 300)) {
      const Vector<D> gradient = kernel.gradient(x, x.norm());
      for (int d = 0; d < D; ++d) {
        Vector<D> above = x;
        Vector<D> below = x;
        above[d] += step;
        below[d] -= step;
        const double numeric =
            (static_cast<double>(kernel.value(above.norm())) - static_cast<double>(kernel.value(below.norm()))) /
            (static_cast<double>(above[d]) - static_cast<double>(below[d]));
        EXPECT_NEAR(gradient[d], numeric, finite_difference_tolerance * scale)
            << "component " << d << ", r / h = " << x.norm() / h;
      }
    }
  }
}

TYPED_TEST(KernelTest, GradientIsRadialAndAntisymmetric) {
  constexpr int D = TypeParam::dimension;
  const TypeParam kernel(Real(0.37));
  const double scale = derivative_scale(kernel);
  for (const auto& x : sample_points(kernel, 300)) {
    const Real r = x.norm();
    const Vector<D> gradient = kernel.gradient(x, r);
    // ∇_i W(x_ij) = −∇_j W(x_ji): pair forces built from it are equal and opposite, bit for bit.
    const Vector<D> mirrored = kernel.gradient(-x, r);
    // W depends on r alone, so the gradient follows any reflection or axis permutation exactly.
    const Vector<D> reversed = kernel.gradient(x.reverse(), r);
    for (int d = 0; d < D; ++d) {
      EXPECT_EQ(gradient[d], -mirrored[d]);
      EXPECT_EQ(gradient[D - 1 - d], reversed[d]);
      EXPECT_NEAR(gradient[d], kernel.derivative(r) * x[d] / r, 16 * real_epsilon * scale);
    }
  }
}

TYPED_TEST(KernelTest, GradientIsZeroAtTheOrigin) {
  constexpr int D = TypeParam::dimension;
  const TypeParam kernel(Real(0.37));
  const Vector<D> gradient = kernel.gradient(Vector<D>::Zero(), 0);
  for (int d = 0; d < D; ++d) EXPECT_EQ(gradient[d], 0);
}

TYPED_TEST(KernelTest, IsNonNegativeAndNonIncreasing) {
  for (const double h : smoothing_lengths) {
    const TypeParam kernel(static_cast<Real>(h));
    std::vector<Real> distances{0, std::nextafter(kernel.support_radius(), Real(0))};
    for (int i = 0; i <= 2000; ++i) distances.push_back(static_cast<Real>(1.2 * kernel.support_radius() * i / 2000));
    for (const Real r : distances) {
      EXPECT_GE(kernel.value(r), 0) << "r / h = " << r / h;
      EXPECT_LE(kernel.derivative(r), 0) << "r / h = " << r / h;
    }
  }
}

TYPED_TEST(KernelTest, PeakAtTheOriginIsFiniteExceptForTheViscosityKernel) {
  const TypeParam kernel(Real(0.37));
  if (KernelFacts<TypeParam>::type == KernelType::viscosity) {
    EXPECT_EQ(kernel.value(0), std::numeric_limits<Real>::infinity());
  } else {
    EXPECT_TRUE(std::isfinite(kernel.value(0)));
    EXPECT_GT(kernel.value(0), kernel.value(Real(0.01) * kernel.support_radius()));
  }
}

TYPED_TEST(KernelTest, VanishesAtAndBeyondTheSupport) {
  constexpr int D = TypeParam::dimension;
  for (const double h : smoothing_lengths) {
    const TypeParam kernel(static_cast<Real>(h));
    const Real support = kernel.support_radius();
    EXPECT_EQ(support, TypeParam::support_factor * static_cast<Real>(h));
    for (const Real r : {support, std::nextafter(support, Real(2) * support), Real(1.001) * support, Real(2) * support,
                         Real(1e3) * support, std::numeric_limits<Real>::infinity()}) {
      EXPECT_EQ(kernel.value(r), 0) << "r = " << r;
      EXPECT_EQ(kernel.derivative(r), 0) << "r = " << r;
      if constexpr (requires { kernel.derivative_over_r(r); }) {
        EXPECT_EQ(kernel.derivative_over_r(r), 0) << "r = " << r;
      }
      const Vector<D> gradient = kernel.gradient(Vector<D>::Constant(r / std::sqrt(Real(D))), r);
      for (int d = 0; d < D; ++d) EXPECT_EQ(gradient[d], 0) << "r = " << r;
      if constexpr (requires { kernel.laplacian(r); }) {
        EXPECT_EQ(kernel.laplacian(r), 0);
      }
    }
  }
}

// The pair loops' kernels have no branch on r (so that they vectorise): a NaN distance, from a
// state that has blown up, must still give a NaN rather than a zero the state check cannot see.
TYPED_TEST(KernelTest, NanDistanceGivesNan) {
  const TypeParam kernel(static_cast<Real>(smoothing_lengths[0]));
  const Real nan = std::numeric_limits<Real>::quiet_NaN();
  EXPECT_TRUE(std::isnan(kernel.value(nan)));
  if constexpr (requires { kernel.derivative_over_r(nan); }) {
    EXPECT_TRUE(std::isnan(kernel.derivative_over_r(nan)));
  }
}

TYPED_TEST(KernelTest, ValueAndDerivativeAreContinuousAtTheSupportEdge) {
  // Every kernel here has W, W' (and W'') → 0 at the edge, the spiky one included: its W' =
  // −3σ/h^(D+1) (1 − q)² vanishes at q = 1; its discontinuity is in the gradient at the origin.
  // Just inside the edge, at 1 − δ, W and W' are therefore O(δ²) or smaller.
  constexpr double inside = 1e-4;
  for (const double h : smoothing_lengths) {
    const TypeParam kernel(static_cast<Real>(h));
    const Real r = static_cast<Real>(kernel.support_radius() * (1 - inside));
    EXPECT_LE(std::abs(kernel.value(r)), 1e-6 * kernel.value(kernel.support_radius() / 2));
    EXPECT_LE(std::abs(kernel.derivative(r)), 1e-6 * derivative_scale(kernel));
  }
}

TYPED_TEST(KernelTest, PiecesJoinContinuously) {
  // Across an interior breakpoint b: W and W' change by O(δ) over [b(1 − δ), b(1 + δ)]; a wrong
  // coefficient in one piece would make an O(1) jump. δ = √ε_machine keeps both rounding and
  // slope contributions well below 100 δ.
  const double offset = std::sqrt(real_epsilon);
  using Facts = KernelFacts<TypeParam>;
  for (const double h : smoothing_lengths) {
    const TypeParam kernel(static_cast<Real>(h));
    const double value_scale = kernel.value(kernel.support_radius() / 2);
    const double slope_scale = derivative_scale(kernel);
    for (std::size_t i = 0; i + 1 < Facts::breakpoints.size(); ++i) {
      const Real below = static_cast<Real>(Facts::breakpoints[i] * h * (1 - offset));
      const Real above = static_cast<Real>(Facts::breakpoints[i] * h * (1 + offset));
      EXPECT_NEAR(kernel.value(below), kernel.value(above), 100 * offset * value_scale);
      EXPECT_NEAR(kernel.derivative(below), kernel.derivative(above), 100 * offset * slope_scale);
    }
  }
}

TYPED_TEST(KernelTest, RejectsInvalidSmoothingLengths) {
  for (const Real h : {Real(0), Real(-0.0), Real(-1), std::numeric_limits<Real>::quiet_NaN(),
                       std::numeric_limits<Real>::infinity(), -std::numeric_limits<Real>::infinity()}) {
    EXPECT_THROW(TypeParam{h}, std::invalid_argument) << "h = " << h;
  }
  EXPECT_EQ(TypeParam(Real(0.37)).smoothing_length(), Real(0.37));
}

TYPED_TEST(KernelTest, MakeKernelChoosesThisKernel) {
  constexpr int D = TypeParam::dimension;
  const KernelType type = KernelFacts<TypeParam>::type;
  const AnyKernel<D> any = make_kernel<D>(type, Real(0.37));
  ASSERT_TRUE(std::holds_alternative<TypeParam>(any));
  EXPECT_EQ(any.index(), static_cast<std::size_t>(type));
  EXPECT_EQ(kernel_support_factor(type), TypeParam::support_factor);
  const Real support = std::visit([](const auto& kernel) { return kernel.support_radius(); }, any);
  EXPECT_EQ(support, kernel_support_factor(type) * Real(0.37));
  const Real value = std::visit([](const auto& kernel) { return kernel.value(Real(0.1)); }, any);
  EXPECT_EQ(value, TypeParam(Real(0.37)).value(Real(0.1)));
}

// The viscosity kernel's Laplacian against W'' + (D − 1) W' / r by second-order central
// differences of W: step ε gives truncation ε²/12 · |W''''| and rounding about 4 ε_machine |W| / ε²;
// ε = ε_machine^(1/4) · h balances them at a relative error of order √ε_machine (1.5e-8 in double,
// 3.5e-4 in float) times W'''' h² / ∇²W on q ≥ 0.3 (the worst error seen is 10 √ε_machine of the
// Laplacian's largest value there); the tolerance is 100 √ε_machine of that value.
template <int D>
void check_viscosity_laplacian_against_finite_differences() {
  const double tolerance = 100 * std::sqrt(real_epsilon);
  for (const double h : smoothing_lengths) {
    const ViscosityKernel<D> kernel(static_cast<Real>(h));
    const Real step = static_cast<Real>(std::pow(real_epsilon, 0.25) * h);
    const double scale = kernel.laplacian(static_cast<Real>(0.3 * h));
    for (int i = 0; i <= 200; ++i) {
      const Real r = static_cast<Real>(h * (0.3 + 0.75 * i / 200.0));
      const double spacing = (static_cast<double>(r + step) - static_cast<double>(r - step)) / 2;
      const double above = kernel.value(r + step);
      const double middle = kernel.value(r);
      const double below = kernel.value(r - step);
      const double second = (above - 2 * middle + below) / (spacing * spacing);
      const double first = (above - below) / (2 * spacing);
      EXPECT_NEAR(kernel.laplacian(r), second + (D - 1) * first / static_cast<double>(r), tolerance * scale)
          << "r / h = " << r / h;
    }
  }
}

TEST(ViscosityKernel, LaplacianMatchesFiniteDifferences2d) {
  check_viscosity_laplacian_against_finite_differences<2>();
}
TEST(ViscosityKernel, LaplacianMatchesFiniteDifferences3d) {
  check_viscosity_laplacian_against_finite_differences<3>();
}

TEST(ViscosityKernel, LaplacianMatchesClosedForms) {
  // 3D: Müller et al. 2003, 45 / (π h⁶) (h − r). 2D: σ (W'' + W'/r) of the 2D-normalised kernel,
  // 10 / (3π h²) · (4/h² − 9r/(2h³) + h/(2r³)), in the unfactored form.
  const double h = 0.37;
  const ViscosityKernel<2> planar(static_cast<Real>(h));
  const ViscosityKernel<3> spatial(static_cast<Real>(h));
  const double scale_2d = 10 / (3 * pi * std::pow(h, 4));
  for (int i = 1; i < 100; ++i) {
    const Real r = static_cast<Real>(h * i / 100.0);
    const double rd = r;
    const double expected_3d = 45 / (pi * std::pow(h, 6)) * (h - rd);
    const double expected_2d = 10 / (3 * pi * h * h) * (4 / (h * h) - 9 * rd / (2 * cube(h)) + h / (2 * cube(rd)));
    EXPECT_NEAR(spatial.laplacian(r), expected_3d, 64 * real_epsilon * 45 / (pi * std::pow(h, 5)));
    EXPECT_NEAR(planar.laplacian(r), expected_2d, 64 * real_epsilon * (expected_2d + scale_2d));
    EXPECT_GT(planar.laplacian(r), 0);
  }
}

TEST(KernelType, NamesRoundTrip) {
  std::vector<std::string_view> names;
  for (const KernelType type : all_kernel_types) {
    EXPECT_EQ(kernel_from_name(kernel_name(type)), type);
    names.push_back(kernel_name(type));
  }
  std::sort(names.begin(), names.end());
  EXPECT_EQ(std::adjacent_find(names.begin(), names.end()), names.end());
  EXPECT_EQ(kernel_name(KernelType::wendland_c4), "wendland_c4");
  static_assert(kernel_from_name("spiky") == KernelType::spiky);
}

TEST(KernelType, UnknownNamesAreRefused) {
  for (const std::string_view name : {"", "cubic", "Cubic_Spline", "wendland", "poly6 ", "gaussian"}) {
    EXPECT_FALSE(kernel_from_name(name).has_value()) << "'" << name << "'";
  }
}

TEST(KernelType, SupportFactors) {
  EXPECT_EQ(kernel_support_factor(KernelType::cubic_spline), 2);
  EXPECT_EQ(kernel_support_factor(KernelType::wendland_c2), 2);
  EXPECT_EQ(kernel_support_factor(KernelType::wendland_c4), 2);
  EXPECT_EQ(kernel_support_factor(KernelType::quintic_spline), 3);
  EXPECT_EQ(kernel_support_factor(KernelType::poly6), 1);
  EXPECT_EQ(kernel_support_factor(KernelType::spiky), 1);
  EXPECT_EQ(kernel_support_factor(KernelType::viscosity), 1);
}

TEST(KernelType, MakeKernelRefusesInvalidSmoothingLength) {
  EXPECT_THROW(make_kernel<3>(KernelType::wendland_c2, 0), std::invalid_argument);
  EXPECT_THROW(make_kernel<2>(KernelType::poly6, -1), std::invalid_argument);
}

}  // namespace
}  // namespace tide
