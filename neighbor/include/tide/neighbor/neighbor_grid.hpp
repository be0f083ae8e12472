#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <string>
#include <string_view>
#include <vector>

#include "tide/core/memory_usage.hpp"
#include "tide/core/particle_set.hpp"
#include "tide/core/scratch_arena.hpp"
#include "tide/core/types.hpp"
#include "tide/neighbor/pair_sort.hpp"

namespace tide {

/// How the grid finds an occupied cell from its coordinates while it builds the per-cell
/// neighbour ranges. bench/neighbor_bench measures both.
enum class CellLookup {
  automatic,  ///< dense while the domain has at most 4 cells per particle, else hash
  hash,       ///< open-addressing table over occupied cells only: memory ∝ particles
  dense       ///< one slot per cell of the whole domain: memory ∝ domain volume (faster)
};

std::string_view cell_lookup_name(CellLookup lookup);

/// Box the particles live in, and which of its axes wrap around.
template <int D>
struct GridDomain {
  Vector<D> lower = Vector<D>::Zero();
  Vector<D> upper = Vector<D>::Ones();
  std::array<bool, D> periodic{};
};

/// A contiguous run of sorted particles [begin, end) seen through one periodic image: the
/// neighbour's position is x_j + shift, with shift one of the grid's 3^D image shifts.
struct CellRange {
  Index begin = 0;
  Index end = 0;
  std::uint32_t shift = 0;
};

/// How a CrossNeighbors table stores a CellRange: the particle run only; the image shift is kept
/// apart, and only on a domain with a periodic axis (elsewhere every shift is 0).
struct SourceRun {
  Index begin = 0;
  Index end = 0;
};

template <int D>
class NeighborGrid;
template <int D>
class NeighborList;

/// For each occupied cell of a query grid, the merged ranges of source particles in its 3^D
/// neighbouring cells of a source grid with the same domain and support. A grid keeps one such
/// table over itself; a second table links two particle sets (e.g. fluid cells → wall particles),
/// so passes walk contiguous ranges instead of looking cells up per particle. Rebuild it after
/// either grid's `update`.
template <int D>
class CrossNeighbors {
 public:
  void build(const NeighborGrid<D>& queries, const NeighborGrid<D>& sources);

  /// A table with no ranges for each of `query_cells` cells: every walk finds nothing.
  void clear(std::size_t query_cells);

  /// Calls f(j, x_ij, r2) for every source particle j with r2 = |x_ij|² < support², where
  /// x_ij = x − x_j (minimum image) and x lies in query cell `cell`.
  template <class F>
  void for_each_in_cell(std::uint32_t cell, const Vector<D>& x, const ConstVectorView<D>& source_x, F&& f) const {
    // Candidates are filtered in chunks without a branch (the index is always written, the
    // count advances only inside the support): most candidates of a 3^D stencil fail the test,
    // and a mispredicted branch per candidate cost more than the distance itself.
    constexpr Index chunk = 64;
    std::array<Index, chunk> inside;
    std::array<Real, chunk> inside_r2;
    for (std::uint32_t r = range_offset_[cell]; r < range_offset_[cell + 1]; ++r) {
      const CellRange range = this->range(r);
      const Vector<D> x_image = x - shifts_[range.shift];
      for (Index first = range.begin; first < range.end; first += chunk) {
        const Index last = std::min<Index>(range.end, first + chunk);
        Index count = 0;
        for (Index j = first; j < last; ++j) {
          Vector<D> xij;
          for (int d = 0; d < D; ++d) xij[d] = x_image[d] - source_x.component[d][j];
          const Real r2 = squared_norm<D>(xij);
          inside[count] = j;
          inside_r2[count] = r2;
          count += r2 < support_squared_ ? 1 : 0;
        }
        for (Index k = 0; k < count; ++k) {
          const Index j = inside[k];
          Vector<D> xij;
          for (int d = 0; d < D; ++d) xij[d] = x_image[d] - source_x.component[d][j];
          f(j, xij, inside_r2[k]);
        }
      }
    }
  }

  std::size_t bytes() const { return held_bytes(range_offset_) + held_bytes(runs_) + held_bytes(run_shifts_); }

  /// Whether a range can have an image shift (the domain has a periodic axis).
  bool periodic() const { return !run_shifts_.empty(); }

  /// Range r of the table (of all query cells, in order).
  CellRange range(std::uint32_t r) const {
    return {runs_[r].begin, runs_[r].end, run_shifts_.empty() ? 0u : std::uint32_t(run_shifts_[r])};
  }

