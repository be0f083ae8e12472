#include "tide/neighbor/neighbor_list.hpp"

#include <array>
#include <limits>
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

}  // namespace

template <int D>
void NeighborList<D>::build(const NeighborGrid<D>& queries, const ConstVectorView<D>& query_x,
                            const CrossNeighbors<D>& table, const ConstVectorView<D>& source_x) {
  const std::size_t words = index_cells(queries, table);
  own_bits_.resize(words);
  bits_ = own_bits_;
  fill(queries, query_x, table, source_x);
}

template <int D>
void NeighborList<D>::build(const NeighborGrid<D>& queries, const ConstVectorView<D>& query_x,
                            const CrossNeighbors<D>& table, const ConstVectorView<D>& source_x, ScratchArena& arena) {
  const std::size_t words = index_cells(queries, table);
  release_memory(own_bits_);
  arena.reset(ScratchArena::aligned(words * sizeof(std::uint64_t)));
  bits_ = arena.take<std::uint64_t>(words);
  fill(queries, query_x, table, source_x);
}

template <int D>
std::size_t NeighborList<D>::index_cells(const NeighborGrid<D>& queries, const CrossNeighbors<D>& table) {
  queries_ = &queries;
  table_ = &table;
  const std::size_t cells = queries.occupied_cells();
  cell_candidates_.resize(cells);
  cell_first_word_.resize(cells + 1);
  for_each_particle(cells, [&](std::size_t c) {
    std::uint32_t candidates = 0;
    for (std::uint32_t r = table.range_offset_[c]; r < table.range_offset_[c + 1]; ++r)
      candidates += table.runs_[r].end - table.runs_[r].begin;
    cell_candidates_[c] = candidates;
  });
  // 32-bit word offsets address 32 GiB of bits, far more than a machine that holds the
  // particles can spare; a list beyond is refused rather than wrapped.
  std::uint64_t words = 0;
  for (std::size_t c = 0; c < cells; ++c) {
    cell_first_word_[c] = static_cast<std::uint32_t>(words);
    const std::uint64_t particles = queries.cell_start_[c + 1] - queries.cell_start_[c];
    words += (particles * cell_candidates_[c] + 63) / 64;
    if (words > std::numeric_limits<std::uint32_t>::max())
      throw std::length_error("neighbour list: more than 2^32 words of neighbour bits");
  }
  cell_first_word_[cells] = static_cast<std::uint32_t>(words);
  return words;
}

template <int D>
void NeighborList<D>::fill(const NeighborGrid<D>& queries, const ConstVectorView<D>& query_x,
                           const CrossNeighbors<D>& table, const ConstVectorView<D>& source_x) {
  const Real support_squared = table.support_squared_;
  // One cell per task: its particles' bit strings follow each other without padding, so a word
  // can hold the end of one and the start of the next, and only the cell's task writes it.
  for_each_particle(queries.occupied_cells(), [&](std::size_t cell) {
    std::uint64_t* out = bits_.data() + cell_first_word_[cell];
    std::uint64_t word = 0;
    std::uint64_t position = 0;  // bit of the cell's string being written
    for (Index i = queries.cell_start_[cell]; i < queries.cell_start_[cell + 1]; ++i) {
      const Vector<D> x = query_x[i];
      // Blocks of up to 64 candidates, one bit each, in a loop the compiler vectorises over the
      // SoA positions (a compare and an OR reduction, no branch: most candidates fail the test,
      // unpredictably).
      for (std::uint32_t r = table.range_offset_[cell]; r < table.range_offset_[cell + 1]; ++r) {
        const CellRange range = table.range(r);
        const Vector<D> x_image = x - table.shifts_[range.shift];
        for (Index first = range.begin; first < range.end; first += 64) {
          const Index count = std::min<Index>(64, range.end - first);
          std::array<const Real*, D> source;
          for (int d = 0; d < D; ++d) source[d] = source_x.component[d] + first;
          std::uint64_t mask = 0;
          for (Index k = 0; k < count; ++k) {
            Vector<D> xij;
            for (int d = 0; d < D; ++d) xij[d] = x_image[d] - source[d][k];
            mask |= squared_norm<D>(xij) < support_squared ? bit[k] : 0;
          }
          const unsigned offset = static_cast<unsigned>(position & 63);
          word |= mask << offset;
          if (offset + count >= 64) {
            out[position >> 6] = word;
            word = offset == 0 ? 0 : mask >> (64 - offset);
          }
          position += count;
        }
      }
    }
    if ((position & 63) != 0) out[position >> 6] = word;
  });
}

template class NeighborList<2>;
template class NeighborList<3>;

}  // namespace tide
