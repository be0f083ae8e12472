#pragma once

// The compaction at the heart of a neighbour list's refinement: of up to 64 candidates, keep
// those inside the support, in their order.

#include <bit>
#include <cstddef>
#include <cstdint>
#include <type_traits>

#if defined(__AVX512F__) && defined(__AVX512VL__)
#include <immintrin.h>
#endif

#include "tide/core/types.hpp"

namespace tide {

/// Whether keep_inside() compacts with AVX-512 (a build for a CPU that has AVX-512F and VL).
#if defined(__AVX512F__) && defined(__AVX512VL__)
inline constexpr bool keep_inside_is_vectorised = true;
#else
inline constexpr bool keep_inside_is_vectorised = false;
#endif

/// Writes to `out`, in their order, the entry[k] of the k < count (count ≤ 64) with
/// r2[k] < limit, with `WithR2` their r2[k] to `r2_out` alike, and returns how many it kept.
/// Each output must have room for 64 values: past the kept ones, it may write up to the next
/// multiple of its vector width. With AVX-512, 8 candidates (16 in float) at a time: a masked
/// compare and a compress of entries and r² in registers, then full-width stores (the compress
/// straight to memory is microcoded on AMD Zen 4). Otherwise one at a time: every entry is
/// stored and only the kept ones are counted, a store per candidate and no branch.
template <bool WithR2>
std::size_t keep_inside(const std::uint32_t* entry, const Real* r2, int count, Real limit, std::uint32_t* out,
                        [[maybe_unused]] Real* r2_out) {
  std::size_t kept = 0;
#if defined(__AVX512F__) && defined(__AVX512VL__)
  if constexpr (std::is_same_v<Real, double>) {
    const __m512d bound = _mm512_set1_pd(limit);
    for (int k = 0; k < count; k += 8) {
      const __mmask8 present = count - k >= 8 ? __mmask8(0xFF) : __mmask8((1u << (count - k)) - 1);
      const __m512d r2_k = _mm512_maskz_loadu_pd(present, r2 + k);
      const __mmask8 inside = _mm512_mask_cmp_pd_mask(present, r2_k, bound, _CMP_LT_OQ);
      const __m256i entry_k = _mm256_maskz_loadu_epi32(present, entry + k);
      _mm256_storeu_si256(reinterpret_cast<__m256i*>(out + kept), _mm256_maskz_compress_epi32(inside, entry_k));
      if constexpr (WithR2) _mm512_storeu_pd(r2_out + kept, _mm512_maskz_compress_pd(inside, r2_k));
      kept += static_cast<std::size_t>(std::popcount(static_cast<unsigned>(inside)));
    }
  } else {
    const __m512 bound = _mm512_set1_ps(limit);
    for (int k = 0; k < count; k += 16) {
      const __mmask16 present = count - k >= 16 ? __mmask16(0xFFFF) : __mmask16((1u << (count - k)) - 1);
      const __m512 r2_k = _mm512_maskz_loadu_ps(present, r2 + k);
      const __mmask16 inside = _mm512_mask_cmp_ps_mask(present, r2_k, bound, _CMP_LT_OQ);
      const __m512i entry_k = _mm512_maskz_loadu_epi32(present, entry + k);
      _mm512_storeu_si512(out + kept, _mm512_maskz_compress_epi32(inside, entry_k));
      if constexpr (WithR2) _mm512_storeu_ps(r2_out + kept, _mm512_maskz_compress_ps(inside, r2_k));
      kept += static_cast<std::size_t>(std::popcount(static_cast<unsigned>(inside)));
    }
  }
#else
  for (int k = 0; k < count; ++k) {
    out[kept] = entry[k];
    if constexpr (WithR2) r2_out[kept] = r2[k];
    kept += r2[k] < limit ? 1 : 0;
  }
#endif
  return kept;
}

}  // namespace tide
