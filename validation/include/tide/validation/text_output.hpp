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

/// The shortest decimal text that reads back as exactly `value`.
std::string format_shortest(double value);

}  // namespace tide::validation
