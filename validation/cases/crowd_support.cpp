#include "crowd_support.hpp"

#include <sstream>
#include <stdexcept>
#include <utility>

#include "../report_support.hpp"
#include "tide/validation/text_output.hpp"

namespace tide::validation {

void require_crowd_variant(const Variant& variant) {
  if (variant.scheme != crowd_scheme || variant.kernel != KernelType::wendland_c2)
    throw std::invalid_argument("the crowd cases run the crowd scheme with the Wendland C2 kernel, not " +
                                variant.scheme + "/" + std::string(kernel_name(variant.kernel)));
}

std::string metric_number(double value) {
  std::string text = format_shortest(value);
  for (char& c : text) {
    if (c == '.') c = '_';
  }
  return text;
}

RunRecord crowd_record(const std::string& case_name, const Variant& variant, int resolution, std::size_t agents,
                       std::uint64_t steps, double wall_seconds, std::vector<Metric> metrics) {
  RunRecord record;
  record.case_name = case_name;
  record.scheme = variant.scheme;
  record.kernel = std::string(kernel_name(variant.kernel));
  record.resolution = resolution;
  record.particles = agents;
  record.steps = steps;
  record.wall_seconds = wall_seconds;
  record.metrics = std::move(metrics);
  return record;
}

std::string metric_block(const std::string& name, const RunRecord& run, std::span<const double> xs,
                         const std::function<std::string(double)>& metric_name) {
  std::ostringstream block;
  block.precision(17);
  block << '$' << name << " << EOD\n";
  for (const double x : xs) block << x << ' ' << detail::metric_value(run, metric_name(x)).value() << '\n';
  block << "EOD\n";
  return block.str();
}

}  // namespace tide::validation
