#include "csv_numbers.hpp"

#include <charconv>
#include <cmath>
#include <stdexcept>
#include <string>
#include <system_error>

namespace tide::io {

std::vector<double> csv_numbers(std::string_view row, std::size_t line, bool finite) {
  std::vector<double> numbers;
  while (true) {
    const std::size_t comma = row.find(',');
    std::string_view field = row.substr(0, comma);
    while (!field.empty() && (field.front() == ' ' || field.front() == '\t')) field.remove_prefix(1);
    while (!field.empty() && (field.back() == ' ' || field.back() == '\t' || field.back() == '\r'))
      field.remove_suffix(1);
    double value = 0;
    const auto [end, error] = std::from_chars(field.data(), field.data() + field.size(), value);
    if (field.empty() || error != std::errc() || end != field.data() + field.size() ||
        (finite && !std::isfinite(value))) {
      throw std::invalid_argument("line " + std::to_string(line) + ": expected a " + (finite ? "finite " : "") +
                                  "number, got \"" + std::string(field) + "\"");
    }
    numbers.push_back(value);
    if (comma == std::string_view::npos) return numbers;
    row.remove_prefix(comma + 1);
  }
}

}  // namespace tide::io
