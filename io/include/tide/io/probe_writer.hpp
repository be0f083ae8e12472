#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "tide/core/scene.hpp"

namespace tide::io {

/// Writes a run's probe readings as one CSV file (docs/output.md, "probes.csv"):
///
///   # TideSPH probes of scene <scene source>
///   # <name>: pressure (Pa) at [x, y(, z)]          one line per probe
///   # <name>: water_height (m) above [x, y(, z)]
///   time,<name>,<name>,...
///   <t>,<value>,<value>,...                           one row per reading, times in s
///
/// Numbers are written in the shortest form that reads back to the same double. Rows are kept in
/// memory and the whole file is rewritten through a temporary and a rename by `write` (atomic on
/// POSIX), so a run killed at any moment leaves either the previous complete file or the new one.
class ProbeWriter {
 public:
  ProbeWriter(std::filesystem::path file, const scene::Scene& scene);

  /// Appends one row: the simulated time and one value per probe, in the scene's order.
  /// std::invalid_argument when the number of values is not the number of probes.
  void add(double time, const std::vector<double>& values);

  /// Replaces the file with the header and every row added so far; creates its directory if
  /// absent. File-system failures give std::runtime_error naming the file; the file already in
  /// place stays as it was.
  void write() const;

  const std::filesystem::path& path() const { return file_; }
  std::size_t rows() const { return row_count_; }

 private:
  std::filesystem::path file_;
  std::size_t probe_count_ = 0;
  std::string header_;
  std::string rows_;
  std::size_t row_count_ = 0;
};

}  // namespace tide::io
