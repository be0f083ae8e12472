#pragma once

// Reading a motion table (scene::MotionTable) from its CSV file.

#include <cstdint>
#include <filesystem>
#include <stdexcept>
#include <vector>

#include "tide/core/scene_motion.hpp"

namespace tide::io {

/// What is wrong with a motion table file, with the line it is on ("line 4: ...").
class MotionTableError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

/// The largest motion table read: a typo cannot make the reader take the machine's memory.
inline constexpr std::uintmax_t largest_motion_table_bytes = 64u << 20;

/// The rows of the CSV file `path` for a `dimension`-D scene: a header line, then one row per
/// sample, `time, x, y[, z], angle` (s, m, rad), comma-separated. Times rise strictly, the first
/// row is time 0 with no displacement and no angle, every number is finite. Throws
/// MotionTableError saying what is wrong and where.
std::vector<scene::MotionSample> read_motion_table(const std::filesystem::path& path, int dimension);

}  // namespace tide::io
