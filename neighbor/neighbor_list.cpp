#include "tide/neighbor/neighbor_list.hpp"

#include <algorithm>
#include <array>
#include <atomic>
#include <bit>
#include <cstring>
#include <stdexcept>

#include "tide/core/parallel.hpp"

namespace tide {

namespace {

// bit[k] = 2^k, loaded rather than shifted so that the candidate loop vectorises.
constexpr std::array<std::uint64_t, 64> bit = [] {
  std::array<std::uint64_t, 64> powers{};
  for (int k = 0; k < 64; ++k) powers[k] = std::uint64_t(1) << k;
  return powers;
}();

// The number of set bits of x, inline: without -mpopcnt (the default x86-64 target) std::popcount
// is a call into libgcc, which perf showed at 1-1.3% of a 3D DFSPH step (Anderson's "Bit
// Twiddling Hacks", counting bits in parallel).
constexpr int set_bit_count(std::uint64_t x) {
  x -= (x >> 1) & 0x5555555555555555u;
  x = (x & 0x3333333333333333u) + ((x >> 2) & 0x3333333333333333u);
  x = (x + (x >> 4)) & 0x0f0f0f0f0f0f0f0fu;
  return static_cast<int>((x * 0x0101010101010101u) >> 56);
}
static_assert(set_bit_count(0) == 0 && set_bit_count(~std::uint64_t(0)) == 64 &&
              set_bit_count(0x8000000000000101u) == 3);

// Appends entry(k) for every set bit k of `mask`, in order, to `out`, eight per round whatever
// the count, the surplus overwritten by what follows: a mask rarely holds more than eight
// neighbours, so the loop ends where the predictor expects, where a loop over the set bits would
// not. A round past the last set bit calls entry(64).
template <class Array, class Entry>
void append_set_bits(std::uint64_t mask, Array& out, Entry&& entry) {
  out.reserve_more(64);
  std::uint32_t* const at = out.data.get() + out.size;
  const int set = set_bit_count(mask);
  for (int written = 0; written < set; written += 8) {
    for (int k = 0; k < 8; ++k) {
      at[written + k] = entry(std::countr_zero(mask));
      mask &= mask - 1;
    }
  }
  out.size += static_cast<std::size_t>(set);
}

}  // namespace

template <int D>
void NeighborList<D>::IndexArray::reserve_more(std::size_t more) {
  if (size + more <= capacity) return;
  // By a quarter, not double: a block keeps its array from build to build, so the copies are
  // paid in the first builds only, while a doubling's slack (up to half the array) stays for the
  // whole run and was the largest single item of the step's memory.
  const std::size_t grown = std::max(capacity + capacity / 4, size + more);
  auto larger = std::make_unique_for_overwrite<std::uint32_t[]>(grown);
  if (size > 0) std::memcpy(larger.get(), data.get(), size * sizeof(std::uint32_t));
  data = std::move(larger);
  capacity = grown;
}

template <int D>
void NeighborList<D>::build(const NeighborGrid<D>& queries, const ConstVectorView<D>& query_x,
                            const CrossNeighbors<D>& table, const ConstVectorView<D>& source_x) {
  queries_ = &queries;
  table_ = &table;
  gradients_cached_ = false;
  const std::size_t cells = queries.occupied_cells();
  span_.resize(queries.particle_count());
  const std::size_t blocks = (cells + cells_per_block - 1) / cells_per_block;
  blocks_.resize(blocks);
  std::atomic<bool> beyond_index_bits = false;
  // One task per block (a block is ~500 particles in 3D; for_each_particle's grain of 256 items
  // would leave a scene of fewer than 256 blocks to one thread).
  parallel_blocks(blocks, 1, [&](std::size_t first_block, std::size_t last_block) {
    for (std::size_t block = first_block; block < last_block; ++block) {
      const std::size_t first_cell = block * cells_per_block;
      const std::size_t last_cell = std::min(cells, first_cell + cells_per_block);
      for (std::size_t c = first_cell; c < last_cell; ++c)
        for (std::uint32_t r = table.range_offset_[c]; r < table.range_offset_[c + 1]; ++r)
          if (table.runs_[r].end > index_mask + Index(1)) beyond_index_bits = true;
      if (!beyond_index_bits) fill_block(first_cell, last_cell, query_x, source_x, blocks_[block]);
    }
  });
  if (beyond_index_bits) throw std::length_error("neighbour list: more than 2^27 source particles");
}

template <int D>
void NeighborList<D>::fill_block(std::size_t first_cell, std::size_t last_cell, const ConstVectorView<D>& query_x,
                                 const ConstVectorView<D>& source_x, IndexArray& out) {
  const NeighborGrid<D>& queries = *queries_;
  const CrossNeighbors<D>& table = *table_;
  const Real list_radius_squared = table.list_radius_squared_;
  const bool periodic = table.periodic();
  out.size = 0;
  for (std::size_t cell = first_cell; cell < last_cell; ++cell) {
    for (Index i = queries.cell_start_[cell]; i < queries.cell_start_[cell + 1]; ++i) {
      const Vector<D> x = query_x[i];
      const std::size_t first_entry = out.size;
      for (std::uint32_t r = table.range_offset_[cell]; r < table.range_offset_[cell + 1]; ++r) {
        const CellRange range = table.range(r);
        const Vector<D> x_image = x - table.shifts_[range.shift];
        const std::uint32_t shift = periodic ? std::uint32_t(range.shift) << index_bits : 0;
        for (Index first = range.begin; first < range.end; first += 64) {
          // Up to 64 candidates in a loop the compiler vectorises over the SoA positions (most
          // fail the test, unpredictably): with AVX-512 their r² and entries, compacted as a
          // refinement does (keep_inside); otherwise one bit each, the mask then decoded.
          const Index count = std::min<Index>(64, range.end - first);
          std::array<const Real*, D> source;
          for (int d = 0; d < D; ++d) source[d] = source_x.component[d] + first;
          const auto squared_distance = [&](Index k) {
            Vector<D> xij;
            for (int d = 0; d < D; ++d) xij[d] = x_image[d] - source[d][k];
            return squared_norm<D>(xij);
          };
          const std::uint32_t base = shift | first;
          if constexpr (keep_inside_is_vectorised) {
            std::array<Real, 64> r2;
            std::array<std::uint32_t, 64> entry;
            for (Index k = 0; k < count; ++k) {
              r2[k] = squared_distance(k);
              entry[k] = base + k;
            }
            out.reserve_more(64);
            out.size += keep_inside<false>(entry.data(), r2.data(), static_cast<int>(count), list_radius_squared,
                                           out.data.get() + out.size, nullptr);
          } else {
            std::uint64_t mask = 0;
            for (Index k = 0; k < count; ++k) mask |= squared_distance(k) < list_radius_squared ? bit[k] : 0;
            append_set_bits(mask, out, [&](int k) { return base + static_cast<std::uint32_t>(k); });
          }
        }
      }
      span_[i] = {static_cast<std::uint32_t>(first_entry), static_cast<std::uint32_t>(out.size - first_entry)};
    }
  }
}

template <int D>
std::size_t NeighborList<D>::bytes() const {
  MemoryUsage usage;
  add_memory(usage, "");
  return usage.total();
}

template <int D>
void NeighborList<D>::add_memory(MemoryUsage& usage, const std::string& owner) const {
  std::size_t indices = held_bytes(blocks_);
  for (const IndexArray& block : blocks_) indices += block.capacity * sizeof(std::uint32_t);
  usage.add(owner + ".indices", indices);
  usage.add(owner + ".spans", held_bytes(span_));
  if (gradients_.empty()) return;
  std::size_t gradients = held_bytes(gradients_);
  for (const std::vector<Real>& block : gradients_) gradients += held_bytes(block);
  usage.add(owner + ".gradients", gradients);
}

template class NeighborList<2>;
template class NeighborList<3>;

}  // namespace tide
