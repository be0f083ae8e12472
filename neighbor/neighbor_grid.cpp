#include "tide/neighbor/neighbor_grid.hpp"

#include <algorithm>
#include <bit>
#include <cmath>
#include <sstream>
#include <stdexcept>
#include <string>

#include "tide/core/log.hpp"
#include "tide/core/parallel.hpp"
#include "tide/neighbor/morton.hpp"

namespace tide {
namespace {

// Cells are made this much wider than the support radius, so that rounding in the cell
// coordinate can never put two particles closer than the support two cells apart.
constexpr Real cell_margin = Real(1e-5);

// Items per block when the cell table is built; fixed so the table never depends on threads.
constexpr std::size_t scan_block = std::size_t(1) << 14;

// Cells per block when neighbour ranges are gathered.
constexpr std::size_t cell_block = 1024;

// The automatic lookup uses the dense table while it costs at most this many cells (4 bytes
// each) per particle; beyond, the domain is mostly empty and the hash table is smaller.
constexpr std::size_t dense_cells_per_particle = 4;

std::uint64_t mix(std::uint64_t code) { return code * 0x9e3779b97f4a7c15ULL; }

}  // namespace

std::string_view cell_lookup_name(CellLookup lookup) {
  switch (lookup) {
    case CellLookup::automatic:
      return "automatic";
    case CellLookup::hash:
      return "hash";
    case CellLookup::dense:
      return "dense";
  }
  return "unknown";
}

template <int D>
NeighborGrid<D>::NeighborGrid(const GridDomain<D>& domain, Real support_radius, SortAlgorithm sort, CellLookup lookup,
                              Real skin)
    : domain_(domain),
      support_radius_(support_radius),
      support_squared_(support_radius * support_radius),
      skin_(skin),
      sort_(sort),
      lookup_(lookup) {
  if (!(support_radius > 0) || !std::isfinite(support_radius))
    throw std::invalid_argument("neighbour grid: support radius must be positive and finite, got " +
                                std::to_string(support_radius));
  if (!(skin >= 0) || !std::isfinite(skin))
    throw std::invalid_argument("neighbour grid: skin must be finite and at least 0, got " + std::to_string(skin));
  std::array<std::uint32_t, D> top{};
  for (int d = 0; d < D; ++d) {
    const Real length = domain.upper[d] - domain.lower[d];
    if (!(length > 0) || !std::isfinite(length))
      throw std::invalid_argument("neighbour grid: domain upper bound must exceed lower bound on axis " +
                                  std::to_string(d));
    const Real cells = std::floor(length / ((support_radius + skin) * (1 + cell_margin)));
    if (cells >= Real(std::uint64_t(1) << morton_bits_per_axis<D>))
      throw std::invalid_argument("neighbour grid: too many cells on axis " + std::to_string(d) +
                                  " for a 64-bit Morton code; enlarge the support or shrink the domain");
    cell_counts_[d] = static_cast<std::uint32_t>(std::max<Real>(cells, 1));
    if (domain.periodic[d] && cell_counts_[d] < 3)
      throw std::invalid_argument(
          "neighbour grid: a periodic axis must be at least 3 (support radius + skin) long (axis " + std::to_string(d) +
          ")");
    cell_size_[d] = length / static_cast<Real>(cell_counts_[d]);
    inverse_cell_size_[d] = Real(1) / cell_size_[d];
    top[d] = cell_counts_[d] - 1;
  }
  invalid_code_ = morton_code<D>(top) + 1;

  // Image shift of each stencil code: digit d (base 3) is 0 (none), 1 (+L) or 2 (−L).
  for (int s = 0; s < stencil_size; ++s) {
    int digits = s;
    for (int d = 0; d < D; ++d, digits /= 3) {
      const Real length = domain.upper[d] - domain.lower[d];
      shifts_[s][d] = digits % 3 == 0 ? Real(0) : (digits % 3 == 1 ? length : -length);
    }
  }
}

template <int D>
bool NeighborGrid<D>::cell_of(const Vector<D>& x, std::array<std::int64_t, D>& cell) const {
  for (int d = 0; d < D; ++d) {
    if (!(x[d] >= domain_.lower[d] && x[d] < domain_.upper[d])) return false;
    const Real scaled = (x[d] - domain_.lower[d]) * inverse_cell_size_[d];
    cell[d] = std::min<std::int64_t>(static_cast<std::int64_t>(scaled), cell_counts_[d] - 1);
  }
  return true;
}

template <int D>
std::array<std::int64_t, D> NeighborGrid<D>::cell_coordinates(std::size_t slot) const {
  const auto cell = morton_decode<D>(cell_codes_[slot]);
  std::array<std::int64_t, D> coordinates;
  for (int d = 0; d < D; ++d) coordinates[d] = cell[d];
  return coordinates;
}

template <int D>
std::uint64_t NeighborGrid<D>::code_of(const std::array<std::int64_t, D>& cell) const {
  std::array<std::uint32_t, D> unsigned_cell;
  for (int d = 0; d < D; ++d) unsigned_cell[d] = static_cast<std::uint32_t>(cell[d]);
  return morton_code<D>(unsigned_cell);
}

template <int D>
std::uint32_t NeighborGrid<D>::find_cell(const std::array<std::int64_t, D>& cell) const {
  if (active_lookup_ == CellLookup::dense) {
    std::size_t linear = 0;
    for (int d = D - 1; d >= 0; --d) linear = linear * cell_counts_[d] + static_cast<std::size_t>(cell[d]);
    return dense_slots_[linear];
  }
  const std::uint64_t code = code_of(cell);
  const std::size_t mask = hash_codes_.size() - 1;
  const int shift = 64 - std::countr_zero(hash_codes_.size());
  for (std::size_t h = static_cast<std::size_t>(mix(code) >> shift);; h = (h + 1) & mask) {
    if (hash_codes_[h] == code) return hash_slots_[h];
    if (hash_codes_[h] == invalid_code_) return no_cell;
  }
}

template <int D>
int NeighborGrid<D>::stencil_ranges(const std::array<std::int64_t, D>& cell,
                                    std::array<CellRange, stencil_size>& out) const {
  int count = 0;
  for (int s = 0; s < stencil_size; ++s) {
    std::array<std::int64_t, D> neighbour;
    std::uint32_t shift = 0;
    bool inside = true;
    int digits = s;
    for (int d = 0, weight = 1; d < D; ++d, digits /= 3, weight *= 3) {
      const std::int64_t n = cell_counts_[d];
      std::int64_t c = cell[d] + digits % 3 - 1;
      if (c < 0 || c >= n) {
        if (!domain_.periodic[d]) {
          inside = false;
          break;
        }
        // The neighbour cell is an image across the periodic side: its particles sit at x + L
        // (wrapped from the top) or x − L (from the bottom).
        shift += static_cast<std::uint32_t>((c >= n ? 1 : 2) * weight);
        c = c >= n ? c - n : c + n;
      }
      neighbour[d] = c;
    }
    if (!inside) continue;
    const std::uint32_t slot = find_cell(neighbour);
    if (slot == no_cell) continue;
    out[count++] = {cell_start_[slot], cell_start_[slot + 1], shift};
  }
  // Sort by start and merge runs that follow each other in memory (Morton order makes many
  // neighbouring cells adjacent), so the inner loops are longer and fewer.
  std::sort(out.begin(), out.begin() + count, [](const CellRange& a, const CellRange& b) { return a.begin < b.begin; });
  int merged = 0;
  for (int r = 0; r < count; ++r) {
    if (merged > 0 && out[merged - 1].end == out[r].begin && out[merged - 1].shift == out[r].shift) {
      out[merged - 1].end = out[r].end;
    } else {
      out[merged++] = out[r];
    }
  }
  return merged;
}

template <int D>
std::size_t NeighborGrid<D>::update_scratch_bytes(std::size_t n) {
  return 2 * ScratchArena::aligned(n * sizeof(std::uint64_t)) + 2 * ScratchArena::aligned(n * sizeof(Index));
}

template <int D>
std::size_t NeighborGrid<D>::update(ParticleSet<D>& particles) {
  return update(particles, own_arena_);
}

template <int D>
std::size_t NeighborGrid<D>::update(ParticleSet<D>& particles, ScratchArena& arena) {
  const std::size_t n = particles.size();
  arena.reset(update_scratch_bytes(n));
  PairSortWorkspace& workspace = sort_workspace_;
  workspace.keys = arena.take<std::uint64_t>(n);
  workspace.key_scratch = arena.take<std::uint64_t>(n);
  workspace.order = arena.take<Index>(n);
  workspace.order_scratch = arena.take<Index>(n);
  auto x = particles[particles.position()];
  const std::span<std::uint64_t> codes = workspace.keys;
  for_each_particle(n, [&](std::size_t i) {
    Vector<D> xi = x[i];
    for (int d = 0; d < D; ++d) {
      if (!domain_.periodic[d] || !std::isfinite(xi[d])) continue;
      const Real length = domain_.upper[d] - domain_.lower[d];
      xi[d] -= length * std::floor((xi[d] - domain_.lower[d]) / length);
      if (xi[d] >= domain_.upper[d]) xi[d] = domain_.lower[d];  // rounding of values just below lower
    }
    x.set(i, xi);
    std::array<std::int64_t, D> cell;
    codes[i] = cell_of(xi, cell) ? code_of(cell) : invalid_code_;
  });
  sort_pairs(sort_, sort_workspace_);
  const auto& sorted = sort_workspace_.keys;
  const std::size_t kept =
      static_cast<std::size_t>(std::lower_bound(sorted.begin(), sorted.end(), invalid_code_) - sorted.begin());
  // The sort's scratch keys are free now (the sort may have swapped them with the keys): each
  // field's gather borrows them.
  particles.permute(std::span<const Index>(workspace.order).first(kept), std::as_writable_bytes(workspace.key_scratch));
  const std::size_t removed = n - kept;
  removed_total_ += removed;
  if (removed > 0) {
    std::ostringstream message;
    message << removed << " particle(s) left the domain or had a non-finite position and were removed ("
            << removed_total_ << " so far)";
    log_warning(message.str());
  }
  build_cells(kept);
  // The arena's next phase may reuse its bytes: no span into it is kept.
  workspace.keys = {};
  workspace.key_scratch = {};
  workspace.order = {};
  workspace.order_scratch = {};
  build_lookup();
  own_neighbors_.build(*this, *this);
  return removed;
}

template <int D>
void NeighborGrid<D>::build_cells(std::size_t n) {
  const auto& sorted = sort_workspace_.keys;
  const std::size_t blocks = (n + scan_block - 1) / scan_block;
  std::vector<std::size_t> first_slot(blocks + 1, 0);
  auto starts_cell = [&](std::size_t i) { return i == 0 || sorted[i] != sorted[i - 1]; };
  parallel_blocks(blocks, 1, [&](std::size_t first, std::size_t last) {
    for (std::size_t b = first; b < last; ++b) {
      std::size_t count = 0;
      for (std::size_t i = b * scan_block; i < std::min(n, (b + 1) * scan_block); ++i) count += starts_cell(i);
      first_slot[b + 1] = count;
    }
  });
  for (std::size_t b = 0; b < blocks; ++b) first_slot[b + 1] += first_slot[b];
  const std::size_t cells = first_slot[blocks];
  cell_codes_.resize(cells);
  cell_start_.resize(cells + 1);
  particle_cell_.resize(n);
  cell_start_[cells] = static_cast<Index>(n);
  parallel_blocks(blocks, 1, [&](std::size_t first, std::size_t last) {
    for (std::size_t b = first; b < last; ++b) {
      std::size_t slot = first_slot[b];
      for (std::size_t i = b * scan_block; i < std::min(n, (b + 1) * scan_block); ++i) {
        if (starts_cell(i)) {
          cell_codes_[slot] = sorted[i];
          cell_start_[slot] = static_cast<Index>(i);
          ++slot;
        }
        particle_cell_[i] = static_cast<Index>(slot - 1);
      }
    }
  });
}

template <int D>
void NeighborGrid<D>::build_lookup() {
  const std::size_t cells = cell_codes_.size();
  std::size_t total = 1;
  for (int d = 0; d < D; ++d) total *= cell_counts_[d];
  active_lookup_ = lookup_;
  if (lookup_ == CellLookup::automatic)
    active_lookup_ = total <= dense_cells_per_particle * particle_cell_.size() ? CellLookup::dense : CellLookup::hash;
  if (active_lookup_ == CellLookup::dense) {
    release_memory(hash_codes_);
    release_memory(hash_slots_);
    dense_slots_.assign(total, no_cell);
    for_each_particle(cells, [&](std::size_t c) {
      std::size_t linear = 0;
      const auto cell = morton_decode<D>(cell_codes_[c]);
      for (int d = D - 1; d >= 0; --d) linear = linear * cell_counts_[d] + cell[d];
      dense_slots_[linear] = static_cast<std::uint32_t>(c);
    });
    return;
  }
  release_memory(dense_slots_);
  const std::size_t capacity = std::bit_ceil(std::max<std::size_t>(2 * cells, 16));
  hash_codes_.assign(capacity, invalid_code_);
  hash_slots_.resize(capacity);
  const std::size_t mask = capacity - 1;
  const int shift = 64 - std::countr_zero(capacity);
  // Sequential insertion keeps the table layout independent of the thread count.
  for (std::size_t c = 0; c < cells; ++c) {
    std::size_t h = static_cast<std::size_t>(mix(cell_codes_[c]) >> shift);
    while (hash_codes_[h] != invalid_code_) h = (h + 1) & mask;
    hash_codes_[h] = cell_codes_[c];
    hash_slots_[h] = static_cast<std::uint32_t>(c);
  }
}

template <int D>
std::size_t NeighborGrid<D>::bytes() const {
  MemoryUsage usage;
  add_memory(usage, "grid");
  return usage.total();
}

template <int D>
void NeighborGrid<D>::add_memory(MemoryUsage& usage, const std::string& owner) const {
  usage.add(owner + ".sort and reorder scratch", own_arena_.bytes());
  usage.add(owner + ".sort histogram", sort_workspace_.histogram);
  usage.add(owner + ".particle cell", particle_cell_);
  usage.add(owner + ".cell codes and starts", held_bytes(cell_codes_) + held_bytes(cell_start_));
  usage.add(owner + ".cell lookup", held_bytes(hash_codes_) + held_bytes(hash_slots_) + held_bytes(dense_slots_));
  own_neighbors_.add_memory(usage, owner + ".own table");
}

template <int D>
void NeighborGrid<D>::release_update_memory() {
  own_arena_.release();
  release_memory(sort_workspace_.histogram);
  own_neighbors_.clear(cell_codes_.size());
}

template <int D>
void CrossNeighbors<D>::add_memory(MemoryUsage& usage, const std::string& owner) const {
  usage.add(owner + ".range offsets", range_offset_);
  usage.add(owner + ".ranges", held_bytes(runs_) + held_bytes(run_shifts_));
}

template <int D>
void CrossNeighbors<D>::clear(std::size_t query_cells) {
  range_offset_.assign(query_cells + 1, 0);
  range_offset_.shrink_to_fit();
  release_memory(runs_);
  release_memory(run_shifts_);
}

template <int D>
void CrossNeighbors<D>::build(const NeighborGrid<D>& queries, const NeighborGrid<D>& sources) {
  for (int d = 0; d < D; ++d) {
    if (queries.cell_counts_[d] != sources.cell_counts_[d] || queries.cell_size_[d] != sources.cell_size_[d] ||
        queries.domain_.periodic[d] != sources.domain_.periodic[d])
      throw std::invalid_argument("cross neighbours: both grids need the same domain, support radius and skin");
  }
  shifts_ = sources.shifts_;
  support_squared_ = sources.support_squared_;
  const Real list_radius = sources.support_radius_ + sources.skin_;
  list_radius_squared_ = list_radius * list_radius;
  // Box of the occupied source cells: a query cell more than one cell outside it on a closed
  // axis has no source in its stencil and needs no look-ups (e.g. the walls above the water).
  using Box = std::array<std::array<std::uint32_t, D>, 2>;
  Box empty;
  empty[0].fill(std::numeric_limits<std::uint32_t>::max());
  empty[1].fill(0);
  const Box occupied = reduce(
      sources.cell_codes_.size(), empty,
      [&](std::size_t c) {
        const auto cell = morton_decode<D>(sources.cell_codes_[c]);
        return Box{cell, cell};
      },
      [](Box a, const Box& b) {
        for (int d = 0; d < D; ++d) {
          a[0][d] = std::min(a[0][d], b[0][d]);
          a[1][d] = std::max(a[1][d], b[1][d]);
        }
        return a;
      });
  const auto near_sources = [&](const std::array<std::int64_t, D>& cell) {
    for (int d = 0; d < D; ++d) {
      if (sources.domain_.periodic[d]) continue;
      if (cell[d] + 1 < std::int64_t(occupied[0][d]) || cell[d] > std::int64_t(occupied[1][d]) + 1) return false;
    }
    return true;
  };
  // One stencil per query cell, gathered per fixed block of cells and then placed by a prefix
  // sum, so the layout is independent of the thread count.
  const std::size_t cells = queries.cell_codes_.size();
  range_offset_.resize(cells + 1);
  range_offset_[0] = 0;
  const std::size_t blocks = (cells + cell_block - 1) / cell_block;
  bool periodic = false;
  for (int d = 0; d < D; ++d) periodic = periodic || sources.domain_.periodic[d];
  // Each block's runs (and shifts) in the table's own 8-byte (and 1-byte) form: these copies
  // live until they are placed, and are the peak of a step above what it keeps.
  std::vector<std::vector<SourceRun>> block_runs(blocks);
  std::vector<std::vector<std::uint8_t>> block_shifts(periodic ? blocks : 0);
  parallel_blocks(blocks, 1, [&](std::size_t first, std::size_t last) {
    std::array<CellRange, NeighborGrid<D>::stencil_size> stencil;
    for (std::size_t b = first; b < last; ++b) {
      for (std::size_t c = b * cell_block; c < std::min(cells, (b + 1) * cell_block); ++c) {
        const auto cell = queries.cell_coordinates(c);
        const int count = near_sources(cell) ? sources.stencil_ranges(cell, stencil) : 0;
        range_offset_[c + 1] = static_cast<std::uint32_t>(count);
        std::vector<SourceRun>& runs = block_runs[b];
        const std::size_t at = runs.size();
        runs.resize(at + std::size_t(count));
        for (int k = 0; k < count; ++k) runs[at + std::size_t(k)] = {stencil[k].begin, stencil[k].end};
        if (!periodic) continue;
        std::vector<std::uint8_t>& shifts = block_shifts[b];
        shifts.resize(at + std::size_t(count));
        for (int k = 0; k < count; ++k) shifts[at + std::size_t(k)] = static_cast<std::uint8_t>(stencil[k].shift);
      }
    }
  });
  for (std::size_t c = 0; c < cells; ++c) range_offset_[c + 1] += range_offset_[c];
  runs_.resize(range_offset_[cells]);
  if (periodic) {
    run_shifts_.resize(runs_.size());
  } else {
    release_memory(run_shifts_);
  }
  parallel_blocks(blocks, 1, [&](std::size_t first, std::size_t last) {
    for (std::size_t b = first; b < last; ++b) {
      const std::size_t r = range_offset_[b * cell_block];
      std::copy(block_runs[b].begin(), block_runs[b].end(), runs_.begin() + std::ptrdiff_t(r));
      if (periodic) std::copy(block_shifts[b].begin(), block_shifts[b].end(), run_shifts_.begin() + std::ptrdiff_t(r));
    }
  });
}

template class NeighborGrid<2>;
template class NeighborGrid<3>;
template class CrossNeighbors<2>;
template class CrossNeighbors<3>;

}  // namespace tide
