#include "tide/validation/report.hpp"

#include <algorithm>
#include <charconv>
#include <fstream>
#include <sstream>
#include <stdexcept>

#include "report_support.hpp"
#include "tide/validation/text_output.hpp"

namespace tide::validation {
namespace {

// The columns every results.csv starts with, before its metric columns.
const std::vector<std::string>& leading_columns() {
  static const std::vector<std::string> columns{"case",      "scheme", "kernel",       "resolution",
                                                "particles", "steps",  "wall_seconds", "particle_steps_per_second",
                                                "status"};
  return columns;
}

// `text` as a T, all of it; `where` names the cell in the error.
template <class T>
T parse_number(const std::string& text, const std::string& where) {
  T value{};
  const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), value);
  if (error != std::errc{} || end != text.data() + text.size())
    throw std::runtime_error(where + ": expected a number, found \"" + text + "\"");
  return value;
}

}  // namespace

void write_csv(const std::filesystem::path& path, std::span<const StudyRun> runs) {
  const std::vector<std::string> metrics = detail::metric_names(runs);
  std::vector<std::string> header = leading_columns();
  header.insert(header.end(), metrics.begin(), metrics.end());
  std::ostringstream out;
  write_csv_row(out, header);
  for (const StudyRun& run : runs) {
    const RunRecord& record = run.record;
    std::vector<std::string> row{record.case_name, record.scheme, record.kernel, std::to_string(record.resolution)};
    if (run.ok()) {
      row.insert(row.end(), {std::to_string(record.particles), std::to_string(record.steps),
                             detail::format_shortest(record.wall_seconds),
                             detail::format_shortest(record.particle_steps_per_second())});
    } else {
      row.insert(row.end(), 4, "");
    }
    row.push_back(run.status());
    for (const std::string& name : metrics) {
      const auto value = detail::metric_value(record, name);
      row.push_back(value && run.ok() ? detail::format_shortest(*value) : "");
    }
    write_csv_row(out, row);
  }
  detail::write_text_file(path, out.str());
}

std::vector<StudyRun> read_csv(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw std::runtime_error(path.string() + ": cannot be read");
  std::ostringstream text;
  text << in.rdbuf();
  std::vector<CsvRecord> records;
  try {
    records = parse_csv(text.str());
  } catch (const std::invalid_argument& error) {
    throw std::runtime_error(path.string() + ":" + error.what());
  }
  const std::vector<std::string>& leading = leading_columns();
  if (records.empty() || records[0].fields.size() < leading.size() ||
      !std::equal(leading.begin(), leading.end(), records[0].fields.begin()))
    throw std::runtime_error(path.string() + ":1: expected the header of a results.csv written by tide validate (" +
                             leading.front() + ", " + leading[1] + ", ..., " + leading.back() + ", metrics)");
  const std::vector<std::string>& header = records[0].fields;
  std::vector<StudyRun> runs;
  for (std::size_t r = 1; r < records.size(); ++r) {
    const CsvRecord& row = records[r];
    const std::string where = path.string() + ":" + std::to_string(row.line);
    if (row.fields.size() != header.size())
      throw std::runtime_error(where + ": expected " + std::to_string(header.size()) + " fields, found " +
                               std::to_string(row.fields.size()));
    const auto cell = [&](std::size_t column) { return where + ", column " + header[column]; };
    StudyRun run;
    RunRecord& record = run.record;
    record.case_name = row.fields[0];
    record.scheme = row.fields[1];
    record.kernel = row.fields[2];
    record.resolution = parse_number<int>(row.fields[3], cell(3));
    const std::string& status = row.fields[8];
    if (status != "ok") {
      const std::string failed = "failed: ";
      if (status.rfind(failed, 0) != 0 || status.size() == failed.size())
        throw std::runtime_error(cell(8) + ": expected \"ok\" or \"failed: <reason>\", found \"" + status + "\"");
      run.failure = status.substr(failed.size());
      runs.push_back(std::move(run));
      continue;
    }
    record.particles = parse_number<std::size_t>(row.fields[4], cell(4));
    record.steps = parse_number<std::uint64_t>(row.fields[5], cell(5));
    record.wall_seconds = parse_number<double>(row.fields[6], cell(6));
    for (std::size_t column = leading.size(); column < header.size(); ++column) {
      if (!row.fields[column].empty())
        record.metrics.push_back({header[column], parse_number<double>(row.fields[column], cell(column))});
    }
    runs.push_back(std::move(run));
  }
  return runs;
}

void write_orders_csv(const std::filesystem::path& path, std::span<const ConvergenceOrder> orders) {
  std::ostringstream out;
  write_csv_row(out, {"case", "scheme", "kernel", "metric", "from", "to", "order", "fit"});
  for (const ConvergenceOrder& order : orders) {
    write_csv_row(out, {order.case_name, order.scheme, order.kernel, order.metric, std::to_string(order.from),
                        std::to_string(order.to), detail::format_shortest(order.order),
                        order.least_squares ? "least_squares" : "consecutive"});
  }
  detail::write_text_file(path, out.str());
}

}  // namespace tide::validation
