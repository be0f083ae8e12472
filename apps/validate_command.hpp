#pragma once

#include <filesystem>
#include <string>
#include <vector>

namespace tide::app {

struct ValidateOptions {
  std::vector<std::string> cases;    // empty: every case
  std::vector<int> resolutions;      // empty: each case's default ladder
  std::vector<std::string> schemes;  // empty: every scheme
  std::vector<std::string> kernels;  // empty: the default kernels of the study
  std::filesystem::path output_directory = "validation-results";
  std::filesystem::path docs_page;           // empty: no markdown page
  std::vector<std::filesystem::path> reuse;  // earlier results.csv files whose runs are taken, not rerun
  bool list = false;
  std::string command_line;  // as typed, for the page's "reproduce it with"
};

/// `tide validate`: runs the validation study (cases × schemes × kernels × resolutions), prints a
/// line per run, writes results.csv, orders.csv and each case's plots, and optionally the docs page.
/// Exit code 2 for an unknown name, 3 if any run failed.
int validate(const ValidateOptions& options);

/// `tide validate --list`: each case's name, title and default resolutions.
int list_cases();

/// The command as typed, with `tide` for the program and each argument quoted for a POSIX shell.
std::string quoted_command_line(int argc, char** argv);

}  // namespace tide::app
