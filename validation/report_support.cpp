#include "report_support.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace tide::validation::detail {

std::optional<double> metric_value(const RunRecord& record, std::string_view name) {
  const auto found =
      std::find_if(record.metrics.begin(), record.metrics.end(), [&](const Metric& m) { return m.name == name; });
  if (found == record.metrics.end()) return std::nullopt;
  return found->value;
}

std::vector<std::string> metric_names(std::span<const StudyRun> runs) {
  std::vector<std::string> names;
  for (const StudyRun& run : runs) {
    for (const Metric& metric : run.record.metrics) {
      if (std::find(names.begin(), names.end(), metric.name) == names.end()) names.push_back(metric.name);
    }
  }
  return names;
}

std::vector<StudyRun> runs_of_case(std::span<const StudyRun> runs, std::string_view case_name) {
  std::vector<StudyRun> selected;
  std::copy_if(runs.begin(), runs.end(), std::back_inserter(selected),
               [&](const StudyRun& run) { return run.record.case_name == case_name; });
  return selected;
}

bool plottable(const StudyRun& run) {
  if (!run.ok() || run.record.metrics.empty()) return false;
  const double error = run.record.metrics.front().value;
  return std::isfinite(error) && error > 0 && run.record.wall_seconds > 0 && run.record.resolution > 0;
}

}  // namespace tide::validation::detail
