// `tide run --resume` as a user meets it (issue 39): a run killed with SIGKILL at random moments
// and resumed each time from its checkpoint ends with the same frames, probes.csv, recovery.csv,
// XDMF file and VTK files (.vtu, .pvd), byte for byte, as the run that was never stopped; a checkpoint of another
// scene, precision or format, or none at all, is refused with exit code 2.

#include <gtest/gtest.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <random>
#include <sstream>
#include <string>
#include <thread>
#include <vector>

#include "run_command.hpp"
#include "tide/io/checkpoint_file.hpp"
#include "tide/io/frame_writer.hpp"

namespace tide {
namespace {

namespace fs = std::filesystem;

using testing_support::CommandResult;

CommandResult run_tide(const std::string& arguments) { return testing_support::run_command(TIDE_COMMAND, arguments); }

class ResumeCommand : public testing::Test {
 protected:
  void SetUp() override {
    directory_ = fs::temp_directory_path() /
                 ("resume_command_test_" + std::string(testing::UnitTest::GetInstance()->current_test_info()->name()));
    fs::remove_all(directory_);
    fs::create_directories(directory_);
  }
  void TearDown() override { fs::remove_all(directory_); }

  // A 2D dam break of 800 particles with probes and a recovery region, 0.25 s: about a second of
  // running on one core.
  fs::path write_scene(const std::string& name, double end = 0.25) {
    const fs::path file = directory_ / name;
    std::ofstream(file) << R"({
  "dimension": 2,
  "particle_spacing": 0.005,
  "kernel": {"type": "wendland_c2", "smoothing_ratio": 1.3},
  "materials": [{"name": "water", "rest_density": 1000, "max_speed": 2.0}],
  "fluid": [{"material": "water", "box": {"min": [0, 0], "max": [0.1, 0.2]}}],
  "walls": {"layers": 3, "container": {"min": [0, 0], "max": [0.4, 0.3], "open_top": true}},
  "probes": [{"name": "P1", "type": "pressure", "position": [0.4, 0.01]},
             {"name": "H1", "type": "water_height", "position": [0.05, 0]}],
  "output": {"probe_interval": 0.005, "vtk": true, "recovery": {"material": "water", "region": {"min": [0, 0], "max": [0.1, 0.3]}}},
  "time": {"start": 0, "end": )"
                        << end << R"(, "output_interval": 0.02}
})";
    return file;
  }

  fs::path directory_;
};

