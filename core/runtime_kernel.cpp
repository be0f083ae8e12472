#include "tide/core/kernels/runtime_kernel.hpp"

#include <cmath>

namespace tide {

template <int D>
void RuntimeKernel<D>::values(const Real* r2, int count, Real* w) const {
  visit([&](const auto& kernel) {
    for (int k = 0; k < count; ++k) w[k] = kernel.value(std::sqrt(r2[k]));
  });
}

template <int D>
void RuntimeKernel<D>::derivatives_over_r(const Real* r2, int count, Real* f) const {
  visit([&](const auto& kernel) {
    for (int k = 0; k < count; ++k) f[k] = kernel.derivative_over_r(std::sqrt(r2[k]));
  });
}

template class RuntimeKernel<2>;
template class RuntimeKernel<3>;

}  // namespace tide
