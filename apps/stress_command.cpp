#include "stress_command.hpp"

#include <algorithm>
#include <cstdio>
#include <iostream>

#include "run_command.hpp"
#include "tide/stress/case.hpp"
#include "tide/stress/table.hpp"
#include "tide/validation/text_output.hpp"

namespace tide::app {
namespace {

int list_stress_cases() {
  for (const stress::Case& c : stress::cases()) std::printf("%-16s %s\n", c.name.c_str(), c.title.c_str());
  return exit_ok;
}

}  // namespace

int stress(const StressOptions& options) {
  if (options.list) return list_stress_cases();
  std::vector<const stress::Case*> plan;
  for (const std::string& name : options.cases) {
    const stress::Case* c = stress::find_case(name);
    if (c == nullptr) {
      std::string names;
      for (const stress::Case& known : stress::cases()) names += (names.empty() ? "" : ", ") + known.name;
      std::cerr << "tide: stress: unknown case '" << name << "'; the cases are: " << names << '\n';
      return exit_bad_input;
    }
    plan.push_back(c);
  }
  if (plan.empty()) {
    for (const stress::Case& c : stress::cases()) plan.push_back(&c);
  }
  const stress::Length length = options.short_runs ? stress::Length::short_run : stress::Length::full;
  std::vector<stress::Row> rows;
  for (const stress::Case* c : plan) {
    std::printf("%s: %s ...\n", c->name.c_str(), c->title.c_str());
    std::fflush(stdout);
    for (const stress::Row& row : c->run(length)) {
      std::printf("  %s | %s = %g (%s): %s\n", row.settings.c_str(), row.metric.c_str(), row.value,
                  row.bound.text().c_str(), row.outcome().c_str());
      rows.push_back(row);
    }
    std::fflush(stdout);
  }
  const std::string table = stress::markdown_table(rows);
  std::cout << '\n' << table;
  const auto& out = options.output_directory;
  validation::write_text_file(out / "stress.md", table);
  stress::write_csv(out / "stress.csv", rows);
  std::cout << "tide: stress: wrote " << (out / "stress.md").string() << " and " << (out / "stress.csv").string()
            << '\n';
  const auto unexpected =
      std::count_if(rows.begin(), rows.end(), [](const stress::Row& row) { return !row.as_expected(); });
  if (unexpected == 0) return exit_ok;
  std::cerr << "tide: stress: " << unexpected << " of " << rows.size()
            << " rows did not behave as their case expects (outcome column)\n";
  return exit_unstable;
}

}  // namespace tide::app
