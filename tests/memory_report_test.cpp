// bench/memory_report as a user meets it: a bad option value is refused with the option's name,
// what it expects and exit code 2; --skin 0 measures the lists rebuilt every step (no candidate
// lists) and the default skin keeps them; the total it reports is the sum of its items.

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <string>
#include <utility>
#include <vector>

#include "run_command.hpp"

namespace tide {
namespace {

namespace fs = std::filesystem;

testing_support::CommandResult run_memory_report(const std::string& arguments) {
  return testing_support::run_command(TIDE_MEMORY_REPORT, arguments);
}

TEST(MemoryReport, BadOptionValuesNameTheOptionAndWhatItExpects) {
  const std::vector<std::pair<std::string, std::string>> cases = {
      {"--skin abc", "--skin expects a number, got 'abc'"},
      {"--skin 0.3x", "--skin expects a number, got '0.3x'"},
      {"--skin -1", "--skin is a number of particle spacings >= 0"},
      {"--skin nan", "--skin is a number of particle spacings >= 0"},
      {"--particles -5", "--particles is a count >= 1"},
      {"--particles many", "--particles expects a number, got 'many'"},
      {"--steps 2.5", "--steps expects a number, got '2.5'"},
      {"--steps -1", "--steps is a count >= 0"},
      {"--dimension 4", "--dimension is 2 or 3"},
      {"--skin", "missing value after --skin"},
  };
  for (const auto& [arguments, message] : cases) {
    const testing_support::CommandResult result = run_memory_report(arguments);
    EXPECT_EQ(result.exit_code, 2) << arguments << ": " << result.output;
    EXPECT_NE(result.output.find("memory_report: " + message), std::string::npos) << arguments << ": " << result.output;
  }
}

// The bytes per fluid particle of a small 2D WCSPH dam break, item by item.
nlohmann::json report(const std::string& skin_option, const std::string& name) {
  const fs::path json = fs::temp_directory_path() / ("memory_report_test_" + name + ".json");
  fs::remove(json);
  const testing_support::CommandResult result =
      run_memory_report("--dimension 2 --particles 2000 --steps 3 " + skin_option + " --json " + json.string());
  EXPECT_EQ(result.exit_code, 0) << result.output;
  std::ifstream in(json);
  nlohmann::json parsed = nlohmann::json::parse(in, nullptr, false);
  fs::remove(json);
  return parsed;
}

double candidate_bytes(const nlohmann::json& report) {
  double bytes = 0;
  for (const auto& item : report["items"])
    if (item["name"].get<std::string>().find("candidates") != std::string::npos)
      bytes += item["bytes_per_particle"].get<double>();
  return bytes;
}

double item_sum(const nlohmann::json& report) {
  double bytes = 0;
  for (const auto& item : report["items"]) bytes += item["bytes_per_particle"].get<double>();
  return bytes;
}

TEST(MemoryReport, SkinZeroHoldsNoCandidateListsAndTheDefaultSkinDoes) {
  const nlohmann::json without_skin = report("--skin 0", "skin0");
  const nlohmann::json default_skin = report("", "default");
  ASSERT_FALSE(without_skin.is_discarded());
  ASSERT_FALSE(default_skin.is_discarded());
  EXPECT_EQ(without_skin["skin"].get<double>(), 0.0);
  EXPECT_EQ(default_skin["skin"].get<double>(), 0.3);  // scene::default_neighbor_skin(wcsph)
  // Without a skin there are no candidate lists (nor positions at the build); with one there are.
  EXPECT_EQ(candidate_bytes(without_skin), 0.0);
  EXPECT_GT(candidate_bytes(default_skin), 0.0);
  EXPECT_LT(without_skin["bytes_per_particle"].get<double>(), default_skin["bytes_per_particle"].get<double>());
  // The total is the sum of the items. Each number is written with 6 significant digits (a
  // relative rounding of at most 5e-6), so the sum of the items and the total each carry at most
  // 5e-6 of the total: 1e-5 of it together.
  for (const nlohmann::json* r : {&without_skin, &default_skin})
    EXPECT_NEAR(item_sum(*r), (*r)["bytes_per_particle"].get<double>(),
                1e-5 * (*r)["bytes_per_particle"].get<double>());
}

}  // namespace
}  // namespace tide
