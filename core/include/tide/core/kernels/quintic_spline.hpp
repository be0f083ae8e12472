#pragma once

#include <numbers>

#include "tide/core/kernels/smoothing_length.hpp"
#include "tide/core/types.hpp"

namespace tide {

/// Quintic spline of Morris, Fox & Zhu (1997, "Modeling low Reynolds number incompressible flows
/// using SPH", J. Comput. Phys. 136, 214), support 3h. With q = r / h,
///   W(r) = σ / h^D · { (3 − q)⁵ − 6 (2 − q)⁵ + 15 (1 − q)⁵   for 0 ≤ q < 1,
///                      (3 − q)⁵ − 6 (2 − q)⁵                 for 1 ≤ q < 2,
///                      (3 − q)⁵                              for 2 ≤ q < 3,
///                      0                                     for q ≥ 3 },
/// σ = 7 / (478π) in 2D (Morris et al. 1997) and 1 / (120π) in 3D. The 3D constant is derived
/// here from ∫ W dV = 1; the 3 / (359π) often quoted for 3D is 0.3 % off and fails that test.
template <int D>
class QuinticSplineKernel {
 public:
  static_assert(D == 2 || D == 3, "TideSPH supports two and three dimensions");
  static constexpr int dimension = D;
  static constexpr Real support_factor = 3;

  explicit QuinticSplineKernel(Real h)
      : smoothing_length_(detail::checked_smoothing_length(h, "QuinticSplineKernel")),
        support_radius_(support_factor * h),
        inverse_h_(detail::coefficient_over_power(1.0, h, 1)),
        value_scale_(detail::coefficient_over_power(sigma, h, D)),
        derivative_scale_(detail::coefficient_over_power(sigma, h, D + 1)),
        gradient_scale_(detail::coefficient_over_power(sigma, h, D + 2)) {}

  Real smoothing_length() const { return smoothing_length_; }
  Real support_radius() const { return support_radius_; }

  // Each piece is computed and one selected, as in CubicSplineKernel: a blend in a pair loop,
  // which then vectorises, rather than an unpredictable branch.
  Real value(Real r) const {
    const Real q = r * inverse_h_;
    const Real outer = pow5(outer_distance(r));
    const Real middle = outer - 6 * pow5(2 - q);
    // The three quintics expanded: 66 − 60q² + 30q⁴ − 10q⁵, cheaper and without their cancellation.
    const Real q2 = q * q;
    const Real inner = 66 + q2 * (-60 + q2 * (30 - 10 * q));
    return r >= support_radius_ ? Real(0) : value_scale_ * (q >= 2 ? outer : q >= 1 ? middle : inner);
  }

  Real derivative(Real r) const {
    if (r >= support_radius_) return 0;
    const Real q = r * inverse_h_;
    if (q >= 1) return derivative_scale_ * outer_derivative(r, q);
    return derivative_scale_ * q * inner_derivative_over_q(q);
  }

  // (1/r) dW/dr, so that ∇W = derivative_over_r(r) x_ij; the pieces are selected rather than
  // branched on, so that a pair loop vectorises. The inner piece's factor q cancels 1/r: no
  // division and exactly zero gradient at r = 0.
  Real derivative_over_r(Real r) const {
    const Real q = r * inverse_h_;
    const Real outer = derivative_scale_ * outer_derivative(r, q) / r;
    const Real inner = gradient_scale_ * inner_derivative_over_q(q);
    return r >= support_radius_ ? Real(0) : q >= 1 ? outer : inner;
  }

  Vector<D> gradient(const Vector<D>& x_ij, Real r) const {
    if (r >= support_radius_) return Vector<D>::Zero();  // also for an infinite x_ij
    return derivative_over_r(r) * x_ij;
  }

 private:
  static constexpr double sigma = D == 2 ? 7.0 / (478.0 * std::numbers::pi) : 1.0 / (120.0 * std::numbers::pi);

  static Real pow4(Real x) {
    const Real x2 = x * x;
    return x2 * x2;
  }
  static Real pow5(Real x) { return pow4(x) * x; }

  // 3 − q taken from the distance to the support edge, so it stays positive inside the support.
  Real outer_distance(Real r) const { return (support_radius_ - r) * inverse_h_; }

  // (1/q) dW/dq on 0 ≤ q < 1, expanded: the three quartics cancel to −120 + 120q² − 50q³.
  static Real inner_derivative_over_q(Real q) { return -120 + q * q * (120 - 50 * q); }

  // dW/dq on 1 ≤ q < 3.
  Real outer_derivative(Real r, Real q) const {
    const Real outer = -5 * pow4(outer_distance(r));
    return q >= 2 ? outer : outer + 30 * pow4(2 - q);
  }

  Real smoothing_length_;
  Real support_radius_;
  Real inverse_h_;
  Real value_scale_;       // σ / h^D
  Real derivative_scale_;  // σ / h^(D+1)
  Real gradient_scale_;    // σ / h^(D+2)
};

}  // namespace tide
