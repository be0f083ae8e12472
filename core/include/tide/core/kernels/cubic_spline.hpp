#pragma once

#include <numbers>

#include "tide/core/kernels/smoothing_length.hpp"
#include "tide/core/types.hpp"

namespace tide {

/// M4 cubic B-spline of Monaghan (1992, "Smoothed particle hydrodynamics", Annu. Rev. Astron.
/// Astrophys. 30, 543), support 2h. With q = r / h,
///   W(r) = σ / h^D · { 1 − 3/2 q² + 3/4 q³   for 0 ≤ q < 1,
///                      1/4 (2 − q)³          for 1 ≤ q < 2,
///                      0                     for q ≥ 2 },
/// σ = 10 / (7π) in 2D and 1 / π in 3D (Monaghan 1992; ∫ W dV = 1 is checked by the tests).
template <int D>
class CubicSplineKernel {
 public:
  static_assert(D == 2 || D == 3, "TideSPH supports two and three dimensions");
  static constexpr int dimension = D;
  static constexpr Real support_factor = 2;

  explicit CubicSplineKernel(Real h)
      : smoothing_length_(detail::checked_smoothing_length(h, "CubicSplineKernel")),
        support_radius_(support_factor * h),
        inverse_h_(detail::coefficient_over_power(1.0, h, 1)),
        value_scale_(detail::coefficient_over_power(sigma, h, D)),
        derivative_scale_(detail::coefficient_over_power(sigma, h, D + 1)),
        gradient_scale_(detail::coefficient_over_power(sigma, h, D + 2)) {}

  Real smoothing_length() const { return smoothing_length_; }
  Real support_radius() const { return support_radius_; }

  // Each piece is computed and one selected, with the values the piecewise formula gives: in a
  // pair loop this is a blend rather than a branch (which piece a neighbour falls in is
  // unpredictable), and the loop vectorises.
  Real value(Real r) const {
    const Real q = r * inverse_h_;
    const Real two_minus_q = outer_distance(r);
    const Real outer = Real(0.25) * value_scale_ * two_minus_q * two_minus_q * two_minus_q;
    const Real inner = value_scale_ * (1 + q * q * (Real(-1.5) + Real(0.75) * q));
    return r >= support_radius_ ? Real(0) : q >= 1 ? outer : inner;
  }

  Real derivative(Real r) const {
    const Real q = r * inverse_h_;
    const Real two_minus_q = outer_distance(r);
    const Real outer = Real(-0.75) * derivative_scale_ * two_minus_q * two_minus_q;
    const Real inner = derivative_scale_ * q * (Real(-3) + Real(2.25) * q);
    return r >= support_radius_ ? Real(0) : q >= 1 ? outer : inner;
  }

  // (1/r) dW/dr, so that ∇W = derivative_over_r(r) x_ij. The inner piece's dW/dr carries a
  // factor q that cancels 1/r: no division, and the gradient is exactly zero at r = 0 without a
  // special case.
  Real derivative_over_r(Real r) const {
    const Real q = r * inverse_h_;
    const Real two_minus_q = outer_distance(r);
    const Real outer = Real(-0.75) * derivative_scale_ * two_minus_q * two_minus_q / r;
    const Real inner = gradient_scale_ * (Real(-3) + Real(2.25) * q);
    return r >= support_radius_ ? Real(0) : q >= 1 ? outer : inner;
  }

  Vector<D> gradient(const Vector<D>& x_ij, Real r) const {
    if (r >= support_radius_) return Vector<D>::Zero();  // also for an infinite x_ij
    return derivative_over_r(r) * x_ij;
  }

 private:
  static constexpr double sigma = D == 2 ? 10.0 / (7.0 * std::numbers::pi) : 1.0 / std::numbers::pi;

  // 2 − q taken from the distance to the support edge, so it stays positive inside the support
  // even where r · (1/h) rounds to 2 or just above.
  Real outer_distance(Real r) const { return (support_radius_ - r) * inverse_h_; }

  Real smoothing_length_;
  Real support_radius_;
  Real inverse_h_;
  Real value_scale_;       // σ / h^D
  Real derivative_scale_;  // σ / h^(D+1)
  Real gradient_scale_;    // σ / h^(D+2)
};

}  // namespace tide