std::string file_text(const fs::path& file) {
  std::ifstream in(file, std::ios::binary);
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

// Every frame file of `run` in name order.
std::vector<fs::path> frame_files(const fs::path& run) {
  std::vector<fs::path> frames;
  for (const auto& entry : fs::directory_iterator(run))
    if (entry.path().extension() == ".h5" && entry.path().filename().string().starts_with("frames_"))
      frames.push_back(entry.path());
  std::sort(frames.begin(), frames.end());
  return frames;
}

void expect_same_frames(const fs::path& straight, const fs::path& resumed) {
  const std::vector<fs::path> a = frame_files(straight), b = frame_files(resumed);
  ASSERT_EQ(a.size(), b.size());
  ASSERT_GE(a.size(), 5u);
  for (std::size_t k = 0; k < a.size(); ++k) {
    SCOPED_TRACE(a[k].filename().string());
    ASSERT_EQ(a[k].filename(), b[k].filename());
    const io::Frame x = io::read_frame(a[k]), y = io::read_frame(b[k]);
    EXPECT_EQ(std::memcmp(&x.time, &y.time, sizeof x.time), 0);
    EXPECT_EQ(x.step, y.step);
    EXPECT_EQ(x.attributes, y.attributes);
    ASSERT_EQ(x.datasets.size(), y.datasets.size());
    for (const auto& [name, dataset] : x.datasets) {
      const io::FrameDataset& other = y.datasets.at(name);
      ASSERT_EQ(dataset.shape, other.shape) << name;
      EXPECT_EQ(std::memcmp(dataset.values.data(), other.values.data(), dataset.values.size() * sizeof(double)), 0)
          << name;
    }
  }
  for (const fs::path& frame : a) {
    const fs::path vtu = fs::path(frame).replace_extension(".vtu").filename();
    EXPECT_EQ(file_text(straight / vtu), file_text(resumed / vtu)) << vtu;
  }
  // frames.pvd names each frame once, as frames.xdmf does.
  for (const char* file : {"frames.xdmf", "frames.pvd", "probes.csv", "recovery.csv"})
    EXPECT_EQ(file_text(straight / file), file_text(resumed / file)) << file;
}

// Starts `tide arguments...` with its output discarded; returns its process id.
pid_t start_tide(const std::vector<std::string>& arguments) {
  const pid_t pid = fork();
  if (pid == 0) {
    std::vector<char*> argv{const_cast<char*>(TIDE_COMMAND)};
    for (const std::string& argument : arguments) argv.push_back(const_cast<char*>(argument.c_str()));
    argv.push_back(nullptr);
    if (std::freopen("/dev/null", "w", stdout) == nullptr || std::freopen("/dev/null", "w", stderr) == nullptr)
      _exit(127);
    execv(TIDE_COMMAND, argv.data());
    _exit(127);
  }
  return pid;
}

TEST_F(ResumeCommand, RunKilledAtRandomMomentsEndsAsTheStraightRun) {
  const fs::path scene = write_scene("dam.json");
  const fs::path straight = directory_ / "straight", killed = directory_ / "killed";
  const CommandResult reference = run_tide("run --quiet --threads 2 --out " + straight.string() + " " + scene.string());
  ASSERT_EQ(reference.exit_code, 0) << reference.output;

  // Twelve attempts killed after 50 to 400 ms (fixed seed), each resuming from the checkpoint the
  // last one left, then one let run to the end. A resume that found a broken checkpoint would exit
  // 2: the writes are atomic, so none may.
  std::mt19937 random(39);
  std::uniform_int_distribution<int> delay_ms(50, 400);
  constexpr int killed_attempts = 12;
  int kills = 0, resumes = 0, status = 0;
  for (int attempt = 0; attempt <= killed_attempts; ++attempt) {
    std::vector<std::string> arguments{
        "run", "--quiet", "--threads", attempt % 2 == 0 ? "1" : "2", "--checkpoint-every", "0.004", scene.string()};
    if (fs::exists(killed / "checkpoint.h5")) {
      arguments.insert(arguments.end(), {"--resume", killed.string()});
      ++resumes;
    } else {
      arguments.insert(arguments.end(), {"--out", killed.string()});
    }
    const pid_t pid = start_tide(arguments);
    ASSERT_GT(pid, 0);
    if (attempt < killed_attempts) {
      std::this_thread::sleep_for(std::chrono::milliseconds(delay_ms(random)));
      kill(pid, SIGKILL);
    }
    ASSERT_EQ(waitpid(pid, &status, 0), pid);
    if (WIFEXITED(status)) {
      ASSERT_EQ(WEXITSTATUS(status), 0) << "attempt " << attempt;
      break;
    }
    ++kills;
  }
  ASSERT_TRUE(WIFEXITED(status));
  std::printf("%d kills, %d resumes\n", kills, resumes);
  EXPECT_GT(kills, 1);
  EXPECT_GT(resumes, 1);
  expect_same_frames(straight, killed);
}

TEST_F(ResumeCommand, ResumeCanRunPastTheEndTime) {
  const fs::path scene = write_scene("dam.json", 0.04);
  const fs::path straight = directory_ / "straight", split = directory_ / "split";
  ASSERT_EQ(run_tide("run --quiet --until 0.08 --out " + straight.string() + " " + scene.string()).exit_code, 0);
  const CommandResult first =
      run_tide("run --quiet --checkpoint-every 0.02 --out " + split.string() + " " + scene.string());
  ASSERT_EQ(first.exit_code, 0) << first.output;
  EXPECT_NE(first.output.find("checkpoints 2,"), std::string::npos) << first.output;
  // The scene comes from the checkpoint.
  const CommandResult second = run_tide("run --quiet --until 0.08 --resume " + split.string());
  ASSERT_EQ(second.exit_code, 0) << second.output;
  expect_same_frames(straight, split);
}

// --checkpoint-wall 0.001: a checkpoint at the first step 1 ms of wall-clock time after the last
// one; the 125 steps take longer than that, so there is at least one besides the one at the end.
TEST_F(ResumeCommand, WallClockIntervalWritesCheckpoints) {
  const fs::path run = directory_ / "run";
  const CommandResult result = run_tide("run --quiet --checkpoint-wall 0.001 --until 0.01 --out " + run.string() + " " +
                                        write_scene("a.json").string());
  ASSERT_EQ(result.exit_code, 0) << result.output;
  const auto at = result.output.find("checkpoints ");
  ASSERT_NE(at, std::string::npos) << result.output;
  EXPECT_GE(std::stoul(result.output.substr(at + 12)), 2u) << result.output;
  EXPECT_TRUE(fs::exists(run / "checkpoint.h5"));
}

TEST_F(ResumeCommand, CheckpointOfAnotherSceneIsRefused) {
  const fs::path run = directory_ / "run";
  ASSERT_EQ(run_tide("run --quiet --checkpoint-every 0.02 --until 0.02 --out " + run.string() + " " +
                     write_scene("a.json").string())
                .exit_code,
            0);
  const CommandResult other =
      run_tide("run --quiet --resume " + run.string() + " " + write_scene("b.json", 0.3).string());
  EXPECT_EQ(other.exit_code, 2) << other.output;
  EXPECT_NE(other.output.find("checkpoint.h5: this checkpoint is of a scene with hash"), std::string::npos)
      << other.output;
}

TEST_F(ResumeCommand, MissingOrBrokenCheckpointIsRefused) {
  const fs::path run = directory_ / "run";
  fs::create_directories(run);
  const fs::path scene = write_scene("a.json");
  CommandResult result = run_tide("run --quiet --resume " + run.string() + " " + scene.string());
  EXPECT_EQ(result.exit_code, 2) << result.output;
  EXPECT_NE(result.output.find("checkpoint.h5: no checkpoint file there"), std::string::npos) << result.output;
  std::ofstream(run / "checkpoint.h5") << "not HDF5";
  result = run_tide("run --quiet --resume " + run.string() + " " + scene.string());
  EXPECT_EQ(result.exit_code, 2) << result.output;
  EXPECT_NE(result.output.find("checkpoint.h5: cannot open as an HDF5 file"), std::string::npos) << result.output;
}

// Another precision or format version, which a command cannot produce: the reader's own refusal.
TEST_F(ResumeCommand, OtherPrecisionOrFormatVersionIsRefused) {
  const fs::path file = directory_ / "checkpoint.h5";
  const io::CheckpointIdentity identity{io::checkpoint_format_version, "0123456789abcdef", "double", 2, {}};
  io::write_checkpoint(file, identity, 0, 0, StateArchive{});
  io::CheckpointIdentity float_build = identity;
  float_build.precision = "float";
  EXPECT_THROW(
      {
        try {
          io::read_checkpoint(file, float_build);
        } catch (const io::CheckpointMismatch& error) {
          EXPECT_NE(std::string(error.what()).find("precision double, not float"), std::string::npos) << error.what();
          throw;
        }
      },
      io::CheckpointMismatch);
  io::CheckpointIdentity newer = identity;
  newer.format_version = io::checkpoint_format_version + 1;
  EXPECT_THROW(io::read_checkpoint(file, newer), io::CheckpointMismatch);
  EXPECT_NO_THROW(io::read_checkpoint(file, identity));
}

}  // namespace
}  // namespace tide
