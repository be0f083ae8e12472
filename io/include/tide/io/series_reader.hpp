#pragma once

// Reads back a CSV series as SeriesWriter writes it (probes.csv, recovery.csv, bodies.csv,
// crowd.csv; docs/output.md): "# " comment lines, a header "time,<column>,...", then rows of numbers.

#include <filesystem>
#include <string>
#include <vector>

namespace tide::io {

struct Series {
  std::vector<std::string> comments;        // the header's comment lines, without "# "
  std::vector<std::string> columns;         // "time" and the others, in the file's order
  std::vector<std::vector<double>> values;  // values[c][row]: one vector per column
};

/// std::runtime_error naming the file, and the line where it is one, for a file that cannot be
/// read, has no header, or has a row that is not one number per column.
Series read_series(const std::filesystem::path& file);

}  // namespace tide::io
