#include "kernel_row.hpp"

#include <algorithm>
#include <cstddef>

#if defined(__x86_64__) && (defined(__GNUC__) || defined(__clang__))
#include <immintrin.h>
#define TIDE_KERNEL_ROW_AVX2 1
#endif

namespace tide::surface {
namespace {

/// KernelTable::operator() on `count` points, written out so the table's fields stay in registers
/// (the row's stores could alias them).
void add_row_scalar(const KernelTable& table, double* row, const double* along_squared, int first, int count,
                    double row_squared) {
  const double steps_per_unit = table.steps_per_unit(), last_step = table.last_step();
  const double* values = table.values();
  for (int i = first; i < count; ++i) {
    const double step = std::min((row_squared + along_squared[i]) * steps_per_unit, last_step);
    const auto k = static_cast<int>(step);
    const double low = values[k];
    row[i] += low + (step - static_cast<double>(k)) * (values[k + 1] - low);
  }
}

#ifdef TIDE_KERNEL_ROW_AVX2
// The scalar loop four points at a time: _mm256_min_pd(a, b) is a < b ? a : b as std::min(a, b)
// is for numbers, the conversions truncate as static_cast<int> does, and multiply and add stay
// separate, so every point gets the scalar loop's bits.
__attribute__((target("avx2"))) void add_row_avx2(const KernelTable& table, double* row, const double* along_squared,
                                                  int count, double row_squared) {
  const __m256d steps_per_unit = _mm256_set1_pd(table.steps_per_unit());
  const __m256d last_step = _mm256_set1_pd(table.last_step());
  const __m256d base = _mm256_set1_pd(row_squared);
  const double* values = table.values();
  // The masked gather with every lane on: the unmasked one leaves GCC 12 warning of its
  // undefined source operand.
  const __m256d zero = _mm256_setzero_pd();
  const __m256d every_lane = _mm256_castsi256_pd(_mm256_set1_epi64x(-1));
  int i = 0;
  for (; i + 4 <= count; i += 4) {
    const __m256d step = _mm256_min_pd(
        _mm256_mul_pd(_mm256_add_pd(base, _mm256_loadu_pd(along_squared + i)), steps_per_unit), last_step);
    const __m128i k = _mm256_cvttpd_epi32(step);
    const __m256d low = _mm256_mask_i32gather_pd(zero, values, k, every_lane, 8);
    const __m256d high = _mm256_mask_i32gather_pd(zero, values + 1, k, every_lane, 8);
    const __m256d fraction = _mm256_sub_pd(step, _mm256_cvtepi32_pd(k));
    const __m256d value = _mm256_add_pd(low, _mm256_mul_pd(fraction, _mm256_sub_pd(high, low)));
    _mm256_storeu_pd(row + i, _mm256_add_pd(_mm256_loadu_pd(row + i), value));
  }
  add_row_scalar(table, row, along_squared, i, count, row_squared);
}

bool has_avx2() {
  static const bool avx2 = __builtin_cpu_supports("avx2");
  return avx2;
}
#endif

}  // namespace

void add_kernel_row(const KernelTable& table, double* row, const double* along_squared, int count, double row_squared) {
#ifdef TIDE_KERNEL_ROW_AVX2
  if (has_avx2()) {
    add_row_avx2(table, row, along_squared, count, row_squared);
    return;
  }
#endif
  add_row_scalar(table, row, along_squared, 0, count, row_squared);
}

}  // namespace tide::surface
