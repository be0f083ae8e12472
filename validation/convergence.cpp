// Observed orders of convergence: for e ≈ C r^-p, ln e is linear in ln r with slope -p.

#include <algorithm>
#include <cmath>

#include "report_support.hpp"
#include "tide/validation/report.hpp"

namespace tide::validation {
namespace {

struct Point {
  double log_resolution;
  double log_error;
};

bool same_group(const RunRecord& a, const RunRecord& b) {
  return a.case_name == b.case_name && a.scheme == b.scheme && a.kernel == b.kernel;
}

// The least-squares slope of log_error against log_resolution, negated.
double fitted_order(const std::vector<Point>& points) {
  double mean_x = 0, mean_y = 0;
  for (const Point& p : points) {
    mean_x += p.log_resolution;
    mean_y += p.log_error;
  }
  mean_x /= static_cast<double>(points.size());
  mean_y /= static_cast<double>(points.size());
  double covariance = 0, variance = 0;
  for (const Point& p : points) {
    covariance += (p.log_resolution - mean_x) * (p.log_error - mean_y);
    variance += (p.log_resolution - mean_x) * (p.log_resolution - mean_x);
  }
  return -covariance / variance;
}

void add_group_orders(const std::vector<StudyRun>& group, std::vector<ConvergenceOrder>& orders) {
  const RunRecord& first = group.front().record;
  for (const std::string& metric : detail::metric_names(group)) {
    std::vector<int> resolutions;
    std::vector<Point> points;
    for (const StudyRun& run : group) {
      const auto error = detail::metric_value(run.record, metric);
      if (!error || !std::isfinite(*error) || *error == 0 || run.record.resolution <= 0) continue;
      resolutions.push_back(run.record.resolution);
      points.push_back({std::log(static_cast<double>(run.record.resolution)), std::log(std::abs(*error))});
    }
    const ConvergenceOrder base{first.case_name, first.scheme, first.kernel, metric};
    for (std::size_t k = 1; k < points.size(); ++k) {
      if (resolutions[k] == resolutions[k - 1]) continue;
      ConvergenceOrder order = base;
      order.from = resolutions[k - 1];
      order.to = resolutions[k];
      order.order =
          (points[k - 1].log_error - points[k].log_error) / (points[k].log_resolution - points[k - 1].log_resolution);
      orders.push_back(order);
    }
    if (points.size() >= 3 && resolutions.front() != resolutions.back()) {
      ConvergenceOrder order = base;
      order.from = resolutions.front();
      order.to = resolutions.back();
      order.order = fitted_order(points);
      order.least_squares = true;
      orders.push_back(order);
    }
  }
}

}  // namespace

std::vector<ConvergenceOrder> convergence_orders(std::span<const StudyRun> runs) {
  std::vector<ConvergenceOrder> orders;
  std::vector<bool> taken(runs.size(), false);
  for (std::size_t k = 0; k < runs.size(); ++k) {
    if (taken[k] || !runs[k].ok()) continue;
    std::vector<StudyRun> group;
    for (std::size_t j = k; j < runs.size(); ++j) {
      if (!taken[j] && runs[j].ok() && same_group(runs[k].record, runs[j].record)) {
        group.push_back(runs[j]);
        taken[j] = true;
      }
    }
    std::stable_sort(group.begin(), group.end(),
                     [](const StudyRun& a, const StudyRun& b) { return a.record.resolution < b.record.resolution; });
    add_group_orders(group, orders);
  }
  return orders;
}

}  // namespace tide::validation
