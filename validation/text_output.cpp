#include "tide/validation/text_output.hpp"

#include "tide/io/atomic_file.hpp"

#include <charconv>
#include <stdexcept>

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

std::vector<CsvRecord> parse_csv(std::string_view text) {
  std::vector<CsvRecord> records;
  std::size_t line = 1;
  std::size_t k = 0;
  while (k < text.size()) {
    CsvRecord record{line, {}};
    for (bool more_fields = true; more_fields;) {
      std::string field;
      if (k < text.size() && text[k] == '"') {
        const std::size_t opening_line = line;
        for (++k;; ++k) {
          if (k >= text.size())
            throw std::invalid_argument("line " + std::to_string(opening_line) + ": a quoted field is not closed");
          if (text[k] == '"') {
            if (k + 1 < text.size() && text[k + 1] == '"') {
              field += '"';
              ++k;
              continue;
            }
            ++k;
            break;
          }
          if (text[k] == '\n') ++line;
          field += text[k];
        }
        if (k < text.size() && text[k] != ',' && text[k] != '\n' && text[k] != '\r')
          throw std::invalid_argument("line " + std::to_string(line) + ": text after a closing quote");
      } else {
        while (k < text.size() && text[k] != ',' && text[k] != '\n' && text[k] != '\r') field += text[k++];
      }
      record.fields.push_back(std::move(field));
      more_fields = k < text.size() && text[k] == ',';
      if (more_fields) ++k;
    }
    if (k < text.size() && text[k] == '\r') ++k;
    if (k < text.size() && text[k] == '\n') {
      ++k;
      ++line;
    }
    records.push_back(std::move(record));
  }
  return records;
}

}  // namespace tide::validation
