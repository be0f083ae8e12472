#include "tide/io/probe_writer.hpp"

#include <array>
#include <charconv>
#include <stdexcept>
#include <string>
#include <utility>

#include "tide/io/atomic_file.hpp"

namespace tide::io {
namespace {

/// The shortest decimal text that reads back to the same double.
void append_number(std::string& text, double value) {
  std::array<char, 32> buffer{};
  const auto result = std::to_chars(buffer.data(), buffer.data() + buffer.size(), value);
  text.append(buffer.data(), result.ptr);
}

std::string position_text(const scene::Vec& position, int dimension) {
  std::string text = "[";
  for (int d = 0; d < dimension; ++d) {
    if (d > 0) text += ", ";
    append_number(text, position[d]);
  }
  return text + "]";
}

}  // namespace

ProbeWriter::ProbeWriter(std::filesystem::path file, const scene::Scene& scene)
    : file_(std::move(file)), probe_count_(scene.probes.size()) {
  header_ = "# TideSPH probes of scene " + scene.source + "\n";
  std::string columns = "time";
  for (const scene::Probe& probe : scene.probes) {
    const bool pressure = probe.type == scene::ProbeType::pressure;
    header_ += "# " + probe.name + (pressure ? ": pressure (Pa) at " : ": water_height (m) above ") +
               position_text(probe.position, scene.dimension) + "\n";
    columns += "," + probe.name;
  }
  header_ += columns + "\n";
}

void ProbeWriter::add(double time, const std::vector<double>& values) {
  if (values.size() != probe_count_) {
    throw std::invalid_argument(file_.string() + ": a row of " + std::to_string(values.size()) + " values for " +
                                std::to_string(probe_count_) + " probes");
  }
  append_number(rows_, time);
  for (const double value : values) {
    rows_ += ',';
    append_number(rows_, value);
  }
  rows_ += '\n';
  ++row_count_;
}

void ProbeWriter::write() const {
  if (file_.has_parent_path()) std::filesystem::create_directories(file_.parent_path());
  replace_atomically(file_,
                     [&](const std::filesystem::path& temporary) { write_text_file(temporary, header_ + rows_); });
}

}  // namespace tide::io