  /// Adds "<owner>.range offsets" and "<owner>.ranges" (runs and, on a periodic domain, shifts).
  void add_memory(MemoryUsage& usage, const std::string& owner) const;

 private:
  friend class NeighborList<D>;
  std::array<Vector<D>, D == 2 ? 9 : 27> shifts_{};
  Real support_squared_ = 0;
  Real list_radius_squared_ = 0;             // (support + skin)²
  std::vector<std::uint32_t> range_offset_;  // query cell c: ranges [offset[c], offset[c+1])
  std::vector<SourceRun> runs_;
  std::vector<std::uint8_t> run_shifts_;  // empty unless the domain has a periodic axis
};

/// Uniform grid of cells at least one support radius wide, whose particles are kept sorted by
/// the Morton code of their cell. After `update`, every cell is a contiguous index range and
/// every occupied cell knows the (merged) ranges of its 3^D neighbouring cells.
///
/// With a skin s > 0 the cells are at least support + s wide: while no particle has moved more
/// than s/2 since the update, every walk (and a NeighborList of radius support + s built at the
/// update) still finds every pair inside the support at the current positions, so the sort and
/// the tables can be kept for several steps (a Verlet list with a skin; Verlet 1967).
///
/// Domain policy: on a periodic axis, positions are wrapped into [lower, upper). A particle
/// outside [lower, upper) on a non-periodic axis, or with a non-finite coordinate, is removed
/// from the set by `update`, which logs a warning and counts it.
template <int D>
class NeighborGrid {
 public:
  NeighborGrid(const GridDomain<D>& domain, Real support_radius, SortAlgorithm sort = SortAlgorithm::radix,
               CellLookup lookup = CellLookup::automatic, Real skin = 0);

  /// Wraps periodic positions, sorts the particles by cell code (one gather per field),
  /// removes particles outside the domain and rebuilds the cell table. Returns the number of
  /// particles removed by this call. The sort and the gather borrow their workspace
  /// (update_scratch_bytes) from the grid's own arena, or from `arena`, which a caller shares
  /// with what it needs only after the update (Interactions: the fluid's neighbour list).
  std::size_t update(ParticleSet<D>& particles);
  std::size_t update(ParticleSet<D>& particles, ScratchArena& arena);

  /// What update takes from its arena for n particles: keys and indices of the sort, each with
  /// a scratch copy; the reorder gathers into the scratch keys.
  static std::size_t update_scratch_bytes(std::size_t n);

  /// Calls f(j, x_ij, r2) for every particle j of the set last passed to `update` with
  /// r2 = |x_i − x_j|² < support², i itself included; x_ij = x_i − x_j with the minimum image
  /// on periodic axes. `x` is that set's position field.
  template <class F>
  void for_each_neighbor(std::size_t i, const ConstVectorView<D>& x, F&& f) const;

  /// Occupied-cell slot of particle i of the set last passed to `update`.
  std::uint32_t particle_cell(std::size_t i) const { return particle_cell_[i]; }

  /// The same for an arbitrary point (e.g. a probe). Passes over a second particle set use a
  /// CrossNeighbors table instead, which avoids the per-point cell look-ups.
  template <class F>
  void for_each_neighbor_of(const Vector<D>& point, const ConstVectorView<D>& x, F&& f) const;

  Real support_radius() const { return support_radius_; }
  Real skin() const { return skin_; }
  const GridDomain<D>& domain() const { return domain_; }
  const Vector<D>& cell_size() const { return cell_size_; }
  const std::array<std::uint32_t, D>& cell_counts() const { return cell_counts_; }
  std::size_t occupied_cells() const { return cell_codes_.size(); }
  std::size_t particle_count() const { return particle_cell_.size(); }
  std::size_t removed_total() const { return removed_total_; }
  /// Sets the count of removed particles so far: a resumed run's, from its checkpoint.
  void restore_removed_total(std::size_t count) { removed_total_ = count; }
  SortAlgorithm sort_algorithm() const { return sort_; }
  CellLookup cell_lookup() const { return lookup_; }
  /// The lookup the last update used (resolves `automatic`).
  CellLookup active_cell_lookup() const { return active_lookup_; }

  /// The per-cell neighbour ranges of the grid over itself (what for_each_neighbor walks).
  const CrossNeighbors<D>& own_neighbors() const { return own_neighbors_; }

  /// Bytes the grid keeps (tables and sort workspace).
  std::size_t bytes() const;

  /// Adds one item per buffer of the grid ("<owner>.<buffer>"), its own range table included.
  void add_memory(MemoryUsage& usage, const std::string& owner) const;

