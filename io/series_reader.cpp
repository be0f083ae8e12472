#include "tide/io/series_reader.hpp"

#include <fstream>
#include <stdexcept>

#include "csv_numbers.hpp"

namespace tide::io {

Series read_series(const std::filesystem::path& file) {
  std::ifstream in(file);
  if (!in) throw std::runtime_error(file.string() + ": cannot read the series file");
  Series series;
  std::string text;
  std::size_t line = 0;
  while (std::getline(in, text)) {
    ++line;
    if (!text.empty() && text.back() == '\r') text.pop_back();
    if (text.starts_with("#")) {
      series.comments.push_back(text.substr(text.starts_with("# ") ? 2 : 1));
      continue;
    }
    if (series.columns.empty()) {
      for (std::size_t start = 0;;) {
        const std::size_t comma = text.find(',', start);
        series.columns.push_back(text.substr(start, comma - start));
        if (comma == std::string::npos) break;
        start = comma + 1;
      }
      if (series.columns.front() != "time")
        throw std::runtime_error(file.string() + ": line " + std::to_string(line) +
                                 ": expected the header \"time,...\", got \"" + text + "\"");
      series.values.resize(series.columns.size());
      continue;
    }
    if (text.empty()) continue;
    std::vector<double> numbers;
    try {
      numbers = csv_numbers(text, line, false);
    } catch (const std::invalid_argument& bad_row) {
      throw std::runtime_error(file.string() + ": " + bad_row.what());
    }
    if (numbers.size() != series.columns.size())
      throw std::runtime_error(file.string() + ": line " + std::to_string(line) + ": expected " +
                               std::to_string(series.columns.size()) + " numbers, got " +
                               std::to_string(numbers.size()));
    for (std::size_t c = 0; c < numbers.size(); ++c) series.values[c].push_back(numbers[c]);
  }
  if (series.columns.empty()) throw std::runtime_error(file.string() + ": no header line \"time,...\"");
  return series;
}

}  // namespace tide::io
