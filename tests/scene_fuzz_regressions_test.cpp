// Every input the scene-parser fuzzer (fuzz/) ever crashed on, kept in fuzz/regressions/: each
// must now give a scene or a SceneError with a message, and nothing else.

#include <gtest/gtest.h>

#include <unistd.h>
#include <algorithm>
#include <cctype>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>
#include <vector>

#include "tide/io/scene_reader.hpp"

namespace tide::io {
namespace {

namespace fs = std::filesystem;

const fs::path regressions_dir = TIDE_FUZZ_REGRESSIONS_DIR;

/// The file names in fuzz/regressions/, sorted.
std::vector<std::string> regression_inputs() {
  std::vector<std::string> inputs;
  for (const auto& entry : fs::directory_iterator(regressions_dir))
    if (entry.is_regular_file()) inputs.push_back(entry.path().filename().string());
  std::sort(inputs.begin(), inputs.end());
  return inputs;
}

/// A hang is a finding too: while alive, SIGALRM ends the test process after `seconds`.
class Deadline {
 public:
  explicit Deadline(unsigned seconds) { ::alarm(seconds); }
  ~Deadline() { ::alarm(0); }
  Deadline(const Deadline&) = delete;
  Deadline& operator=(const Deadline&) = delete;
};

class SceneFuzzRegression : public ::testing::TestWithParam<std::string> {};

TEST_P(SceneFuzzRegression, ParsesOrThrowsSceneError) {
  const Deadline deadline(60);
  std::ifstream in(regressions_dir / GetParam(), std::ios::binary);
  ASSERT_TRUE(in) << "cannot read " << GetParam();
  const std::string text{std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
  try {
    const scene::Scene scene = parse_scene(text, GetParam());
    EXPECT_TRUE(scene.dimension == 2 || scene.dimension == 3);
  } catch (const SceneError& error) {
    EXPECT_STRNE(error.what(), "");
  }
}

/// A test name from the file name: its letters and digits, the rest as '_'.
std::string test_name(const ::testing::TestParamInfo<std::string>& info) {
  std::string name = fs::path(info.param).stem().string();
  std::replace_if(
      name.begin(), name.end(), [](unsigned char c) { return !std::isalnum(c); }, '_');
  return name;
}

INSTANTIATE_TEST_SUITE_P(Inputs, SceneFuzzRegression, ::testing::ValuesIn(regression_inputs()), test_name);

TEST(SceneFuzzRegressions, FolderIsNotEmpty) { EXPECT_FALSE(regression_inputs().empty()); }

}  // namespace
}  // namespace tide::io
