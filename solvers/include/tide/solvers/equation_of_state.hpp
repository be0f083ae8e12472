#pragma once

#include <algorithm>
#include <cmath>

#include "tide/core/scene.hpp"
#include "tide/core/types.hpp"

namespace tide {

/// Weakly compressible equation of state p(ρ) and its inverse.
/// Tait (Monaghan 1994; Batchelor): p = B((ρ/ρ0)^γ − 1) with B = ρ0 c0² / γ.
/// Linear: p = c0² (ρ − ρ0).
/// Both have sound speed c0 at rest density, so c0 = 10 v_max keeps |ρ/ρ0 − 1| ≈ 1%.
/// An optional background pressure p_b is added to either (Morris, Fox & Zhu 1997; Adami, Hu &
/// Adams 2013): closed and periodic flows then keep p > 0, away from the tensile instability.
class EquationOfState {
 public:
  EquationOfState(scene::EquationOfState kind, Real rest_density, Real sound_speed, Real exponent,
                  Real background_pressure = 0)
      : tait_(kind == scene::EquationOfState::tait),
        rest_density_(rest_density),
        sound_speed_(sound_speed),
        exponent_(exponent),
        background_pressure_(background_pressure),
        stiffness_(tait_ ? rest_density * sound_speed * sound_speed / exponent : sound_speed * sound_speed),
        integer_exponent_(
            exponent == std::floor(exponent) && exponent >= 1 && exponent <= 16 ? static_cast<int>(exponent) : 0) {}

  Real pressure(Real density) const {
    if (tait_) return stiffness_ * (power(density / rest_density_) - Real(1)) + background_pressure_;
    return stiffness_ * (density - rest_density_) + background_pressure_;
  }

  Real density(Real pressure) const {
    const Real excess = pressure - background_pressure_;
    if (tait_) return rest_density_ * std::pow(std::max(excess / stiffness_ + Real(1), Real(0)), Real(1) / exponent_);
    return rest_density_ + excess / stiffness_;
  }

  Real rest_density() const { return rest_density_; }
  Real sound_speed() const { return sound_speed_; }

 private:
  // (ρ/ρ0)^γ by repeated squaring for the usual integer γ (7), which is several times cheaper
  // than std::pow and runs once per particle per step.
  Real power(Real ratio) const {
    if (integer_exponent_ == 0) return std::pow(ratio, exponent_);
    Real result = 1;
    Real base = ratio;
    for (int n = integer_exponent_; n > 0; n >>= 1) {
      if (n & 1) result *= base;
      base *= base;
    }
    return result;
  }

  bool tait_;
  Real rest_density_;
  Real sound_speed_;
  Real exponent_;
  Real background_pressure_;
  Real stiffness_;
  int integer_exponent_;  // γ when it is a whole number in [1, 16], else 0
};

}  // namespace tide
