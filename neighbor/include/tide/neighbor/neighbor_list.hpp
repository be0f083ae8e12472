#pragma once

#include <algorithm>
#include <bit>
#include <cstddef>
#include <cstdint>
#include <span>
#include <string>
#include <vector>

#include "tide/core/memory_usage.hpp"
#include "tide/core/particle_set.hpp"
#include "tide/core/scratch_arena.hpp"
#include "tide/core/types.hpp"
#include "tide/neighbor/neighbor_grid.hpp"

namespace tide {

/// The neighbours of every query particle, found once per step and walked by every pass (and
/// every sweep of a pressure solve) until the particles move again: a Verlet list without a skin
/// (Verlet 1967), so it is exact and the passes see the same neighbours in the same order as the
/// cell walk of CrossNeighbors, which keeps the sums bitwise identical.
///
/// Compact: instead of 4-byte indices (CSR, as in Cabana), each particle keeps one bit per
/// candidate of its cell's merged ranges, set when the candidate lies inside the support. All
/// particles of a cell share its candidates, so their bit strings follow each other without
/// padding and one offset per cell locates every particle's bits. In 3D with cells of one
/// support radius a particle has ~216 candidates for ~29 neighbours: 27 bytes per particle
/// (32 if each string were rounded up to whole words) against 116 for an index list.
template <int D>
class NeighborList {
 public:
  /// Marks, for every particle of `queries` (positions `query_x`), which candidates of `table`
  /// (built from `queries` to a source grid whose positions are `source_x`) are neighbours.
  /// `queries` and `table` must outlive the list and stay unchanged until the next build.
  void build(const NeighborGrid<D>& queries, const ConstVectorView<D>& query_x, const CrossNeighbors<D>& table,
             const ConstVectorView<D>& source_x);

  /// The same with the bits in `arena` (one phase of it) instead of the list's own array: the list
  /// is valid until the arena's next reset.
  void build(const NeighborGrid<D>& queries, const ConstVectorView<D>& query_x, const CrossNeighbors<D>& table,
             const ConstVectorView<D>& source_x, ScratchArena& arena);

  /// Calls f(j, x_ij, r2) for every source neighbour j of query particle i, in the order of
  /// CrossNeighbors::for_each_in_cell, with the same x_ij = x_i − x_j (minimum image) and r2.
  /// The positions must be those of the last build.
  template <class F>
  void for_each(std::size_t i, const ConstVectorView<D>& query_x, const ConstVectorView<D>& source_x, F&& f) const {
    const std::uint32_t cell = queries_->particle_cell_[i];
    const std::uint64_t* bits = bits_.data() + cell_first_word_[cell];
    const Vector<D> x = query_x[i];
    // Bit of the current range's first candidate in the cell's string.
    std::uint64_t position = std::uint64_t(i - queries_->cell_start_[cell]) * cell_candidates_[cell];
    for (std::uint32_t r = table_->range_offset_[cell]; r < table_->range_offset_[cell + 1]; ++r) {
      const CellRange range = table_->range(r);
      const Vector<D> x_image = x - table_->shifts_[range.shift];
      const Index length = range.end - range.begin;
      for (Index first = 0; first < length; first += 64) {
        std::uint64_t word = extract(bits, position + first, std::min<Index>(64, length - first));
        while (word != 0) {
          const Index j = range.begin + first + static_cast<Index>(std::countr_zero(word));
          word &= word - 1;
          Vector<D> xij;
          for (int d = 0; d < D; ++d) xij[d] = x_image[d] - source_x.component[d][j];
          f(j, xij, squared_norm<D>(xij));
        }
      }
      position += length;
    }
  }

  /// Bytes the list holds (bits in an arena are the arena's).
  std::size_t bytes() const {
    return held_bytes(own_bits_) + held_bytes(cell_first_word_) + held_bytes(cell_candidates_);
  }

  /// Adds "<owner>.bits" (the list's own, 0 in an arena) and "<owner>.cell offsets" (first word and
  /// candidates of each cell).
  void add_memory(MemoryUsage& usage, const std::string& owner) const {
    usage.add(owner + ".bits", own_bits_);
    usage.add(owner + ".cell offsets", held_bytes(cell_first_word_) + held_bytes(cell_candidates_));
  }

 private:
  // `count` (1..64) bits of the particle's bit string from bit `position` on.
  static std::uint64_t extract(const std::uint64_t* bits, std::uint64_t position, Index count) {
    const std::uint64_t word = position >> 6;
    const unsigned offset = static_cast<unsigned>(position & 63);
    std::uint64_t value = bits[word] >> offset;
    // The bits continue in the next word only when they are still this particle's.
    if (offset != 0 && offset + count > 64) value |= bits[word + 1] << (64 - offset);
    return count == 64 ? value : value & ((std::uint64_t(1) << count) - 1);
  }

  // Candidates and first word of each cell; returns the words of the whole list.
  std::size_t index_cells(const NeighborGrid<D>& queries, const CrossNeighbors<D>& table);
  // Sets the bits of bits_ (sized by index_cells).
  void fill(const NeighborGrid<D>& queries, const ConstVectorView<D>& query_x, const CrossNeighbors<D>& table,
            const ConstVectorView<D>& source_x);

  const NeighborGrid<D>* queries_ = nullptr;
  const CrossNeighbors<D>* table_ = nullptr;
  std::vector<std::uint32_t> cell_first_word_;  // query cell c: the first word of its bit string
  std::vector<std::uint32_t> cell_candidates_;  // query cell c: candidates, i.e. bits per particle
  std::vector<std::uint64_t> own_bits_;
  std::span<std::uint64_t> bits_;  // own_bits_, or a span of an arena
};

extern template class NeighborList<2>;
extern template class NeighborList<3>;

}  // namespace tide
