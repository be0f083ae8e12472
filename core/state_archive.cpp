#include "tide/core/state_archive.hpp"

#include <stdexcept>
#include <utility>

namespace tide {
namespace {

template <class Map>
const auto& entry(const Map& entries, const std::string& path, const char* kind) {
  const auto found = entries.find(path);
  if (found == entries.end())
    throw std::runtime_error("the checkpoint has no " + std::string(kind) + " entry '" + path + "'");
  return found->second;
}

template <class T>
T single(std::span<const T> values, const std::string& path) {
  if (values.size() != 1)
    throw std::runtime_error("checkpoint entry '" + path + "': expected one value, found " +
                             std::to_string(values.size()));
  return values.front();
}

}  // namespace

void StateArchive::put_reals(const std::string& path, std::span<const Real> values) {
  reals_[path].assign(values.begin(), values.end());
}

void StateArchive::put_doubles(const std::string& path, std::vector<double> values) {
  doubles_[path] = std::move(values);
}

void StateArchive::put_counts(const std::string& path, std::vector<std::uint64_t> values) {
  counts_[path] = std::move(values);
}

void StateArchive::put_text(const std::string& path, std::string text) { texts_[path] = std::move(text); }

std::span<const Real> StateArchive::reals(const std::string& path) const { return entry(reals_, path, "real"); }

std::span<const double> StateArchive::doubles(const std::string& path) const { return entry(doubles_, path, "double"); }

std::span<const std::uint64_t> StateArchive::counts(const std::string& path) const {
  return entry(counts_, path, "count");
}

const std::string& StateArchive::text(const std::string& path) const { return entry(texts_, path, "text"); }

double StateArchive::double_value(const std::string& path) const { return single(doubles(path), path); }

std::uint64_t StateArchive::count_value(const std::string& path) const { return single(counts(path), path); }

}  // namespace tide
