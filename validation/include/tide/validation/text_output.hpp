#pragma once

// Writing result files: whole files replaced atomically, CSV rows, numbers that read back exactly.
// Shared by the validation report and the stress suite.

#include <filesystem>
#include <ostream>
#include <string>
#include <string_view>
#include <vector>

namespace tide::validation {

/// Writes `text` to `path` through a temporary file beside it and a rename, so a reader never
/// sees a half-written file; creates the parent directory if needed.
void write_text_file(const std::filesystem::path& path, std::string_view text);

/// Writes one CSV line (RFC 4180: a field with a comma, quote or line break is quoted, its
/// quotes doubled).
void write_csv_row(std::ostream& out, const std::vector<std::string>& fields);

/// The records of a CSV text (RFC 4180, as write_csv_row writes them: quoted fields may hold
/// commas, doubled quotes and line breaks), each with the 1-based line it starts on. Throws
/// std::invalid_argument naming the line of an unterminated quote or of text after a closing quote.
struct CsvRecord {
  std::size_t line = 0;
  std::vector<std::string> fields;
};
std::vector<CsvRecord> parse_csv(std::string_view text);

/// The shortest decimal text that reads back as exactly `value`.
std::string format_shortest(double value);

}  // namespace tide::validation
