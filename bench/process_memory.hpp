#pragma once

// The resident memory of this process as Linux reports it (/proc/self/status), to check the
// itemised accounting (MemoryUsage) against what the process really holds.

#include <cstddef>

namespace tide::bench {

/// VmRSS and VmHWM (peak resident set) in bytes; 0 where /proc is not readable.
struct ResidentMemory {
  std::size_t current = 0;
  std::size_t peak = 0;
};

ResidentMemory resident_memory();

/// The C heap (glibc's mallinfo2, all arenas): bytes in use, bytes freed but kept by the allocator
/// (resident once touched, though no structure holds them), and bytes of blocks mapped on their own
/// (large allocations, returned to the system when freed). All 0 without glibc.
struct HeapMemory {
  std::size_t in_use = 0;
  std::size_t free_kept = 0;
  std::size_t mapped = 0;
};

HeapMemory heap_memory();

/// Resets VmHWM to the current resident set (writes 5 to /proc/self/clear_refs, Linux ≥ 4.0), so
/// that the next peak covers only what follows; false where that is not possible.
bool reset_peak_resident_memory();

}  // namespace tide::bench
