#include "motion_table_file.hpp"

#include <fstream>
#include <stdexcept>
#include <string>
#include <system_error>

#include "csv_numbers.hpp"
#include "scene_text.hpp"

namespace tide::io {

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
    std::vector<double> numbers;
    try {
      numbers = csv_numbers(text, line, true);
    } catch (const std::invalid_argument& bad_row) {
      throw MotionTableError(bad_row.what());
    }
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
