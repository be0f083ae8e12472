#pragma once

// Helpers shared by the report's writers (CSV, convergence orders, plots, markdown).

#include <filesystem>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "tide/validation/report.hpp"
#include "tide/validation/text_output.hpp"

namespace tide::validation::detail {

using validation::format_shortest;
using validation::write_text_file;

/// The value of the metric called `name`, if the record has it.
std::optional<double> metric_value(const RunRecord& record, std::string_view name);

/// The metric names of `runs`, each once, in the order they are first seen.
std::vector<std::string> metric_names(std::span<const StudyRun> runs);

/// The runs of the case called `case_name`, in their order.
std::vector<StudyRun> runs_of_case(std::span<const StudyRun> runs, std::string_view case_name);

/// A successful run whose primary error, wall time and resolution are positive: a point on log axes.
bool plottable(const StudyRun& run);

}  // namespace tide::validation::detail
