#include "tide/core/kernels/runtime_kernel.hpp"

namespace tide {

template class RuntimeKernel<2>;
template class RuntimeKernel<3>;

}  // namespace tide
