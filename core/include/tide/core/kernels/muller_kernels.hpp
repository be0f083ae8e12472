#pragma once

#include <numbers>

#include "tide/core/kernels/smoothing_length.hpp"
#include "tide/core/types.hpp"

// The three kernels of Müller, Charypar & Gross (2003, "Particle-based fluid simulation for
// interactive applications", Proc. SCA 2003), each with support h as in the paper. The paper
// gives the 3D normalisations; the 2D ones are derived here from ∫ W 2πr dr = 1 and checked by
// quadrature in the tests. With q = r / h, each kernel is W(r) = σ / h^D · f(q).

namespace tide {

/// Müller et al. (2003) poly6 kernel: W(r) = σ / h^D · (1 − q²)³ for q < 1, else 0;
/// σ = 315 / (64π) in 3D (the paper's 315 / (64π h⁹) (h² − r²)³) and 4 / π in 2D.
template <int D>
class Poly6Kernel {
 public:
  static_assert(D == 2 || D == 3, "TideSPH supports two and three dimensions");
  static constexpr int dimension = D;
  static constexpr Real support_factor = 1;

  explicit Poly6Kernel(Real h)
      : smoothing_length_(detail::checked_smoothing_length(h, "Poly6Kernel")),
        support_radius_(support_factor * h),
        inverse_h_(detail::coefficient_over_power(1.0, h, 1)),
        value_scale_(detail::coefficient_over_power(sigma, h, D)),
        derivative_scale_(detail::coefficient_over_power(-6.0 * sigma, h, D + 1)),
        gradient_scale_(detail::coefficient_over_power(-6.0 * sigma, h, D + 2)) {}

  Real smoothing_length() const { return smoothing_length_; }
  Real support_radius() const { return support_radius_; }

  Real value(Real r) const {
    if (r >= support_radius_) return 0;
    const Real s = one_minus_q2(r);
    return value_scale_ * s * s * s;
  }

  // d/dq (1 − q²)³ = −6q (1 − q²)²; the −6 is folded into the scales.
  Real derivative(Real r) const {
    if (r >= support_radius_) return 0;
    const Real s = one_minus_q2(r);
    return derivative_scale_ * (r * inverse_h_) * s * s;
  }

  // (1/r) dW/dr = −6σ / h^(D+2) · (1 − q²)²: no division, exactly zero gradient at r = 0.
  Real derivative_over_r(Real r) const {
    const Real s = one_minus_q2(r);
    return r >= support_radius_ ? Real(0) : gradient_scale_ * s * s;
  }

  Vector<D> gradient(const Vector<D>& x_ij, Real r) const {
    if (r >= support_radius_) return Vector<D>::Zero();  // also for an infinite x_ij
    return derivative_over_r(r) * x_ij;
  }

 private:
  static constexpr double sigma = D == 2 ? 4.0 / std::numbers::pi : 315.0 / (64.0 * std::numbers::pi);

  // 1 − q² as (1 − q)(1 + q) with 1 − q from the distance to the support edge: no cancellation
  // near the edge, and never negative inside the support.
  Real one_minus_q2(Real r) const { return (support_radius_ - r) * inverse_h_ * (1 + r * inverse_h_); }

  Real smoothing_length_;
  Real support_radius_;
  Real inverse_h_;
  Real value_scale_;       // σ / h^D
  Real derivative_scale_;  // −6σ / h^(D+1)
  Real gradient_scale_;    // −6σ / h^(D+2)
};

/// Müller et al. (2003) spiky kernel: W(r) = σ / h^D · (1 − q)³ for q < 1, else 0;
/// σ = 15 / π in 3D (the paper's 15 / (π h⁶) (h − r)³) and 10 / π in 2D. Its gradient does not
/// vanish as r → 0 (that is its purpose: pressure keeps particles apart), so the gradient is
/// discontinuous at the origin and set to zero there, where its direction is undefined.
template <int D>
class SpikyKernel {
 public:
  static_assert(D == 2 || D == 3, "TideSPH supports two and three dimensions");
  static constexpr int dimension = D;
  static constexpr Real support_factor = 1;

  explicit SpikyKernel(Real h)
      : smoothing_length_(detail::checked_smoothing_length(h, "SpikyKernel")),
        support_radius_(support_factor * h),
        inverse_h_(detail::coefficient_over_power(1.0, h, 1)),
        value_scale_(detail::coefficient_over_power(sigma, h, D)),
        derivative_scale_(detail::coefficient_over_power(-3.0 * sigma, h, D + 1)) {}

  Real smoothing_length() const { return smoothing_length_; }
  Real support_radius() const { return support_radius_; }

  Real value(Real r) const {
    if (r >= support_radius_) return 0;
    const Real t = one_minus_q(r);
    return value_scale_ * t * t * t;
  }

  Real derivative(Real r) const {
    if (r >= support_radius_) return 0;
    const Real t = one_minus_q(r);
    return derivative_scale_ * t * t;
  }

