#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <memory>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

#include "tide/core/memory_usage.hpp"
#include "tide/core/parallel.hpp"
#include "tide/core/particle_set.hpp"
#include "tide/core/types.hpp"
#include "tide/neighbor/keep_inside.hpp"
#include "tide/neighbor/neighbor_grid.hpp"
#include "tide/neighbor/neighbor_run.hpp"

namespace tide {

/// The neighbours of every query particle, found once per step and walked by every pass (and
/// every sweep of a pressure solve) until the particles move again (Verlet 1967). Built from a
/// table of grids without a skin, it holds the pairs inside the support in the order of the cell
/// walk of CrossNeighbors, which keeps the sums bitwise identical to that walk's. Built from
/// grids with a skin, it holds the candidates within support + skin, and `refine` then lists
/// those inside the support at the current positions, in the same order, for the passes: the
/// candidates serve until some particle has moved half the skin.
///
/// The candidates of a cell's merged ranges (~216 for ~29 neighbours in 3D with cells of one
/// support radius) are tested 64 at a time in a loop the compiler vectorises (a compare and an
/// OR into a bit mask, no branch), and each mask is decoded at once into 4-byte indices (CSR, as
/// in Cabana); built for AVX-512, the tested candidates are compacted by a compress instead
/// (keep_inside). The indices of a block of cells are written by one task into the block's own
/// array, so no task needs another's counts first. A list of bits per candidate (1 bit per
/// candidate against 32 per neighbour) cost the passes a mispredicted branch per range and word,
/// which kept their pair loops from overlapping and vectorising (docs/performance.md).
template <int D>
class NeighborList {
 public:
  /// Lists, for every particle of `queries` (positions `query_x`), the candidates of `table`
  /// (built from `queries` to a source grid whose positions are `source_x`) inside the support.
  /// `queries` and `table` must outlive the list and stay unchanged until the next build.
  void build(const NeighborGrid<D>& queries, const ConstVectorView<D>& query_x, const CrossNeighbors<D>& table,
             const ConstVectorView<D>& source_x);

  /// Lists the entries of `candidates` (built from grids with a skin) inside the support at the
  /// positions `query_x` and `source_x`, in their order. `candidates` must outlive the list, and
  /// its grids and table stay unchanged until the next refine.
  void refine(const NeighborList& candidates, const ConstVectorView<D>& query_x, const ConstVectorView<D>& source_x) {
    refine(candidates, query_x, source_x, IgnorePairs{});
  }

  /// refine(), handing each query particle's listed pairs, as they are listed, to
  /// visit(i, runs): runs(f) calls f(run) for the NeighborRuns of particle i in the list's order,
  /// with indices and r² (the refinement's own, bitwise those of for_each_run) but no x_ij or
  /// gradients. A pass that needs no more than r² then walks the candidates once for both jobs.
  template <class Visit>
  void refine(const NeighborList& candidates, const ConstVectorView<D>& query_x, const ConstVectorView<D>& source_x,
              Visit&& visit) {
    queries_ = candidates.queries_;
    table_ = candidates.table_;
    gradients_cached_ = false;
    span_.resize(candidates.span_.size());
    blocks_.resize(candidates.blocks_.size());
    parallel_blocks(blocks_.size(), 1, [&](std::size_t first_block, std::size_t last_block) {
      for (std::size_t block = first_block; block < last_block; ++block) {
        if (table_->periodic()) {
          refine_block<true>(candidates, block, query_x, source_x, visit);
        } else {
          refine_block<false>(candidates, block, query_x, source_x, visit);
        }
      }
    });
  }

