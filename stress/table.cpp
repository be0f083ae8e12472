#include "tide/stress/table.hpp"

#include <cmath>
#include <sstream>

#include "cases/case_support.hpp"
#include "tide/validation/text_output.hpp"

namespace tide::stress {
namespace {

// A cell of a markdown table: pipes escaped, line breaks flattened.
std::string cell(std::string text) {
  std::string escaped;
  for (const char c : text) {
    if (c == '|') {
      escaped += "\\|";
    } else {
      escaped += c == '\n' ? ' ' : c;
    }
  }
  return escaped;
}

std::string value_text(double value) { return std::isnan(value) ? "–" : format_number(value); }

}  // namespace

std::string markdown_table(std::span<const Row> rows) {
  std::ostringstream out;
  out << "| case | settings | outcome | metric | value | bound | simulated s | wall s | note |\n"
      << "| --- | --- | --- | --- | ---: | --- | ---: | ---: | --- |\n";
  for (const Row& row : rows) {
    out << "| " << cell(row.case_name) << " | " << cell(row.settings) << " | " << cell(row.outcome()) << " | "
        << cell(row.metric) << " | " << value_text(row.value) << " | " << row.bound.text() << " | "
        << format_number(row.simulated_seconds) << " | " << format_number(row.wall_seconds) << " | " << cell(row.note)
        << " |\n";
  }
  return out.str();
}

void write_csv(const std::filesystem::path& path, std::span<const Row> rows) {
  std::ostringstream out;
  validation::write_csv_row(out, {"case", "settings", "outcome", "metric", "value", "bound_relation", "bound_limit",
                                  "expect_pass", "simulated_seconds", "wall_seconds", "note"});
  for (const Row& row : rows) {
    validation::write_csv_row(
        out, {row.case_name, row.settings, row.outcome(), row.metric,
              std::isnan(row.value) ? std::string() : validation::format_shortest(row.value),
              row.bound.kind == Bound::Kind::below ? "below" : "above", validation::format_shortest(row.bound.limit),
              row.expect_pass ? "true" : "false", validation::format_shortest(row.simulated_seconds),
              validation::format_shortest(row.wall_seconds), row.note});
  }
  validation::write_text_file(path, out.str());
}

}  // namespace tide::stress
