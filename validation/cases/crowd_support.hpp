#pragma once

// What the crowd cases share (docs/crowds.md): the variant they run and their run record.

#include <cstdint>
#include <functional>
#include <span>
#include <string>
#include <vector>

#include "case_support.hpp"

namespace tide::validation {

/// Throws std::invalid_argument unless `variant` is the crowd scheme with the Wendland C2 kernel,
/// the kernel the model's one parameter set is for (docs/crowds.md, "Parameters").
void require_crowd_variant(const Variant& variant);

/// `value` as it appears in a metric's name: 0.5 → "0_5", 2 → "2".
std::string metric_number(double value);

/// The record of a crowd case's run: `agents` and `steps` summed over its simulations.
RunRecord crowd_record(const std::string& case_name, const Variant& variant, int resolution, std::size_t agents,
                       std::uint64_t steps, double wall_seconds, std::vector<Metric> metrics);

/// A gnuplot data block `$<name>`: a line "x y" for each x of `xs`, y the metric called
/// `metric_name(x)` of `run`.
std::string metric_block(const std::string& name, const RunRecord& run, std::span<const double> xs,
                         const std::function<std::string(double)>& metric_name);

}  // namespace tide::validation
