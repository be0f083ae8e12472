#include "tide/io/frame_writer.hpp"

#include <gtest/gtest.h>
#include <hdf5.h>

#include <cctype>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <map>
#include <numeric>
#include <set>
#include <sstream>
#include <stdexcept>
#include <string>
#include <string_view>
#include <type_traits>
#include <vector>

#include "output_directory_test.hpp"
#include "sample_particles.hpp"
#include "xml_reader.hpp"

namespace tide::io {
namespace {

namespace fs = std::filesystem;
using testing_support::parse_xml_file;
using testing_support::sample_set;
using testing_support::XmlElement;

// ---------------------------------------------------------------------------------------------
// Helpers.

/// An HDF5 identifier for the test's own look into the files, closed on scope exit.
struct Hdf5Object {
  hid_t id;
  herr_t (*close)(hid_t);
  ~Hdf5Object() {
    if (id >= 0) close(id);
  }
};

std::vector<std::size_t> parse_dimensions(const std::string& text) {
  std::istringstream in(text);
  std::vector<std::size_t> dimensions;
  for (std::size_t extent = 0; in >> extent;) dimensions.push_back(extent);
  return dimensions;
}

/// Opens the dataset a <DataItem> names, with HDF5 itself, and checks that its shape is both
/// `expected_shape` and the item's Dimensions, its stored type the item's NumberType/Precision,
/// and its values `expected_values` where given.
void expect_data_item_matches_dataset(const XmlElement& item, const fs::path& directory,
                                      const std::vector<std::size_t>& expected_shape,
                                      const std::vector<double>& expected_values = {}) {
  SCOPED_TRACE(item.text);
  EXPECT_EQ(item.attribute("Format"), "HDF");
  EXPECT_EQ(parse_dimensions(item.attribute("Dimensions")), expected_shape);

  const std::size_t colon = item.text.find(':');
  ASSERT_NE(colon, std::string::npos);
  const fs::path file_path = directory / item.text.substr(0, colon);
  const std::string dataset_path = item.text.substr(colon + 1);
  ASSERT_TRUE(fs::is_regular_file(file_path));

  const Hdf5Object file{H5Fopen(file_path.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT), H5Fclose};
  ASSERT_GE(file.id, 0);
  const Hdf5Object dataset{H5Dopen2(file.id, dataset_path.c_str(), H5P_DEFAULT), H5Dclose};
  ASSERT_GE(dataset.id, 0);
  const Hdf5Object space{H5Dget_space(dataset.id), H5Sclose};
  const int rank = H5Sget_simple_extent_ndims(space.id);
  ASSERT_GE(rank, 1);
  std::vector<hsize_t> dims(static_cast<std::size_t>(rank));
  H5Sget_simple_extent_dims(space.id, dims.data(), nullptr);
  EXPECT_EQ(std::vector<std::size_t>(dims.begin(), dims.end()), expected_shape);

  const Hdf5Object type{H5Dget_type(dataset.id), H5Tclose};
  const std::string& number_type = item.attribute("NumberType");
  EXPECT_EQ(std::to_string(H5Tget_size(type.id)), item.attribute("Precision"));
  if (number_type == "Float") {
    EXPECT_EQ(H5Tget_class(type.id), H5T_FLOAT);
    EXPECT_EQ(H5Tget_size(type.id), sizeof(Real)) << "frames store the build's precision";
  } else {
    ASSERT_EQ(number_type, "UInt");
    EXPECT_EQ(H5Tget_class(type.id), H5T_INTEGER);
    EXPECT_EQ(H5Tget_sign(type.id), H5T_SGN_NONE);
  }
  if (!expected_values.empty()) {
    std::vector<double> values(expected_values.size());
    ASSERT_GE(H5Dread(dataset.id, H5T_NATIVE_DOUBLE, H5S_ALL, H5S_ALL, H5P_DEFAULT, values.data()), 0);
    EXPECT_EQ(values, expected_values);
  }
}

std::set<std::string> directory_listing(const fs::path& directory) {
  std::set<std::string> names;
  for (const auto& entry : fs::directory_iterator(directory)) names.insert(entry.path().filename().string());
  return names;
}

// ---------------------------------------------------------------------------------------------
// Tests, for 2D and 3D sets.

template <class Dimension>
using FrameWriterTest = testing_support::OutputDirectoryTest<Dimension>;
TYPED_TEST_SUITE(FrameWriterTest, testing_support::Dimensions, testing_support::DimensionName);

TYPED_TEST(FrameWriterTest, XdmfNamesEveryDatasetWithItsShapeAndType) {
  constexpr int D = TestFixture::D;
  const std::vector<std::size_t> counts = {5, 7, 7};
  const std::vector<double> times = {0.0, 0.125, 1.0 / 3.0};
  FrameWriter<D> writer(this->directory, {"density", "velocity", "phase", "id"});
  for (std::size_t k = 0; k < counts.size(); ++k) writer.write(sample_set<D>(counts[k], int(k)), times[k], 40 * k);

  const XmlElement xdmf = parse_xml_file(this->directory / "frames.xdmf");
  ASSERT_EQ(xdmf.name, "Xdmf");
  EXPECT_EQ(xdmf.attribute("Version"), "3.0");
  const XmlElement& collection = xdmf.only("Domain").only("Grid");
  EXPECT_EQ(collection.attribute("GridType"), "Collection");
  EXPECT_EQ(collection.attribute("CollectionType"), "Temporal");
  const auto grids = collection.all("Grid");
  ASSERT_EQ(grids.size(), counts.size());

  for (std::size_t k = 0; k < grids.size(); ++k) {
    SCOPED_TRACE("frame " + std::to_string(k));
    const XmlElement& grid = *grids[k];
    const std::size_t n = counts[k];
    EXPECT_EQ(grid.attribute("GridType"), "Uniform");
    EXPECT_EQ(std::stod(grid.only("Time").attribute("Value")), times[k]);
    const XmlElement& topology = grid.only("Topology");
    EXPECT_EQ(topology.attribute("TopologyType"), "Polyvertex");
    EXPECT_EQ(topology.attribute("NumberOfElements"), std::to_string(n));
    std::vector<double> each_particle_a_cell(n);
    std::iota(each_particle_a_cell.begin(), each_particle_a_cell.end(), 0.0);
    expect_data_item_matches_dataset(topology.only("DataItem"), this->directory, {n}, each_particle_a_cell);

    const XmlElement& geometry = grid.only("Geometry");
    EXPECT_EQ(geometry.attribute("GeometryType"), D == 2 ? "XY" : "XYZ");
    expect_data_item_matches_dataset(geometry.only("DataItem"), this->directory, {n, D});

    std::set<std::string> named = {"position"};
    for (const XmlElement* attribute : grid.all("Attribute")) {
      const std::string& name = attribute->attribute("Name");
      named.insert(name);
      EXPECT_EQ(attribute->attribute("Center"), "Node");
      const bool is_vector = name == "velocity";
      // 2D vectors are "Matrix": XDMF's "Vector" means three components (see frame_writer.cpp).
      EXPECT_EQ(attribute->attribute("AttributeType"), !is_vector ? "Scalar" : D == 3 ? "Vector" : "Matrix") << name;
      expect_data_item_matches_dataset(attribute->only("DataItem"), this->directory,
                                       is_vector ? std::vector<std::size_t>{n, D} : std::vector<std::size_t>{n});
    }
    EXPECT_EQ(named, (std::set<std::string>{"position", "density", "velocity", "phase", "id"}));

    // ... and the frame file holds exactly the datasets the XDMF names, nothing unreferenced.
    const std::string& reference = geometry.only("DataItem").text;
    std::set<std::string> stored;
    for (const auto& [name, dataset] : read_frame(this->directory / reference.substr(0, reference.find(':'))).datasets)
      stored.insert(name);
    EXPECT_EQ(stored, named);
  }
}

TYPED_TEST(FrameWriterTest, ValuesTimeStepAndAttributesRoundTrip) {
  constexpr int D = TestFixture::D;
  constexpr std::size_t n = 6;
  const ParticleSet<D> set = sample_set<D>(n, 2);
  const double time = 1.0 / 3.0;
  const std::uint64_t step = (std::uint64_t(1) << 40) + 7;  // beyond 32 bits on purpose
  const std::map<std::string, std::string> attributes = {{"scene", "dam_break_2d.json"},
                                                         {"time_step_limit", "acoustic"}};
  FrameWriter<D> writer(this->directory, {"density", "pressure", "velocity", "phase"});
  const fs::path written = writer.write(set, time, step, attributes);
  EXPECT_EQ(written, this->directory / "frames_000000.h5");

  const Frame frame = read_frame(written);
  EXPECT_EQ(frame.group, "frame_000000");
  EXPECT_EQ(frame.time, time);
  EXPECT_EQ(frame.step, step);
  EXPECT_EQ(frame.attributes, attributes);
  ASSERT_EQ(frame.datasets.size(), 5u);

  const auto expect_scalars = [&](const std::string& name, const auto& values) {
    const FrameDataset& dataset = frame.datasets.at(name);
    ASSERT_EQ(dataset.shape, std::vector<std::size_t>{n}) << name;
    for (std::size_t i = 0; i < n; ++i) EXPECT_EQ(dataset.values[i], double(values[i])) << name << "[" << i << "]";
  };
  const auto expect_vectors = [&](const std::string& name, const auto& vectors) {
    const FrameDataset& dataset = frame.datasets.at(name);
    ASSERT_EQ(dataset.shape, (std::vector<std::size_t>{n, D})) << name;
    for (std::size_t i = 0; i < n; ++i)
      for (int d = 0; d < D; ++d)
        EXPECT_EQ(dataset.values[i * D + d], double(vectors.component[d][i])) << name << "[" << i << "][" << d << "]";
  };
  expect_scalars("density", set[set.scalar("density")]);
  expect_scalars("pressure", set[set.scalar("pressure")]);
  expect_scalars("phase", set[set.index("phase")]);
  expect_vectors("position", set[set.position()]);
  expect_vectors("velocity", set[set.vector("velocity")]);
}

TYPED_TEST(FrameWriterTest, LeavesOnlyCompleteFilesBehind) {
  constexpr int D = TestFixture::D;
  FrameWriter<D> writer(this->directory / "nested" / "out", {"density"}, "dam");
  for (int k = 0; k < 3; ++k) writer.write(sample_set<D>(4, k), 0.1 * k, std::uint64_t(k));
  EXPECT_EQ(writer.frames_written(), 3u);
  EXPECT_EQ(writer.xdmf_path(), this->directory / "nested" / "out" / "dam.xdmf");
  EXPECT_EQ(directory_listing(writer.directory()),
            (std::set<std::string>{"dam_000000.h5", "dam_000001.h5", "dam_000002.h5", "dam.xdmf"}));
}

TYPED_TEST(FrameWriterTest, FailedFrameLeavesTheXdmfNamingOnlyCompleteFrames) {
  constexpr int D = TestFixture::D;
  FrameWriter<D> writer(this->directory, {"density"});
  writer.write(sample_set<D>(3, 0), 0.0, 0);
  writer.write(sample_set<D>(3, 1), 0.5, 10);

  // A directory where the third frame's temporary file must go makes HDF5 fail to create it.
  const fs::path obstacle = this->directory / ".frames_000002.h5.tmp";
  fs::create_directory(obstacle);
  std::ofstream(obstacle / "keep") << "x";
  try {
    writer.write(sample_set<D>(3, 2), 1.0, 20);
    ADD_FAILURE() << "writing into an unwritable temporary file did not throw";
  } catch (const std::runtime_error& error) {
    EXPECT_NE(std::string(error.what()).find(".frames_000002.h5.tmp"), std::string::npos) << error.what();
  }
  EXPECT_FALSE(fs::exists(this->directory / "frames_000002.h5"));
  EXPECT_EQ(writer.frames_written(), 2u);
  EXPECT_EQ(parse_xml_file(writer.xdmf_path()).only("Domain").only("Grid").all("Grid").size(), 2u);

  fs::remove_all(obstacle);
  writer.write(sample_set<D>(3, 2), 1.0, 20);
  EXPECT_EQ(parse_xml_file(writer.xdmf_path()).only("Domain").only("Grid").all("Grid").size(), 3u);
  EXPECT_EQ(read_frame(this->directory / "frames_000002.h5").step, 20u);
}

TYPED_TEST(FrameWriterTest, UnknownFieldIsRefusedByName) {
  constexpr int D = TestFixture::D;
  FrameWriter<D> writer(this->directory, {"density", "vorticity"});
  try {
    writer.write(sample_set<D>(3, 0), 0.0, 0);
    ADD_FAILURE() << "an unknown field was written";
  } catch (const std::invalid_argument& error) {
    EXPECT_NE(std::string(error.what()).find("'vorticity'"), std::string::npos) << error.what();
  }
  EXPECT_TRUE(directory_listing(this->directory).empty());
}

TYPED_TEST(FrameWriterTest, BadRequestsAreRefused) {
  constexpr int D = TestFixture::D;
  EXPECT_THROW(FrameWriter<D>(this->directory, {"density", "density"}), std::invalid_argument);
  EXPECT_THROW(FrameWriter<D>(this->directory, {"a/b"}), std::invalid_argument);
  EXPECT_THROW(FrameWriter<D>(this->directory, {}, "run:1"), std::invalid_argument);
  FrameWriter<D> writer(this->directory, {});
  EXPECT_THROW(writer.write(sample_set<D>(2, 0), 0.0, 0, {{"time", "noon"}}), std::invalid_argument);
  EXPECT_EQ(writer.frames_written(), 0u);
}

TYPED_TEST(FrameWriterTest, DamagedFilesGiveAClearErrorNamingTheFile) {
  constexpr int D = TestFixture::D;
  FrameWriter<D> writer(this->directory, {"density", "velocity"});
  const fs::path good = writer.write(sample_set<D>(50, 0), 0.0, 0);
  const auto size = fs::file_size(good);

  std::vector<fs::path> damaged;
  for (const auto kept : {size - 1, size / 2, size / 4, decltype(size){0}}) {
    const fs::path path = this->directory / ("truncated_to_" + std::to_string(kept) + ".h5");
    fs::copy_file(good, path);
    fs::resize_file(path, kept);
    damaged.push_back(path);
  }
  std::ofstream(this->directory / "text.h5") << "not an HDF5 file\n";
  damaged.push_back(this->directory / "text.h5");
  damaged.push_back(this->directory / "missing.h5");
  {  // valid HDF5, but not a frame: no group at the root
    const fs::path path = this->directory / "foreign.h5";
    const Hdf5Object file{H5Fcreate(path.c_str(), H5F_ACC_TRUNC, H5P_DEFAULT, H5P_DEFAULT), H5Fclose};
    ASSERT_GE(file.id, 0);
    damaged.push_back(path);
  }

  for (const fs::path& path : damaged) {
    ::testing::internal::CaptureStderr();
    try {
      read_frame(path);
      ADD_FAILURE() << path << " was read without error";
    } catch (const std::runtime_error& error) {
      EXPECT_NE(std::string(error.what()).find(path.filename().string()), std::string::npos) << error.what();
    }
    EXPECT_EQ(::testing::internal::GetCapturedStderr(), "") << "HDF5 printed its error stack for " << path;
  }
}

}  // namespace
}  // namespace tide::io
