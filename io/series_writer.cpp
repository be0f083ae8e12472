#include "tide/io/series_writer.hpp"

#include <array>
#include <charconv>
#include <stdexcept>
#include <utility>

#include "tide/io/atomic_file.hpp"

namespace tide::io {

void append_number(std::string& text, double value) {
  std::array<char, 32> buffer{};
  const auto result = std::to_chars(buffer.data(), buffer.data() + buffer.size(), value);
  text.append(buffer.data(), result.ptr);
}

std::string vector_text(const scene::Vec& v, int dimension) {
  std::string text = "[";
  for (int d = 0; d < dimension; ++d) {
    if (d > 0) text += ", ";
    append_number(text, v[d]);
  }
  return text + "]";
}

SeriesWriter::SeriesWriter(std::filesystem::path file, const std::vector<std::string>& comments,
                           const std::vector<std::string>& columns)
    : file_(std::move(file)), column_count_(columns.size()) {
  for (const std::string& comment : comments) header_ += "# " + comment + "\n";
  header_ += "time";
  for (const std::string& column : columns) header_ += "," + column;
  header_ += "\n";
}

void SeriesWriter::add(double time, const std::vector<double>& values) {
  if (values.size() != column_count_) {
    throw std::invalid_argument(file_.string() + ": a row of " + std::to_string(values.size()) + " values for " +
                                std::to_string(column_count_) + " columns");
  }
  append_number(rows_, time);
  for (const double value : values) {
    rows_ += ',';
    append_number(rows_, value);
  }
  rows_ += '\n';
  ++row_count_;
}

void SeriesWriter::write() const {
  if (file_.has_parent_path()) std::filesystem::create_directories(file_.parent_path());
  replace_atomically(file_,
                     [&](const std::filesystem::path& temporary) { write_text_file(temporary, header_ + rows_); });
}

}  // namespace tide::io