  /// Keeps ∇W_ij = derivative_over_r(r) x_ij of every listed pair at the positions `query_x` and
  /// `source_x` (those of the last build or refine), computed from the x_ij and r² of
  /// for_each_run, for the runs to hand out as NeighborRun::gradient until the next build or
  /// refine. A pressure solve walks the same pairs in every sweep of a step; this computes their
  /// kernel term once, and a walk that needs only the gradients no longer gathers positions.
  template <class DerivativeOverR>
  void cache_gradients(const ConstVectorView<D>& query_x, const ConstVectorView<D>& source_x,
                       const DerivativeOverR& derivative_over_r) {
    gradients_cached_ = false;
    gradients_.resize(blocks_.size());
    parallel_blocks(blocks_.size(), 1, [&](std::size_t first_block, std::size_t last_block) {
      for (std::size_t block = first_block; block < last_block; ++block) {
        std::vector<Real>& gradients = gradients_[block];
        // D per index at the capacity of the block's indices, which grow by a quarter
        // (IndexArray), rather than by the doubling of a vector's own growth.
        if (gradients.capacity() < D * blocks_[block].capacity) {
          gradients.clear();
          gradients.shrink_to_fit();
          gradients.reserve(D * blocks_[block].capacity);
        }
        gradients.resize(D * blocks_[block].size);
        const auto [first_particle, last_particle] = particles_of_block(block);
        for (Index i = first_particle; i < last_particle; ++i) {
          Real* const particle = gradients.data() + D * span_[i].first;
          const int total = static_cast<int>(span_[i].count);
          int first = 0;
          for_each_run(i, query_x, source_x, [&](const NeighborRun<D>& run) {
            for (int k = 0; k < run.count; ++k) {
              const Real factor = derivative_over_r(std::sqrt(run.r2[k]));
              for (int d = 0; d < D; ++d) particle[d * total + first + k] = factor * run.x_ij[d][k];
            }
            first += run.count;
          });
        }
      }
    });
    gradients_cached_ = true;
  }

  /// Calls f(j, x_ij, r2) for every source neighbour j of query particle i, in the order of
  /// CrossNeighbors::for_each_in_cell, with the same x_ij = x_i − x_j (minimum image) and r2.
  /// The positions must be those of the last build.
  template <class F>
  void for_each(std::size_t i, const ConstVectorView<D>& query_x, const ConstVectorView<D>& source_x, F&& f) const {
    const Vector<D> x = query_x[i];
    const std::uint32_t* entry = entries(i);
    const std::uint32_t* const end = entry + span_[i].count;
    if (!table_->periodic()) {
      for (; entry != end; ++entry) call(*entry, x, source_x, f);
      return;
    }
    for (; entry != end; ++entry) call(*entry & index_mask, x - table_->shifts_[*entry >> index_bits], source_x, f);
  }

  /// Calls f(run) for the neighbours of query particle i in runs of up to NeighborRun::capacity,
  /// in the order of for_each, with the gradients when they are cached. With `Offsets` false and
  /// the gradients cached, the runs hold indices and gradients only (no x_ij, no r²).
  template <bool Offsets = true, class F>
  void for_each_run(std::size_t i, const ConstVectorView<D>& query_x, const ConstVectorView<D>& source_x, F&& f) const {
    const Vector<D> x = query_x[i];
    const std::uint32_t* const first_entry = entries(i);
    const int total = static_cast<int>(span_[i].count);
    const Real* const particle_gradients =
        gradients_cached_ ? gradients_[block_of(i)].data() + D * span_[i].first : nullptr;
    const bool offsets = Offsets || !particle_gradients;
    NeighborRun<D> run;
    for (int first = 0; first < total; first += NeighborRun<D>::capacity) {
      run.count = std::min(NeighborRun<D>::capacity, total - first);
      const std::uint32_t* const entry = first_entry + first;
      for (int d = 0; d < D; ++d)
        run.gradient[d] = particle_gradients ? particle_gradients + d * total + first : nullptr;
      set_indices(run, entry, table_->periodic());
      if (table_->periodic()) {
        if (offsets) {
          for (int k = 0; k < run.count; ++k) {
            const Vector<D> x_image = x - table_->shifts_[entry[k] >> index_bits];
            for (int d = 0; d < D; ++d) run.x_ij[d][k] = x_image[d] - source_x.component[d][run.index[k]];
          }
        }
      } else {
        if (offsets) {
          for (int k = 0; k < run.count; ++k)
            for (int d = 0; d < D; ++d) run.x_ij[d][k] = x[d] - source_x.component[d][entry[k]];
        }
      }
      if (offsets) {
        for (int k = 0; k < run.count; ++k) {
          Real r2 = 0;
          for (int d = 0; d < D; ++d) r2 += run.x_ij[d][k] * run.x_ij[d][k];
          run.r2[k] = r2;
        }
      }
      f(std::as_const(run));
    }
  }