  // (1/r) dW/dr, so that ∇W = derivative_over_r(r) x_ij; zero at r = 0.
  Real derivative_over_r(Real r) const { return r >= support_radius_ || r <= 0 ? Real(0) : derivative(r) / r; }

  Vector<D> gradient(const Vector<D>& x_ij, Real r) const {
    if (r >= support_radius_) return Vector<D>::Zero();  // also for an infinite x_ij
    return derivative_over_r(r) * x_ij;
  }

 private:
  static constexpr double sigma = D == 2 ? 10.0 / std::numbers::pi : 15.0 / std::numbers::pi;

  // 1 − q from the distance to the support edge, so it stays positive inside the support.
  Real one_minus_q(Real r) const { return (support_radius_ - r) * inverse_h_; }

  Real smoothing_length_;
  Real support_radius_;
  Real inverse_h_;
  Real value_scale_;       // σ / h^D
  Real derivative_scale_;  // −3σ / h^(D+1)
};

/// Müller et al. (2003) viscosity kernel: W(r) = σ / h^D · (−q³/2 + q² + 1/(2q) − 1) for q < 1,
/// else 0; σ = 15 / (2π) in 3D (as in the paper) and 10 / (3π) in 2D. It is made for its
/// Laplacian, which is positive everywhere inside the support; W itself diverges like 1/(2q) at
/// r = 0, so value(0) and derivative(0) are infinite (gradient(0) is zero by convention) and the
/// kernel must not be used for density summation.
template <int D>
class ViscosityKernel {
 public:
  static_assert(D == 2 || D == 3, "TideSPH supports two and three dimensions");
  static constexpr int dimension = D;
  static constexpr Real support_factor = 1;

  explicit ViscosityKernel(Real h)
      : smoothing_length_(detail::checked_smoothing_length(h, "ViscosityKernel")),
        support_radius_(support_factor * h),
        inverse_h_(detail::coefficient_over_power(1.0, h, 1)),
        value_scale_(detail::coefficient_over_power(0.5 * sigma, h, D)),
        derivative_scale_(detail::coefficient_over_power(-0.5 * sigma, h, D + 1)),
        laplacian_scale_(detail::coefficient_over_power(D == 2 ? 0.5 * sigma : 6.0 * sigma, h, D + 2)) {}

  Real smoothing_length() const { return smoothing_length_; }
  Real support_radius() const { return support_radius_; }

  // The polynomial factorises as f(q) = (1 − q)³ (1 + q) / (2q): evaluated that way it is
  // non-negative and free of the cancellation of the paper's four terms near the support edge.
  Real value(Real r) const {
    if (r >= support_radius_) return 0;
    const Real q = r * inverse_h_;
    const Real t = one_minus_q(r);
    return value_scale_ * t * t * t * (1 + q) / q;
  }

  // f'(q) = −(1 − q)² (3q² + 2q + 1) / (2q²).
  Real derivative(Real r) const {
    if (r >= support_radius_) return 0;
    const Real q = r * inverse_h_;
    const Real t = one_minus_q(r);
    return derivative_scale_ * t * t * (1 + q * (2 + 3 * q)) / (q * q);
  }

  // (1/r) dW/dr, so that ∇W = derivative_over_r(r) x_ij; zero at r = 0.
  Real derivative_over_r(Real r) const { return r >= support_radius_ || r <= 0 ? Real(0) : derivative(r) / r; }

  Vector<D> gradient(const Vector<D>& x_ij, Real r) const {
    if (r >= support_radius_) return Vector<D>::Zero();  // also for an infinite x_ij
    return derivative_over_r(r) * x_ij;
  }

  /// ∇²W = W'' + (D − 1) W' / r. In 3D this is the paper's 45 / (π h⁶) (h − r). In 2D, from the
  /// 2D-normalised W: σ / h⁴ · (4 − 9q/2 + 1/(2q³)) = σ / h⁴ · (1 − q)(9q³ + q² + q + 1) / (2q³),
  /// still positive inside the support but, unlike 3D, divergent like 1/q³ at r = 0.
  Real laplacian(Real r) const {
    if (r >= support_radius_) return 0;
    const Real t = one_minus_q(r);
    if constexpr (D == 3) {
      return laplacian_scale_ * t;
    } else {
      const Real q = r * inverse_h_;
      return laplacian_scale_ * t * (1 + q * (1 + q * (1 + 9 * q))) / (q * q * q);
    }
  }

 private:
  static constexpr double sigma = D == 2 ? 10.0 / (3.0 * std::numbers::pi) : 15.0 / (2.0 * std::numbers::pi);

  // 1 − q from the distance to the support edge, so it stays positive inside the support.
  Real one_minus_q(Real r) const { return (support_radius_ - r) * inverse_h_; }

  Real smoothing_length_;
  Real support_radius_;
  Real inverse_h_;
  Real value_scale_;       // σ / (2 h^D)
  Real derivative_scale_;  // −σ / (2 h^(D+1))
  Real laplacian_scale_;   // 2D: σ / (2 h⁴); 3D: 6σ / h⁵
};

}  // namespace tide
