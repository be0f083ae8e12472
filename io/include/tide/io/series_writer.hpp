#pragma once

#include <filesystem>
#include <string>
#include <utility>
#include <vector>

#include "tide/core/scene.hpp"

namespace tide::io {

/// Writes a time series as one CSV file: a header (comment lines starting with '#' and the
/// column line "time,<column>,..."), then one row per reading, "<t>,<value>,...", times in s.
/// Numbers are written in the shortest form that reads back to the same double. Rows are kept in
/// memory and the whole file is rewritten through a temporary and a rename by `write` (atomic on
/// POSIX), so a run killed at any moment leaves either the previous complete file or the new one.
class SeriesWriter {
 public:
  /// `comments`: the header's comment lines, without their "# " and newline.
  SeriesWriter(std::filesystem::path file, const std::vector<std::string>& comments,
               const std::vector<std::string>& columns);

  /// Appends one row: the simulated time and one value per column, in order.
  /// std::invalid_argument when the number of values is not the number of columns.
  void add(double time, const std::vector<double>& values);

  /// Replaces the file with the header and every row added so far; creates its directory if
  /// absent. File-system failures give std::runtime_error naming the file; the file already in
  /// place stays as it was.
  void write() const;

  const std::filesystem::path& path() const { return file_; }
  std::size_t rows() const { return row_count_; }

  /// The rows added so far, as the file's text after its header: what a checkpoint keeps.
  const std::string& rows_text() const { return rows_; }
  /// Continues a series that had `count` rows, `text` (rows_text of its writer).
  void continue_after(std::string text, std::size_t count) {
    rows_ = std::move(text);
    row_count_ = count;
  }

 private:
  std::filesystem::path file_;
  std::size_t column_count_ = 0;
  std::string header_;
  std::string rows_;
  std::size_t row_count_ = 0;
};

/// The shortest decimal text that reads back to the same double, appended to `text`.
void append_number(std::string& text, double value);

/// "[x, y]" (2D) or "[x, y, z]" (3D) in the numbers of append_number, for header lines.
std::string vector_text(const scene::Vec& v, int dimension);

}  // namespace tide::io