  /// Bytes the list holds.
  std::size_t bytes() const;

  /// Adds "<owner>.indices" (every block's array, at capacity) and "<owner>.spans" (each
  /// particle's first entry and count).
  void add_memory(MemoryUsage& usage, const std::string& owner) const;

 private:
  // Source indices take the low bits of an entry, the image shift (on a periodic domain) the rest;
  // build() refuses a source set the low bits cannot number.
  static constexpr int index_bits = 27;
  static constexpr std::uint32_t index_mask = (std::uint32_t(1) << index_bits) - 1;
  // Query cells per block; fixed, so the layout does not depend on the thread count.
  static constexpr std::size_t cells_per_block = 64;

  // The indices of one block of cells, grown without initialising (a mask's decoding writes up to
  // 64 entries past the count before the count is known).
  struct IndexArray {
    std::unique_ptr<std::uint32_t[]> data;
    std::size_t size = 0;
    std::size_t capacity = 0;
    // Makes room for `more` entries past size.
    void reserve_more(std::size_t more);
  };
  struct Span {
    std::uint32_t first = 0;  // in the block's array
    std::uint32_t count = 0;
  };

  std::size_t block_of(std::size_t i) const { return queries_->particle_cell_[i] / cells_per_block; }
  const std::uint32_t* entries(std::size_t i) const { return blocks_[block_of(i)].data.get() + span_[i].first; }
  // The query particles of a block's cells, [first, last).
  std::pair<Index, Index> particles_of_block(std::size_t block) const {
    const std::size_t first_cell = block * cells_per_block;
    const std::size_t last_cell = std::min(queries_->occupied_cells(), first_cell + cells_per_block);
    return {queries_->cell_start_[first_cell], queries_->cell_start_[last_cell]};
  }

  // Points run.index at `entry`'s count source indices, unpacked on a periodic domain.
  static void set_indices(NeighborRun<D>& run, const std::uint32_t* entry, bool periodic) {
    if (!periodic) {
      run.index = entry;
      return;
    }
    for (int k = 0; k < run.count; ++k) run.unpacked_index[k] = entry[k] & index_mask;
    run.index = run.unpacked_index.data();
  }

  template <class F>
  static void call(std::uint32_t j, const Vector<D>& x, const ConstVectorView<D>& source_x, F& f) {
    Vector<D> xij;
    for (int d = 0; d < D; ++d) xij[d] = x[d] - source_x.component[d][j];
    f(Index(j), xij, squared_norm<D>(xij));
  }

  // Lists the particles of cells [first_cell, last_cell) into `out`.
  void fill_block(std::size_t first_cell, std::size_t last_cell, const ConstVectorView<D>& query_x,
                  const ConstVectorView<D>& source_x, IndexArray& out);
  // What refine() without a visitor hands the pairs to: no r² is kept for it.
  struct IgnorePairs {
    template <class Runs>
    void operator()(std::size_t, const Runs&) const {}
  };

  // The same from the entries of `candidates`, for the block of cells `block`, visiting each
  // particle's pairs (refine()).
  template <bool periodic, class Visit>
  void refine_block(const NeighborList& candidates, std::size_t block, const ConstVectorView<D>& query_x,
                    const ConstVectorView<D>& source_x, Visit& visit);

