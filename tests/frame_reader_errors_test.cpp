// read_frame on files that are not what FrameWriter writes: each one is refused with a
// std::runtime_error naming the file and what was expected, and HDF5 prints nothing.

#include <gtest/gtest.h>
#include <hdf5.h>

#include <unistd.h>
#include <array>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <functional>
#include <random>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

#include "tide/io/frame_writer.hpp"

namespace tide::io {
namespace {

namespace fs = std::filesystem;

constexpr std::size_t particle_count = 8;
constexpr const char* frame_group = "frame_000000";

/// An HDF5 identifier that closes itself; a negative one fails the test where it was made.
class Id {
 public:
  Id(hid_t id, herr_t (*closer)(hid_t)) : id_(id), closer_(closer) { EXPECT_GE(id, 0) << "an HDF5 call failed"; }
  ~Id() {
    if (id_ >= 0) closer_(id_);
  }
  Id(const Id&) = delete;
  Id& operator=(const Id&) = delete;
  operator hid_t() const { return id_; }

 private:
  hid_t id_;
  herr_t (*closer_)(hid_t);
};

/// A 2D set with a scalar, a vector and an index field besides the positions.
ParticleSet<2> small_set() {
  ParticleSet<2> set;
  set.append(particle_count);
  const auto density = set.add_scalar("density");
  const auto velocity = set.add_vector("velocity");
  const auto id = set.add_index("id");
  for (std::size_t i = 0; i < particle_count; ++i) {
    set[density][i] = Real(1000 + i);
    set[id][i] = Index(i);
    for (int d = 0; d < 2; ++d) {
      set[set.position()].component[d][i] = Real(0.1 * double(i) + d);
      set[velocity].component[d][i] = Real(d - 0.5);
    }
  }
  return set;
}

/// A dataset of doubles with the given shape (scalar for an empty one), all zero.
void add_dataset(hid_t parent, const char* name, const std::vector<hsize_t>& shape) {
  const Id space(
      shape.empty() ? H5Screate(H5S_SCALAR) : H5Screate_simple(static_cast<int>(shape.size()), shape.data(), nullptr),
      H5Sclose);
  const Id dataset(H5Dcreate2(parent, name, H5T_IEEE_F64LE, space, H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT), H5Dclose);
  std::size_t count = 1;
  for (const hsize_t extent : shape) count *= extent;
  const std::vector<double> zeros(count);
  EXPECT_GE(H5Dwrite(dataset, H5T_NATIVE_DOUBLE, H5S_ALL, H5S_ALL, H5P_DEFAULT, zeros.data()), 0);
}

/// An attribute of `count` doubles (a scalar one for count 0).
void add_number_attribute(hid_t object, const char* name, hsize_t count) {
  const Id space(count == 0 ? H5Screate(H5S_SCALAR) : H5Screate_simple(1, &count, nullptr), H5Sclose);
  const Id attribute(H5Acreate2(object, name, H5T_IEEE_F64LE, space, H5P_DEFAULT, H5P_DEFAULT), H5Aclose);
  const std::vector<double> values(count == 0 ? 1 : count, 2.5);
  EXPECT_GE(H5Awrite(attribute, H5T_NATIVE_DOUBLE, values.data()), 0);
}

/// An attribute of `count` fixed-length strings of 8 bytes (a scalar one for count 0).
void add_string_attribute(hid_t object, const char* name, hsize_t count) {
  const Id type(H5Tcopy(H5T_C_S1), H5Tclose);
  EXPECT_GE(H5Tset_size(type, 8), 0);
  const Id space(count == 0 ? H5Screate(H5S_SCALAR) : H5Screate_simple(1, &count, nullptr), H5Sclose);
  const Id attribute(H5Acreate2(object, name, type, space, H5P_DEFAULT, H5P_DEFAULT), H5Aclose);
  const std::vector<char> text(8 * (count == 0 ? 1 : count), 'x');
  EXPECT_GE(H5Awrite(attribute, type, text.data()), 0);
}

class FrameReaderErrors : public ::testing::Test {
 protected:
  void SetUp() override {
    const std::string test_name = ::testing::UnitTest::GetInstance()->current_test_info()->name();
    directory_ = fs::path(::testing::TempDir()) / ("tide_frame_reader_" + test_name + "_" + std::to_string(::getpid()));
    fs::remove_all(directory_);
    good_ = FrameWriter<2>(directory_, {"density", "velocity", "id"}).write(small_set(), 0.25, 3);
  }
  void TearDown() override { fs::remove_all(directory_); }

