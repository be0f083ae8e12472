#pragma once

#include <array>
#include <cstdint>

namespace tide {

/// Bits per axis a Morton code holds: 32 in 2D, 21 in 3D (so the code fits 64 bits).
template <int D>
inline constexpr int morton_bits_per_axis = D == 2 ? 32 : 21;

namespace detail {

// Spreads the low 32 bits of v so that bit k moves to bit 2k.
constexpr std::uint64_t spread_by_one(std::uint64_t v) {
  v &= 0xffffffffULL;
  v = (v | (v << 16)) & 0x0000ffff0000ffffULL;
  v = (v | (v << 8)) & 0x00ff00ff00ff00ffULL;
  v = (v | (v << 4)) & 0x0f0f0f0f0f0f0f0fULL;
  v = (v | (v << 2)) & 0x3333333333333333ULL;
  v = (v | (v << 1)) & 0x5555555555555555ULL;
  return v;
}

// Spreads the low 21 bits of v so that bit k moves to bit 3k.
constexpr std::uint64_t spread_by_two(std::uint64_t v) {
  v &= 0x1fffffULL;
  v = (v | (v << 32)) & 0x001f00000000ffffULL;
  v = (v | (v << 16)) & 0x001f0000ff0000ffULL;
  v = (v | (v << 8)) & 0x100f00f00f00f00fULL;
  v = (v | (v << 4)) & 0x10c30c30c30c30c3ULL;
  v = (v | (v << 2)) & 0x1249249249249249ULL;
  return v;
}

// Inverse of spread_by_one: gathers every second bit into the low 32 bits.
constexpr std::uint64_t compact_by_one(std::uint64_t v) {
  v &= 0x5555555555555555ULL;
  v = (v | (v >> 1)) & 0x3333333333333333ULL;
  v = (v | (v >> 2)) & 0x0f0f0f0f0f0f0f0fULL;
  v = (v | (v >> 4)) & 0x00ff00ff00ff00ffULL;
  v = (v | (v >> 8)) & 0x0000ffff0000ffffULL;
  v = (v | (v >> 16)) & 0x00000000ffffffffULL;
  return v;
}

// Inverse of spread_by_two: gathers every third bit into the low 21 bits.
constexpr std::uint64_t compact_by_two(std::uint64_t v) {
  v &= 0x1249249249249249ULL;
  v = (v | (v >> 2)) & 0x10c30c30c30c30c3ULL;
  v = (v | (v >> 4)) & 0x100f00f00f00f00fULL;
  v = (v | (v >> 8)) & 0x001f0000ff0000ffULL;
  v = (v | (v >> 16)) & 0x001f00000000ffffULL;
  v = (v | (v >> 32)) & 0x00000000001fffffULL;
  return v;
}

}  // namespace detail

/// Z-order (Morton) code of a cell: the bits of the cell coordinates interleaved, x lowest.
/// Cells close in space get close codes, so sorting by code keeps neighbours close in memory.
template <int D>
constexpr std::uint64_t morton_code(const std::array<std::uint32_t, D>& cell) {
  if constexpr (D == 2) {
    return detail::spread_by_one(cell[0]) | (detail::spread_by_one(cell[1]) << 1);
  } else {
    return detail::spread_by_two(cell[0]) | (detail::spread_by_two(cell[1]) << 1) |
           (detail::spread_by_two(cell[2]) << 2);
  }
}

}  // namespace tide

namespace tide {

/// Cell coordinates of a Morton code (inverse of morton_code).
template <int D>
constexpr std::array<std::uint32_t, D> morton_decode(std::uint64_t code) {
  std::array<std::uint32_t, D> cell{};
  for (int d = 0; d < D; ++d) {
    cell[d] =
        static_cast<std::uint32_t>(D == 2 ? detail::compact_by_one(code >> d) : detail::compact_by_two(code >> d));
  }
  return cell;
}

}  // namespace tide
