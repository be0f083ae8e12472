#pragma once

#include <algorithm>
#include <numbers>

#include "tide/core/kernels/smoothing_length.hpp"
#include "tide/core/types.hpp"

namespace tide {

/// Wendland C2 kernel with the normalisation of Dehnen & Aly (2012, "Improving convergence in
/// smoothed particle hydrodynamics simulations without pairing instability", MNRAS 425, 1068,
/// Table 1). Their support radius H is 2h here. With u = r / H,
///   W(r) = σ / H^D · (1 − u)⁴ (1 + 4u)   for u < 1, else 0,
/// σ = 7 / π in 2D and 21 / (2π) in 3D.
template <int D>
class WendlandC2Kernel {
 public:
  static_assert(D == 2 || D == 3, "TideSPH supports two and three dimensions");
  static constexpr int dimension = D;
  static constexpr Real support_factor = 2;

  explicit WendlandC2Kernel(Real h)
      : smoothing_length_(detail::checked_smoothing_length(h, "WendlandC2Kernel")),
        support_radius_(support_factor * h),
        inverse_support_(detail::coefficient_over_power(1.0, support_radius_, 1)),
        value_scale_(detail::coefficient_over_power(sigma, support_radius_, D)),
        derivative_scale_(detail::coefficient_over_power(-20.0 * sigma, support_radius_, D + 1)),
        gradient_scale_(detail::coefficient_over_power(-20.0 * sigma, support_radius_, D + 2)) {}

  Real smoothing_length() const { return smoothing_length_; }
  Real support_radius() const { return support_radius_; }

  // Zero outside the support without a branch or a select (1 − u is clamped at 0 there), the same
  // numbers inside: a pair loop over it vectorises (GCC 12 kept a select on r as a branch).
  Real value(Real r) const {
    const Real u = clamped_u(r);
    const Real t = one_minus_u(r);
    const Real t2 = t * t;
    return value_scale_ * t2 * t2 * (1 + 4 * u);
  }

  // d/du [(1 − u)⁴ (1 + 4u)] = −20 u (1 − u)³; the −20 is folded into the scales.
  Real derivative(Real r) const {
    if (r >= support_radius_) return 0;
    const Real t = one_minus_u(r);
    return derivative_scale_ * (r * inverse_support_) * t * t * t;
  }

  // (1/r) dW/dr = −20 σ / H^(D+2) · (1 − u)³: no division, exactly zero gradient at r = 0, and
  // zero outside the support without a branch, as value().
  Real derivative_over_r(Real r) const {
    const Real t = one_minus_u(r);
    return gradient_scale_ * t * t * t;
  }

  Vector<D> gradient(const Vector<D>& x_ij, Real r) const {
    if (r >= support_radius_) return Vector<D>::Zero();  // also for an infinite x_ij
    return derivative_over_r(r) * x_ij;
  }

 private:
  static constexpr double sigma = D == 2 ? 7.0 / std::numbers::pi : 21.0 / (2.0 * std::numbers::pi);

  // 1 − u taken from the distance to the support edge, so it stays positive inside the support;
  // 0 outside it (a NaN r stays NaN).
  Real one_minus_u(Real r) const { return std::max(support_radius_ - r, Real(0)) * inverse_support_; }
  // u, at most 1: outside the support (an infinite r included) the clamped 1 − u then gives 0.
  Real clamped_u(Real r) const { return std::min(r, support_radius_) * inverse_support_; }

  Real smoothing_length_;
  Real support_radius_;    // H = 2h
  Real inverse_support_;   // 1 / H
  Real value_scale_;       // σ / H^D
  Real derivative_scale_;  // −20 σ / H^(D+1)
  Real gradient_scale_;    // −20 σ / H^(D+2)
};

}  // namespace tide