  /// For a set sorted once that afterwards only takes part in CrossNeighbors tables (fixed
  /// walls): frees the grid's own arena (the sort workspace), the sort histogram and the table
  /// of the grid over itself, which such a set never walks. for_each_neighbor then finds nothing
  /// until the next update rebuilds them.
  void release_update_memory();

 private:
  friend class CrossNeighbors<D>;
  friend class NeighborList<D>;
  static constexpr std::uint32_t no_cell = std::numeric_limits<std::uint32_t>::max();
  static constexpr int stencil_size = D == 2 ? 9 : 27;

  bool cell_of(const Vector<D>& x, std::array<std::int64_t, D>& cell) const;
  std::array<std::int64_t, D> cell_coordinates(std::size_t slot) const;
  std::uint64_t code_of(const std::array<std::int64_t, D>& cell) const;
  std::uint32_t find_cell(const std::array<std::int64_t, D>& cell) const;
  int stencil_ranges(const std::array<std::int64_t, D>& cell, std::array<CellRange, stencil_size>& out) const;
  void build_cells(std::size_t n);
  void build_lookup();

  GridDomain<D> domain_;
  Real support_radius_;
  Real support_squared_;
  Real skin_;
  SortAlgorithm sort_;
  CellLookup lookup_;
  CellLookup active_lookup_ = CellLookup::hash;
  Vector<D> cell_size_;
  Vector<D> inverse_cell_size_;
  std::array<std::uint32_t, D> cell_counts_{};
  std::uint64_t invalid_code_ = 0;
  std::array<Vector<D>, stencil_size> shifts_;
  std::size_t removed_total_ = 0;

  ScratchArena own_arena_;
  PairSortWorkspace sort_workspace_;       // spans into the arena while update runs, empty after
  std::vector<std::uint64_t> cell_codes_;  // occupied cells in Morton order
  std::vector<Index> cell_start_;          // cell c holds sorted particles [start[c], start[c+1])
  std::vector<Index> particle_cell_;       // occupied-cell slot of each sorted particle
  std::vector<std::uint64_t> hash_codes_;  // open addressing: code, or invalid_code_ if empty
  std::vector<std::uint32_t> hash_slots_;
  std::vector<std::uint32_t> dense_slots_;  // linear cell index -> slot, or no_cell
  CrossNeighbors<D> own_neighbors_;
};

template <int D>
template <class F>
void NeighborGrid<D>::for_each_neighbor(std::size_t i, const ConstVectorView<D>& x, F&& f) const {
  own_neighbors_.for_each_in_cell(particle_cell_[i], x[i], x, f);
}

template <int D>
template <class F>
void NeighborGrid<D>::for_each_neighbor_of(const Vector<D>& point, const ConstVectorView<D>& x, F&& f) const {
  Vector<D> wrapped = point;
  for (int d = 0; d < D; ++d) {
    if (domain_.periodic[d]) {
      const Real length = domain_.upper[d] - domain_.lower[d];
      wrapped[d] -= length * std::floor((wrapped[d] - domain_.lower[d]) / length);
    }
  }
  std::array<std::int64_t, D> cell;
  for (int d = 0; d < D; ++d) {
    const Real scaled = (wrapped[d] - domain_.lower[d]) * inverse_cell_size_[d];
    const Real count = static_cast<Real>(cell_counts_[d]);
    // Farther than one cell outside a non-periodic side (or not finite): no neighbours.
    if (!(scaled >= Real(-1) && scaled < count + Real(1))) return;
    cell[d] = static_cast<std::int64_t>(std::floor(scaled));
    if (domain_.periodic[d]) cell[d] = std::clamp<std::int64_t>(cell[d], 0, cell_counts_[d] - 1);
  }
  std::array<CellRange, stencil_size> stencil;
  const int count = stencil_ranges(cell, stencil);
  for (int r = 0; r < count; ++r) {
    const Vector<D> image = wrapped - shifts_[stencil[r].shift];
    for (Index j = stencil[r].begin; j < stencil[r].end; ++j) {
      Vector<D> xij;
      for (int d = 0; d < D; ++d) xij[d] = image[d] - x.component[d][j];
      const Real r2 = squared_norm<D>(xij);
      if (r2 < support_squared_) f(j, xij, r2);
    }
  }
}

extern template class NeighborGrid<2>;
extern template class NeighborGrid<3>;
extern template class CrossNeighbors<2>;
extern template class CrossNeighbors<3>;

}  // namespace tide