  const NeighborGrid<D>* queries_ = nullptr;
  const CrossNeighbors<D>* table_ = nullptr;
  std::vector<IndexArray> blocks_;
  std::vector<Span> span_;  // query particle i
  // Per block, D per index: what cache_gradients computed, valid while gradients_cached_ (a
  // build or refine clears it). Particle i's are at D × its first entry, by component:
  // component d of its entry k at D first + d count + k.
  std::vector<std::vector<Real>> gradients_;
  bool gradients_cached_ = false;
};

template <int D>
template <bool periodic, class Visit>
void NeighborList<D>::refine_block(const NeighborList& candidates, std::size_t block, const ConstVectorView<D>& query_x,
                                   const ConstVectorView<D>& source_x, Visit& visit) {
  constexpr bool visits = !std::is_same_v<std::remove_const_t<Visit>, IgnorePairs>;
  const Real support_squared = table_->support_squared_;
  IndexArray& out = blocks_[block];
  out.size = 0;
  std::vector<Real> listed_r2;  // with a visitor: r² of the particle's listed pairs, in order
  const auto [first_particle, last_particle] = particles_of_block(block);
  for (Index i = first_particle; i < last_particle; ++i) {
    const Vector<D> x = query_x[i];
    const std::uint32_t* const entries = candidates.entries(i);
    const Index total = candidates.span_[i].count;
    const std::size_t first_entry = out.size;
    // keep_inside may write up to 64 values past a chunk's first kept one.
    if constexpr (visits) listed_r2.resize(std::max<std::size_t>(listed_r2.size(), total + 64));
    for (Index first = 0; first < total; first += 64) {
      // The candidates' positions are gathered by index, 64 at a time, in a loop the compiler
      // vectorises, as in fill_block.
      const std::uint32_t* const entry = entries + first;
      const Index count = std::min<Index>(64, total - first);
      std::array<Real, 64> r2;
      for (Index k = 0; k < count; ++k) {
        const std::uint32_t j = periodic ? entry[k] & index_mask : entry[k];
        Real sum = 0;
        for (int d = 0; d < D; ++d) {
          const Real x_image = periodic ? x[d] - table_->shifts_[entry[k] >> index_bits][d] : x[d];
          const Real xij = x_image - source_x.component[d][j];
          sum += xij * xij;
        }
        r2[k] = sum;
      }
      // About half the candidates pass, so they are compacted (keep_inside) where fill_block's
      // sparser pass decodes a bit mask: BM_NeighborRefine, 3D, 10^5 particles, 1 thread:
      // 12.8 ms with the mask, 10.0 ms with a store per candidate and a counted keep.
      out.reserve_more(64);
      Real* const at_r2 = visits ? listed_r2.data() + (out.size - first_entry) : nullptr;
      out.size += keep_inside<visits>(entry, r2.data(), static_cast<int>(count), support_squared,
                                      out.data.get() + out.size, at_r2);
    }
    span_[i] = {static_cast<std::uint32_t>(first_entry), static_cast<std::uint32_t>(out.size - first_entry)};
    if constexpr (visits) {
      const std::uint32_t* const listed = out.data.get() + first_entry;
      const int listed_count = static_cast<int>(span_[i].count);
      visit(std::size_t(i), [&](auto&& f) {
        NeighborRun<D> run;
        for (int first = 0; first < listed_count; first += NeighborRun<D>::capacity) {
          run.count = std::min(NeighborRun<D>::capacity, listed_count - first);
          set_indices(run, listed + first, periodic);
          std::copy_n(listed_r2.data() + first, run.count, run.r2.begin());
          f(std::as_const(run));
        }
      });
    }
  }
}

extern template class NeighborList<2>;
extern template class NeighborList<3>;

}  // namespace tide
