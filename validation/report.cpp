#include "tide/validation/report.hpp"

#include <sstream>

#include "report_support.hpp"

namespace tide::validation {

void write_csv(const std::filesystem::path& path, std::span<const StudyRun> runs) {
  const std::vector<std::string> metrics = detail::metric_names(runs);
  std::vector<std::string> header{"case",      "scheme", "kernel",       "resolution",
                                  "particles", "steps",  "wall_seconds", "particle_steps_per_second",
                                  "status"};
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
