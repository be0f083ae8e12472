#pragma once

// The stress table: one row per run, as markdown (printed by `tide stress` and pasted into
// docs/stability.md) and as CSV.

#include <filesystem>
#include <span>
#include <string>

#include "tide/stress/case.hpp"

namespace tide::stress {

/// A markdown table with the columns case, settings, outcome, metric, value, bound, simulated
/// time, wall time and note.
std::string markdown_table(std::span<const Row> rows);

/// Writes the same columns as CSV (value in full precision, bound split into its relation and
/// limit). The file is replaced atomically.
void write_csv(const std::filesystem::path& path, std::span<const Row> rows);

}  // namespace tide::stress
