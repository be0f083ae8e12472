#pragma once

// A typed test over 2D and 3D with a fresh output directory of its own under the temporary
// directory, removed after the test: what the output writers' tests run in.

#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <string>
#include <type_traits>

namespace tide::testing_support {

template <class Dimension>
class OutputDirectoryTest : public ::testing::Test {
 protected:
  static constexpr int D = Dimension::value;

  void SetUp() override {
    const auto* test = ::testing::UnitTest::GetInstance()->current_test_info();
    std::string name = std::string(test->test_suite_name()) + "_" + test->name() + "_" + std::to_string(::getpid());
    for (char& c : name)
      if (c == '/') c = '_';
    directory = std::filesystem::temp_directory_path() / ("tide_" + name);
    std::filesystem::remove_all(directory);
  }
  void TearDown() override { std::filesystem::remove_all(directory); }

  std::filesystem::path directory;
};

/// "2D", "3D": the typed tests' names.
struct DimensionName {
  template <class Dimension>
  static std::string GetName(int) {
    return std::to_string(Dimension::value) + "D";
  }
};

using Dimensions = ::testing::Types<std::integral_constant<int, 2>, std::integral_constant<int, 3>>;

}  // namespace tide::testing_support
