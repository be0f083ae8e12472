#pragma once

#include <filesystem>
#include <string>
#include <vector>

namespace tide::app {

struct StressOptions {
  std::vector<std::string> cases;  // empty: every case
  bool short_runs = false;         // the short forms the tests run
  std::filesystem::path output_directory = "stress-results";
  bool list = false;
};

/// `tide stress`: runs the stress cases, prints the table (markdown) and writes stress.md and
/// stress.csv into the output directory. Exit code 2 for an unknown case, 3 if any row did not
/// behave as its case says it should (a bound failed, or a failure mode did not show).
int stress(const StressOptions& options);

}  // namespace tide::app
