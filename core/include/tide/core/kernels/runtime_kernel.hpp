#pragma once

#include <cmath>
#include <type_traits>
#include <variant>

#include "tide/core/kernels/kernel.hpp"
#include "tide/core/types.hpp"

namespace tide {

/// The scene's kernel, chosen at run time, for the passes: they are compiled once against this
/// class rather than once per kernel (a scheme's passes instantiated for each of the seven kernels
/// made its file take about four times as long to compile). One pair's value or gradient is a
/// switch on the kernel, which a pair loop predicts every time; a hot pair loop is instantiated
/// per kernel by visit() around it alone (or, for its gradients, by with_gradients in
/// neighbor_run.hpp), and a run's values can be taken in one call that loops over the concrete
/// kernel (values). Every number is the concrete kernel's own, bit for bit.
template <int D>
class RuntimeKernel {
 public:
  static constexpr int dimension = D;

  /// From AnyKernel<D> or one of its alternatives; implicit, as the passes take any kernel so.
  template <class Kernel>
  requires std::is_constructible_v < AnyKernel<D>,
  const Kernel& > RuntimeKernel(const Kernel& kernel)  // NOLINT(google-explicit-constructor)
      : kernel_(kernel),
  smoothing_length_(visit([](const auto& k) { return k.smoothing_length(); })),
  support_radius_(visit([](const auto& k) { return k.support_radius(); })) {}

  const AnyKernel<D>& any() const { return kernel_; }
  Real smoothing_length() const { return smoothing_length_; }
  Real support_radius() const { return support_radius_; }

  Real value(Real r) const {
    return visit([r](const auto& k) { return k.value(r); });
  }
  Real derivative_over_r(Real r) const {
    return visit([r](const auto& k) { return k.derivative_over_r(r); });
  }
  Vector<D> gradient(const Vector<D>& x_ij, Real r) const {
    return visit([&](const auto& k) { return k.gradient(x_ij, r); });
  }

  /// w[k] = W(√r2[k]) for k < count.
  void values(const Real* r2, int count, Real* w) const {
    visit([&](const auto& kernel) {
      for (int k = 0; k < count; ++k) w[k] = kernel.value(std::sqrt(r2[k]));
    });
  }

  /// f(concrete kernel).
  template <class F>
  decltype(auto) visit(F&& f) const {
    static_assert(std::variant_size_v<AnyKernel<D>> == 7, "one case per KernelType");
    switch (kernel_.index()) {
      case 0:
        return f(*std::get_if<0>(&kernel_));
      case 1:
        return f(*std::get_if<1>(&kernel_));
      case 2:
        return f(*std::get_if<2>(&kernel_));
      case 3:
        return f(*std::get_if<3>(&kernel_));
      case 4:
        return f(*std::get_if<4>(&kernel_));
      case 5:
        return f(*std::get_if<5>(&kernel_));
      default:
        return f(*std::get_if<6>(&kernel_));
    }
  }

 private:
  AnyKernel<D> kernel_;
  Real smoothing_length_;
  Real support_radius_;
};

extern template class RuntimeKernel<2>;
extern template class RuntimeKernel<3>;

}  // namespace tide
