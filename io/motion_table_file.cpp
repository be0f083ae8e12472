#include "motion_table_file.hpp"

#include <charconv>
#include <cmath>
#include <fstream>
#include <string>
#include <string_view>
#include <system_error>

#include "scene_text.hpp"

namespace tide::io {
namespace {

// The comma-separated numbers of one row, or an error naming the first field that is not one.
std::vector<double> numbers_of(std::string_view row, std::size_t line) {
  std::vector<double> numbers;
  while (true) {
    const std::size_t comma = row.find(',');
    std::string_view field = row.substr(0, comma);
    while (!field.empty() && (field.front() == ' ' || field.front() == '\t')) field.remove_prefix(1);
    while (!field.empty() && (field.back() == ' ' || field.back() == '\t' || field.back() == '\r'))
      field.remove_suffix(1);
    double value = 0;
    const auto [end, error] = std::from_chars(field.data(), field.data() + field.size(), value);
    if (field.empty() || error != std::errc() || end != field.data() + field.size() || !std::isfinite(value)) {
      throw MotionTableError("line " + std::to_string(line) + ": expected a finite number, got \"" +
                             std::string(field) + "\"");
    }
    numbers.push_back(value);
    if (comma == std::string_view::npos) return numbers;
    row.remove_prefix(comma + 1);
  }
}

}  // namespace

std::vector<scene::MotionSample> read_motion_table(const std::filesystem::path& path, int dimension) {
  std::error_code error;
  const std::uintmax_t bytes = std::filesystem::file_size(path, error);
  if (error) throw MotionTableError("cannot read the file: " + error.message());
  if (bytes > largest_motion_table_bytes) {
    throw MotionTableError("the file has " + std::to_string(bytes) + " bytes, more than the " +
                           std::to_string(largest_motion_table_bytes) + " a motion table may have");
  }
  std::ifstream in(path);
  if (!in) throw MotionTableError("cannot open the file");
  const std::size_t columns = static_cast<std::size_t>(dimension) + 2;
  const std::string layout = dimension == 2 ? "time, x, y, angle" : "time, x, y, z, angle";
  std::vector<scene::MotionSample> rows;
  std::string text;
  std::size_t line = 0;
  if (!std::getline(in, text)) throw MotionTableError("line 1: expected a header line (" + layout + "), got nothing");
  ++line;
  while (std::getline(in, text)) {
    ++line;
    if (text.find_first_not_of(" \t\r") == std::string::npos) continue;
    const std::vector<double> numbers = numbers_of(text, line);
    if (numbers.size() != columns) {
      throw MotionTableError("line " + std::to_string(line) + ": expected " + std::to_string(columns) + " numbers (" +
                             layout + "), got " + std::to_string(numbers.size()));
    }
    scene::MotionSample row;
    row.time = numbers[0];
    for (int d = 0; d < dimension; ++d) row.displacement[d] = numbers[1 + d];
    row.angle = numbers[columns - 1];
    if (rows.empty() && (row.time != 0 || row.displacement != scene::Vec{} || row.angle != 0)) {
      throw MotionTableError("line " + std::to_string(line) +
                             ": expected the first row at time 0 with no displacement and no angle (the scene "
                             "places the obstacle at its start), got time " +
                             format_number(row.time) + ", displacement " + format_vector(row.displacement, dimension) +
                             ", angle " + format_number(row.angle));
    }
    if (!rows.empty() && !(row.time > rows.back().time)) {
      throw MotionTableError("line " + std::to_string(line) + ": expected a time after " +
                             format_number(rows.back().time) + ", got " + format_number(row.time));
    }
    rows.push_back(row);
  }
  if (rows.size() < 2)
    throw MotionTableError("expected at least two rows after the header, got " + std::to_string(rows.size()));
  return rows;
}

}  // namespace tide::io
