#pragma once

namespace tide {

/// Makes the C allocator map every block of 1 MiB or more on its own, so that a large array is
/// returned to the system when it is freed. glibc's default threshold rises to the size of each
/// large block freed (up to 32 MiB), after which such arrays come from the heap, and what the
/// setup frees (the particle samples, the walls' sort) stays resident: 3D WCSPH at 10^6 fluid
/// particles held 210 B per particle but kept 258 B resident, and 221 B with this (bench/memory_report).
/// The steps allocate no large block once sizes settle, so the mapping costs nothing per step.
/// A process-wide choice for executables (the `tide` app, the benchmarks), not for the library;
/// does nothing without glibc.
void release_large_blocks_to_the_system();

}  // namespace tide