  /// A copy of the good frame named `name`, changed by `edit(file, frame group)` through HDF5.
  fs::path edited(const std::string& name, const std::function<void(hid_t, hid_t)>& edit) const {
    const fs::path path = directory_ / name;
    fs::copy_file(good_, path);
    const Id file(H5Fopen(path.c_str(), H5F_ACC_RDWR, H5P_DEFAULT), H5Fclose);
    const Id group(H5Gopen2(file, frame_group, H5P_DEFAULT), H5Gclose);
    edit(file, group);
    return path;
  }

  /// A file named `name` holding `bytes`.
  fs::path written(const std::string& name, const std::string& bytes) const {
    const fs::path path = directory_ / name;
    std::ofstream(path, std::ios::binary) << bytes;
    return path;
  }

  std::string good_bytes() const {
    std::ifstream in(good_, std::ios::binary);
    return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
  }

  fs::path directory_;
  fs::path good_;
};

/// read_frame(path) throws a std::runtime_error whose message names the file and contains
/// `expected`; nothing reaches stderr.
void expect_refused(const fs::path& path, std::string_view expected) {
  SCOPED_TRACE(path.filename().string());
  ::testing::internal::CaptureStderr();
  try {
    read_frame(path);
    ADD_FAILURE() << "read without error";
  } catch (const std::runtime_error& error) {
    const std::string message = error.what();
    EXPECT_NE(message.find(path.string()), std::string::npos) << message;
    EXPECT_NE(message.find(expected), std::string::npos) << message;
  }
  EXPECT_EQ(::testing::internal::GetCapturedStderr(), "");
}

TEST_F(FrameReaderErrors, TheGoodFrameReads) {
  const Frame frame = read_frame(good_);
  EXPECT_EQ(frame.group, frame_group);
  EXPECT_EQ(frame.step, 3u);
  EXPECT_EQ(frame.datasets.at("position").shape, (std::vector<std::size_t>{particle_count, 2}));
}

TEST_F(FrameReaderErrors, TruncatedFilesAreNotHdf5) {
  const std::string bytes = good_bytes();
  for (const std::size_t kept : {std::size_t{0}, std::size_t{7}, std::size_t{100}, bytes.size() / 2, bytes.size() - 1})
    expect_refused(written("truncated_" + std::to_string(kept) + ".h5", bytes.substr(0, kept)),
                   "cannot open as an HDF5 file");
}

TEST_F(FrameReaderErrors, RandomBytesAreNotHdf5) {
  std::mt19937 random(6);
  std::uniform_int_distribution<int> byte(0, 255);
  std::string noise(4096, '\0');
  for (char& c : noise) c = static_cast<char>(byte(random));
  expect_refused(written("noise.h5", noise), "cannot open as an HDF5 file");
  // HDF5's signature followed by noise: the superblock itself is garbage.
  const std::string signature = "\x89HDF\r\n\x1a\n";
  expect_refused(written("signature_then_noise.h5", signature + noise), "cannot open as an HDF5 file");
}

TEST_F(FrameReaderErrors, MissingFrameGroup) {
  expect_refused(edited("no_group.h5", [](hid_t file, hid_t) { H5Ldelete(file, frame_group, H5P_DEFAULT); }),
                 "expected one frame group at the root, found 0");
  expect_refused(edited("two_groups.h5",
                        [](hid_t file, hid_t) {
                          const Id extra(H5Gcreate2(file, "frame_000001", H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT),
                                         H5Gclose);
                        }),
                 "expected one frame group at the root, found 2");
  expect_refused(edited("dataset_for_group.h5",
                        [](hid_t file, hid_t) {
                          H5Ldelete(file, frame_group, H5P_DEFAULT);
                          add_dataset(file, frame_group, {particle_count});
                        }),
                 "/frame_000000: expected a group, found a dataset");
}

TEST_F(FrameReaderErrors, MissingTimeOrStep) {
  for (const char* name : {"time", "step"}) {
    expect_refused(edited(std::string("no_") + name + ".h5", [&](hid_t, hid_t group) { H5Adelete(group, name); }),
                   "has no '" + std::string(name) + "' attribute");
  }
}

TEST_F(FrameReaderErrors, TimeOrStepThatIsNotOneNumber) {
  for (const char* name : {"time", "step"}) {
    const std::string what = "attribute '" + std::string(name) + "' of /frame_000000: expected one number";
    expect_refused(edited(std::string("array_") + name + ".h5",
                          [&](hid_t, hid_t group) {
                            H5Adelete(group, name);
                            add_number_attribute(group, name, 64);
                          }),
                   what);
    expect_refused(edited(std::string("text_") + name + ".h5",
                          [&](hid_t, hid_t group) {
                            H5Adelete(group, name);
                            add_string_attribute(group, name, 0);
                          }),
                   what);
  }
}

TEST_F(FrameReaderErrors, ExtraAttributeThatIsNotOneString) {
  expect_refused(edited("number_attribute.h5", [](hid_t, hid_t group) { add_number_attribute(group, "scene", 0); }),
                 "attribute 'scene' of /frame_000000: expected one fixed-length string");
  expect_refused(
      edited("string_array_attribute.h5", [](hid_t, hid_t group) { add_string_attribute(group, "scene", 16); }),
      "attribute 'scene' of /frame_000000: expected one fixed-length string");
}

TEST_F(FrameReaderErrors, MissingPosition) {
  expect_refused(edited("no_position.h5", [](hid_t, hid_t group) { H5Ldelete(group, "position", H5P_DEFAULT); }),
                 "expected a dataset 'position'");
}

TEST_F(FrameReaderErrors, DatasetsOfTheWrongShape) {
  const std::array<std::pair<const char*, std::vector<hsize_t>>, 4> cases{{
      {"scalar_dataset", {}},
      {"three_dimensional", {particle_count, 2, 2}},
      {"too_few_rows", {particle_count - 1}},
      {"too_many_columns", {particle_count, 3}},
  }};
  for (const auto& [name, shape] : cases) {
    expect_refused(edited(std::string(name) + ".h5", [&](hid_t, hid_t group) { add_dataset(group, name, shape); }),
                   "dataset '" + std::string(name) + "'");
  }
  expect_refused(edited("position_with_four_columns.h5",
                        [](hid_t, hid_t group) {
                          H5Ldelete(group, "position", H5P_DEFAULT);
                          add_dataset(group, "position", {particle_count, 4});
                        }),
                 "dataset 'position'");
}

TEST_F(FrameReaderErrors, DatasetsThatDoNotHoldNumbers) {
  expect_refused(edited("text_dataset.h5",
                        [](hid_t, hid_t group) {
                          const Id type(H5Tcopy(H5T_C_S1), H5Tclose);
                          const hsize_t count = particle_count;
                          const Id space(H5Screate_simple(1, &count, nullptr), H5Sclose);
                          const Id dataset(
                              H5Dcreate2(group, "names", type, space, H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT), H5Dclose);
                        }),
                 "dataset 'names'");
  expect_refused(edited("subgroup.h5",
                        [](hid_t, hid_t group) {
                          const Id subgroup(H5Gcreate2(group, "nested", H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT),
                                            H5Gclose);
                        }),
                 "dataset 'nested' of /frame_000000: expected a dataset, found a group");
}

TEST_F(FrameReaderErrors, DatasetClaimingMoreValuesThanItStores) {
  // Shrinking a dataset's extent is allowed for chunked layouts only, so grow a contiguous one's
  // claim instead: a contiguous dataset of 2^40 rows cannot be stored in this small file.
  expect_refused(edited("huge_claim.h5",
                        [](hid_t, hid_t group) {
                          const hsize_t rows = hsize_t(1) << 40;
                          const Id space(H5Screate_simple(1, &rows, nullptr), H5Sclose);
                          const Id dataset(
                              H5Dcreate2(group, "huge", H5T_IEEE_F64LE, space, H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT),
                              H5Dclose);
                        }),
                 "dataset 'huge'");
}

}  // namespace
}  // namespace tide::io
