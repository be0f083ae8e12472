#include "tide/validation/text_output.hpp"

#include "tide/io/atomic_file.hpp"

#include <charconv>

namespace tide::validation {
namespace {

std::string csv_field(std::string_view text) {
  if (text.find_first_of(",\"\r\n") == std::string_view::npos) return std::string(text);
  std::string quoted = "\"";
  for (const char c : text) {
    if (c == '"') quoted += '"';
    quoted += c;
  }
  return quoted + '"';
}

}  // namespace

void write_text_file(const std::filesystem::path& path, std::string_view text) {
  io::replace_text_atomically(path, std::string(text));
}

std::string format_shortest(double value) {
  char text[32];
  const auto result = std::to_chars(text, text + sizeof text, value);
  return std::string(text, result.ptr);
}

void write_csv_row(std::ostream& out, const std::vector<std::string>& fields) {
  for (std::size_t k = 0; k < fields.size(); ++k) out << (k > 0 ? "," : "") << csv_field(fields[k]);
  out << '\n';
}

}  // namespace tide::validation
