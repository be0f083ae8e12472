#pragma once

#include <array>
#include <optional>
#include <stdexcept>
#include <string_view>
#include <variant>

#include "tide/core/kernels/cubic_spline.hpp"
#include "tide/core/kernels/muller_kernels.hpp"
#include "tide/core/kernels/quintic_spline.hpp"
#include "tide/core/kernels/wendland_c2.hpp"
#include "tide/core/kernels/wendland_c4.hpp"
#include "tide/core/types.hpp"

namespace tide {

/// The smoothing kernels a scene can name. Scene files spell them exactly as the enumerators.
enum class KernelType { cubic_spline, wendland_c2, wendland_c4, quintic_spline, poly6, spiky, viscosity };

inline constexpr std::array<KernelType, 7> all_kernel_types{
    KernelType::cubic_spline, KernelType::wendland_c2, KernelType::wendland_c4, KernelType::quintic_spline,
    KernelType::poly6,        KernelType::spiky,       KernelType::viscosity};

constexpr std::string_view kernel_name(KernelType type) {
  switch (type) {
    case KernelType::cubic_spline:
      return "cubic_spline";
    case KernelType::wendland_c2:
      return "wendland_c2";
    case KernelType::wendland_c4:
      return "wendland_c4";
    case KernelType::quintic_spline:
      return "quintic_spline";
    case KernelType::poly6:
      return "poly6";
    case KernelType::spiky:
      return "spiky";
    case KernelType::viscosity:
      return "viscosity";
  }
  throw std::invalid_argument("kernel_name: not a KernelType value");
}

/// The kernel called `name` (exact, case-sensitive), or nothing if there is none.
constexpr std::optional<KernelType> kernel_from_name(std::string_view name) {
  for (const KernelType type : all_kernel_types) {
    if (kernel_name(type) == name) return type;
  }
  return std::nullopt;
}

/// Support radius / smoothing length: what a neighbour grid needs before any kernel exists.
constexpr Real kernel_support_factor(KernelType type) {
  switch (type) {
    case KernelType::cubic_spline:
      return CubicSplineKernel<3>::support_factor;
    case KernelType::wendland_c2:
      return WendlandC2Kernel<3>::support_factor;
    case KernelType::wendland_c4:
      return WendlandC4Kernel<3>::support_factor;
    case KernelType::quintic_spline:
      return QuinticSplineKernel<3>::support_factor;
    case KernelType::poly6:
      return Poly6Kernel<3>::support_factor;
    case KernelType::spiky:
      return SpikyKernel<3>::support_factor;
    case KernelType::viscosity:
      return ViscosityKernel<3>::support_factor;
  }
  throw std::invalid_argument("kernel_support_factor: not a KernelType value");
}

/// Any kernel, chosen at run time: the scene set-up visits it for one-off sums; the passes take it
/// wrapped in RuntimeKernel (runtime_kernel.hpp), which evaluates whole runs of pairs per call.
/// The alternatives are in KernelType order: index() == static_cast<std::size_t>(type).
template <int D>
using AnyKernel = std::variant<CubicSplineKernel<D>, WendlandC2Kernel<D>, WendlandC4Kernel<D>, QuinticSplineKernel<D>,
                               Poly6Kernel<D>, SpikyKernel<D>, ViscosityKernel<D>>;

/// The kernel of `type` with smoothing length h; throws std::invalid_argument for a bad h.
template <int D>
AnyKernel<D> make_kernel(KernelType type, Real h) {
  switch (type) {
    case KernelType::cubic_spline:
      return CubicSplineKernel<D>(h);
    case KernelType::wendland_c2:
      return WendlandC2Kernel<D>(h);
    case KernelType::wendland_c4:
      return WendlandC4Kernel<D>(h);
    case KernelType::quintic_spline:
      return QuinticSplineKernel<D>(h);
    case KernelType::poly6:
      return Poly6Kernel<D>(h);
    case KernelType::spiky:
      return SpikyKernel<D>(h);
    case KernelType::viscosity:
      return ViscosityKernel<D>(h);
  }
  throw std::invalid_argument("make_kernel: not a KernelType value");
}

}  // namespace tide
