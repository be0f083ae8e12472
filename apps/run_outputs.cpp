#include "run_outputs.hpp"

#include <cstdint>
#include <span>
#include <stdexcept>

namespace tide::app {
namespace {

void save_tally(StateArchive& archive, const std::string& path, const TimeStepTally& tally) {
  archive.put_counts(path, std::vector<std::uint64_t>(tally.counts.begin(), tally.counts.end()));
}

TimeStepTally restore_tally(const StateArchive& archive, const std::string& path) {
  const std::span<const std::uint64_t> counts = archive.counts(path);
  TimeStepTally tally;
  if (counts.size() != tally.counts.size()) throw std::runtime_error("checkpoint entry '" + path + "': another length");
  for (std::size_t k = 0; k < counts.size(); ++k) tally.counts[k] = counts[k];
  return tally;
}

void save_solves(StateArchive& archive, const std::string& path, const SolveTally& tally) {
  archive.put_counts(path + "/counts",
                     {tally.solves, tally.missed, tally.iterations, static_cast<std::uint64_t>(tally.max_iterations)});
  archive.put_doubles(path + "/errors", {tally.error_sum, tally.max_error});
}

SolveTally restore_solves(const StateArchive& archive, const std::string& path) {
  const std::span<const std::uint64_t> counts = archive.counts(path + "/counts");
  const std::span<const double> errors = archive.doubles(path + "/errors");
  if (counts.size() != 4 || errors.size() != 2)
    throw std::runtime_error("checkpoint entry '" + path + "': another length");
  return {counts[0], counts[1], counts[2], static_cast<int>(counts[3]), errors[0], errors[1]};
}

}  // namespace

void RunTallies::save(StateArchive& archive, const std::string& path) const {
  save_tally(archive, path + "/run", run);
  save_tally(archive, path + "/frame", frame);
  for (const auto& [name, tallies] : {std::pair{"/run_", &run_solves}, std::pair{"/frame_", &frame_solves}}) {
    save_solves(archive, path + name + "density_solves", tallies->density);
    save_solves(archive, path + name + "divergence_solves", tallies->divergence);
  }
}

void RunTallies::restore(const StateArchive& archive, const std::string& path) {
  run = restore_tally(archive, path + "/run");
  frame = restore_tally(archive, path + "/frame");
  for (const auto& [name, tallies] : {std::pair{"/run_", &run_solves}, std::pair{"/frame_", &frame_solves}}) {
    tallies->density = restore_solves(archive, path + name + "density_solves");
    tallies->divergence = restore_solves(archive, path + name + "divergence_solves");
  }
}

void save_grids(StateArchive& archive, const std::string& path, const std::vector<std::string>& grids) {
  std::string text;
  std::vector<std::uint64_t> lengths;
  for (const std::string& grid : grids) {
    text += grid;
    lengths.push_back(grid.size());
  }
  archive.put_text(path + "/xdmf_grids", std::move(text));
  archive.put_counts(path + "/xdmf_grid_lengths", std::move(lengths));
}

std::vector<std::string> restore_grids(const StateArchive& archive, const std::string& path) {
  const std::string& text = archive.text(path + "/xdmf_grids");
  std::vector<std::string> grids;
  std::size_t offset = 0;
  for (const std::uint64_t length : archive.counts(path + "/xdmf_grid_lengths")) {
    if (length > text.size() - offset)
      throw std::runtime_error("checkpoint entry '" + path + "/xdmf_grid_lengths': longer than the grids' text");
    grids.push_back(text.substr(offset, length));
    offset += length;
  }
  return grids;
}

}  // namespace tide::app
