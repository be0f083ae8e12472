#pragma once

// The colour field's inner loop (field_tile.hpp): one row of grid points along the first axis,
// each adding the tabulated kernel (kernel_table.hpp) at its squared distance from a particle.

#include "kernel_table.hpp"

namespace tide::surface {

/// row[i] += table(row_squared + along_squared[i]) for i in [0, count): with AVX2 where the CPU
/// has it (chosen at run time; four points at a time, the table read by gathers), otherwise one
/// point at a time. Both do the same operations in the same order on every point (no fused
/// multiply-add), so the values are the same bits either way.
void add_kernel_row(const KernelTable& table, double* row, const double* along_squared, int count, double row_squared);

}  // namespace tide::surface
