// The checkpoint file on its own: every kind of StateArchive entry comes back with the same bits
// at the same path, and a file that is not a checkpoint, or a damaged one, is refused with a
// std::runtime_error naming the file.

#include <gtest/gtest.h>

#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <limits>
#include <stdexcept>
#include <string>
#include <vector>

#include "tide/core/particle_set.hpp"
#include "tide/core/particle_set_state.hpp"
#include "tide/core/state_archive.hpp"
#include "tide/io/checkpoint_file.hpp"
#include "tide/io/frame_writer.hpp"

namespace tide::io {
namespace {

namespace fs = std::filesystem;

class CheckpointFile : public testing::Test {
 protected:
  void SetUp() override {
    directory_ = fs::path(testing::TempDir()) /
                 ("checkpoint_file_test_" + std::string(testing::UnitTest::GetInstance()->current_test_info()->name()));
    fs::remove_all(directory_);
    fs::create_directories(directory_);
  }
  void TearDown() override { fs::remove_all(directory_); }

  const CheckpointIdentity identity_{checkpoint_format_version, "00000000000000ff", "double", 3, "scene.json"};
  fs::path directory_;
};

std::string refusal(const fs::path& file, const CheckpointIdentity& identity) {
  try {
    read_checkpoint(file, identity);
  } catch (const std::runtime_error& error) {
    return error.what();
  }
  return "";
}

TEST_F(CheckpointFile, EveryEntryComesBackWithTheSameBits) {
  StateArchive archive;
  const std::vector<Real> reals{Real(0.1), -Real(0), std::numeric_limits<Real>::denorm_min(),
                                std::numeric_limits<Real>::infinity()};
  archive.put_reals("fluid/position", reals);
  archive.put_reals("empty", std::vector<Real>{});
  archive.put_doubles("scheme/time", {1.0 / 3, std::numeric_limits<double>::max()});
  archive.put_counts("deep/er/counts", {0, std::numeric_limits<std::uint64_t>::max()});
  archive.put_text("run/rows", std::string("a,b\n\0c", 6));
  const fs::path file = directory_ / "checkpoint.h5";
  write_checkpoint(file, identity_, 7, 0.5, archive);

  const StateArchive back = read_checkpoint(file, identity_);
  ASSERT_EQ(back.reals("fluid/position").size(), reals.size());
  EXPECT_EQ(std::memcmp(back.reals("fluid/position").data(), reals.data(), reals.size() * sizeof(Real)), 0);
  EXPECT_TRUE(back.reals("empty").empty());
  EXPECT_EQ(back.doubles("scheme/time")[0], 1.0 / 3);
  EXPECT_EQ(back.counts("deep/er/counts")[1], std::numeric_limits<std::uint64_t>::max());
  EXPECT_EQ(back.text("run/rows"), std::string("a,b\n\0c", 6));
  EXPECT_EQ(checkpoint_scene_file(file), fs::path("scene.json"));
  EXPECT_THROW(back.reals("nowhere"), std::runtime_error);
  EXPECT_FALSE(fs::exists(directory_ / ".checkpoint.h5.tmp"));
}

TEST_F(CheckpointFile, ParticleSetComesBackWithItsSizeIdsAndFields) {
  ParticleSet<2> set;
  set.append(5);
  const ScalarField density = set.add_scalar("density");
  const IndexField phase = set.add_index("phase");
  for (std::size_t i = 0; i < 5; ++i) {
    set[set.position()].set(i, Vector<2>(Real(i), Real(2 * i)));
    set[density][i] = Real(1000 + i);
    set[phase][i] = Index(i % 2);
  }
  StateArchive archive;
  save_particles(archive, "fluid", set);

  ParticleSet<2> other = set;  // the same fields, as a simulation built from the same scene has
  other.resize(2, 0);
  restore_particles(archive, "fluid", other);
  ASSERT_EQ(other.size(), 5u);
  EXPECT_EQ(other.next_id(), set.next_id());
  for (std::size_t i = 0; i < 5; ++i) {
    EXPECT_EQ(other[other.position()][i], set[set.position()][i]);
    EXPECT_EQ(other[density][i], set[density][i]);
    EXPECT_EQ(other[phase][i], set[phase][i]);
  }
}

TEST_F(CheckpointFile, FrameFileIsNotACheckpoint) {
  ParticleSet<3> set;
  set.append(3);
  FrameWriter<3> writer(directory_, {"position"});
  const fs::path frame = writer.write(set, 0, 0);
  const std::string message = refusal(frame, identity_);
  EXPECT_NE(message.find(frame.string() + ": not a TideSPH checkpoint: expected a string attribute 'format'"),
            std::string::npos)
      << message;
}

TEST_F(CheckpointFile, TruncatedCheckpointIsRefused) {
  const fs::path file = directory_ / "checkpoint.h5";
  StateArchive archive;
  archive.put_reals("fluid/position", std::vector<Real>(1000, Real(1)));
  write_checkpoint(file, identity_, 0, 0, archive);
  fs::resize_file(file, fs::file_size(file) / 2);
  const std::string message = refusal(file, identity_);
  EXPECT_NE(message.find(file.string() + ": "), std::string::npos) << message;
}

TEST_F(CheckpointFile, AnotherDimensionIsRefused) {
  const fs::path file = directory_ / "checkpoint.h5";
  write_checkpoint(file, identity_, 0, 0, StateArchive{});
  CheckpointIdentity two_d = identity_;
  two_d.dimension = 2;
  EXPECT_NE(refusal(file, two_d).find("this checkpoint is of dimension 3, not 2"), std::string::npos);
}

}  // namespace
}  // namespace tide::io
