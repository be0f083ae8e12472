// The VTK files a frame writer writes with VtkFiles::on (docs/output.md, "VTK files"): each
// frame's .vtu file, read back by parsing its XML header and following the offsets into the raw
// appended data, holds every field bit for bit; the .pvd collection names each frame once, with
// its time, also across a continued run; and without VTK files nothing of them is written.

#include <gtest/gtest.h>

#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>
#include <string>
#include <type_traits>
#include <vector>

#include "output_directory_test.hpp"
#include "sample_particles.hpp"
#include "tide/io/frame_writer.hpp"
#include "xml_reader.hpp"

namespace tide::io {
namespace {

namespace fs = std::filesystem;
using testing_support::parse_xml_file;
using testing_support::sample_set;
using testing_support::XmlElement;
using testing_support::XmlParser;

/// One <DataArray> of a .vtu file and the bytes its offset points at.
struct VtuArray {
  std::string type;
  int components = 1;
  std::string bytes;
};

/// A .vtu file as a reader meets it: the XML header, and each array by section and name.
struct VtuFile {
  XmlElement root;
  std::map<std::string, std::map<std::string, VtuArray>> sections;  // "PointData" -> "density" -> ...
};

/// Splits the file at the '_' that opens the raw appended data, parses the XML before it (closed
/// as the file closes it) and reads each array's 64-bit length and bytes at its offset; checks that
/// the arrays fill the appended data exactly and the file ends as VTK's XML does.
VtuFile read_vtu(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream buffer;
  buffer << in.rdbuf();
  const std::string text = buffer.str();
  const std::string opening = "<AppendedData encoding=\"raw\">";
  const std::size_t underscore = text.find('_', text.find(opening));
  if (text.find(opening) == std::string::npos || underscore == std::string::npos)
    throw std::runtime_error(path.string() + ": no raw appended data");
  VtuFile file{XmlParser(text.substr(0, underscore) + "</AppendedData></VTKFile>").parse_document(), {}};
  const std::size_t data = underscore + 1;
  std::size_t end = data;
  const auto read_section = [&](const std::string& section, const XmlElement& element) {
    for (const XmlElement* array : element.all("DataArray")) {
      EXPECT_EQ(array->attribute("format"), "appended");
      const std::size_t at = data + std::stoul(array->attribute("offset"));
      std::uint64_t length = 0;
      std::memcpy(&length, text.data() + at, sizeof length);
      VtuArray read{array->attribute("type"), 1, text.substr(at + sizeof length, length)};
      if (array->attributes.contains("NumberOfComponents"))
        read.components = std::stoi(array->attribute("NumberOfComponents"));
      end = std::max<std::size_t>(end, at + sizeof length + length);
      file.sections[section][array->attribute("Name")] = read;
    }
  };
  const XmlElement& grid = file.root.only("UnstructuredGrid");
  read_section("FieldData", grid.only("FieldData"));
  const XmlElement& piece = grid.only("Piece");
  for (const char* section : {"PointData", "Points", "Cells"}) read_section(section, piece.only(section));
  EXPECT_EQ(text.substr(end), "\n  </AppendedData>\n</VTKFile>\n");
  return file;
}

template <class T>
std::string bytes_of(const std::vector<T>& values) {
  return std::string(reinterpret_cast<const char*>(values.data()), values.size() * sizeof(T));
}

template <class Dimension>
using VtkFrames = testing_support::OutputDirectoryTest<Dimension>;
TYPED_TEST_SUITE(VtkFrames, testing_support::Dimensions, testing_support::DimensionName);

TYPED_TEST(VtkFrames, EveryFieldReadsBackBitForBit) {
  constexpr int D = TestFixture::D;
  const std::vector<std::size_t> counts = {5, 9000};  // the second spans several of the writer's blocks
  const std::vector<double> times = {0.125, 1.0 / 3.0};
  FrameWriter<D> writer(this->directory, {"density", "velocity", "phase", "id", "pressure"}, "frames", VtkFiles::on);
  for (std::size_t k = 0; k < counts.size(); ++k) {
    SCOPED_TRACE("frame " + std::to_string(k));
    const ParticleSet<D> set = sample_set<D>(counts[k], int(k));
    const std::size_t n = set.size();
    writer.write(set, times[k], 40 * k + 7);
    const VtuFile file = read_vtu(this->directory / ("frames_00000" + std::to_string(k) + ".vtu"));

    EXPECT_EQ(file.root.attribute("type"), "UnstructuredGrid");
    EXPECT_EQ(file.root.attribute("header_type"), "UInt64");
    EXPECT_EQ(file.root.attribute("byte_order"), "LittleEndian");
    const XmlElement& piece = file.root.only("UnstructuredGrid").only("Piece");
    EXPECT_EQ(piece.attribute("NumberOfPoints"), std::to_string(n));
    EXPECT_EQ(piece.attribute("NumberOfCells"), std::to_string(n));

    const auto& field_data = file.sections.at("FieldData");
    EXPECT_EQ(field_data.at("TimeValue").type, "Float64");
    EXPECT_EQ(field_data.at("TimeValue").bytes, bytes_of(std::vector<double>{times[k]}));
    EXPECT_EQ(field_data.at("step").type, "UInt64");
    EXPECT_EQ(field_data.at("step").bytes, bytes_of(std::vector<std::uint64_t>{40 * k + 7}));

    const char* real_type = std::is_same_v<Real, double> ? "Float64" : "Float32";
    const auto& point_data = file.sections.at("PointData");
    EXPECT_EQ(point_data.size(), 5u);  // position is the points
    for (const char* scalar : {"density", "pressure"}) {
      const std::span<const Real> values = set[set.scalar(scalar)];
      EXPECT_EQ(point_data.at(scalar).type, real_type);
      EXPECT_EQ(point_data.at(scalar).bytes, bytes_of(std::vector<Real>(values.begin(), values.end()))) << scalar;
    }
    for (const char* index : {"phase", "id"}) {
      const std::span<const Index> values = set[set.index(index)];
      EXPECT_EQ(point_data.at(index).type, "UInt32");
      EXPECT_EQ(point_data.at(index).bytes, bytes_of(std::vector<Index>(values.begin(), values.end()))) << index;
    }
    // Vectors interleaved, D components; the points padded to three with z = 0.
    const auto interleaved = [&](const ConstVectorView<D>& view, int width) {
      std::vector<Real> values;
      for (std::size_t i = 0; i < n; ++i)
        for (int d = 0; d < width; ++d) values.push_back(d < D ? view.component[d][i] : Real(0));
      return bytes_of(values);
    };
    EXPECT_EQ(point_data.at("velocity").components, D);
    EXPECT_EQ(point_data.at("velocity").bytes, interleaved(set[set.vector("velocity")], D));
    const VtuArray& points = file.sections.at("Points").at("position");
    EXPECT_EQ(points.type, real_type);
    EXPECT_EQ(points.components, 3);
    EXPECT_EQ(points.bytes, interleaved(set[set.position()], 3));

    // Every particle a vertex cell (VTK_VERTEX = 1) of itself.
    std::vector<std::uint32_t> connectivity(n), offsets(n);
    for (std::size_t i = 0; i < n; ++i) {
      connectivity[i] = std::uint32_t(i);
      offsets[i] = std::uint32_t(i + 1);
    }
    const auto& cells = file.sections.at("Cells");
    EXPECT_EQ(cells.at("connectivity").bytes, bytes_of(connectivity));
    EXPECT_EQ(cells.at("offsets").bytes, bytes_of(offsets));
    EXPECT_EQ(cells.at("types").type, "UInt8");
    EXPECT_EQ(cells.at("types").bytes, std::string(n, '\1'));
  }
}

/// The (file, timestep) of every DataSet of a .pvd file.
std::vector<std::pair<std::string, double>> collection(const fs::path& pvd) {
  const XmlElement root = parse_xml_file(pvd);
  EXPECT_EQ(root.attribute("type"), "Collection");
  std::vector<std::pair<std::string, double>> entries;
  for (const XmlElement* dataset : root.only("Collection").all("DataSet"))
    entries.emplace_back(dataset->attribute("file"), std::stod(dataset->attribute("timestep")));
  return entries;
}

TYPED_TEST(VtkFrames, CollectionNamesEachFrameOnceAlsoWhenContinued) {
  constexpr int D = TestFixture::D;
  const std::vector<double> times = {0.0, 0.1, 0.30000000000000004, 0.4};
  std::vector<std::string> grids;
  {
    FrameWriter<D> killed(this->directory, {"density"}, "frames", VtkFiles::on);
    for (int k = 0; k < 3; ++k) killed.write(sample_set<D>(4, k), times[k], k);
    EXPECT_EQ(collection(killed.pvd_path()).size(), 3u);
    grids = killed.xdmf_grids();
  }
  // A run resumed from a checkpoint taken after frame 1 writes frame 2 again, then frame 3.
  grids.pop_back();
  FrameWriter<D> resumed(this->directory, {"density"}, "frames", VtkFiles::on);
  resumed.continue_after(grids);
  for (int k = 2; k < 4; ++k) resumed.write(sample_set<D>(4, k), times[k], k);
  const auto entries = collection(resumed.pvd_path());
  ASSERT_EQ(entries.size(), 4u);
  for (std::size_t k = 0; k < entries.size(); ++k) {
    EXPECT_EQ(entries[k].first, "frames_00000" + std::to_string(k) + ".vtu");
    EXPECT_EQ(entries[k].second, times[k]);  // exact: the shortest text that reads back the same
    EXPECT_TRUE(fs::exists(this->directory / entries[k].first));
  }
}

TYPED_TEST(VtkFrames, NoneWithoutAskingForThem) {
  constexpr int D = TestFixture::D;
  FrameWriter<D> writer(this->directory, {"density"});
  writer.write(sample_set<D>(4, 0), 0.0, 0);
  for (const auto& entry : fs::directory_iterator(this->directory)) {
    EXPECT_NE(entry.path().extension(), ".vtu");
    EXPECT_NE(entry.path().extension(), ".pvd");
  }
}

}  // namespace
}  // namespace tide::io
