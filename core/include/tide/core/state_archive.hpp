#pragma once

#include <cstdint>
#include <map>
#include <span>
#include <string>
#include <vector>

#include "tide/core/types.hpp"

namespace tide {

/// What a run keeps from one step to the next, as named arrays (a checkpoint, docs/output.md):
/// a simulation and `tide run` put what their next step reads under slash-separated paths
/// ("fluid/density") and take it back on resume. Four kinds, each stored in its own type so that
/// a value comes back with the same bits: Reals (the particle fields, float or double as the
/// build), doubles (times, the bodies' motion), counts (steps, indices) and texts.
class StateArchive {
 public:
  void put_reals(const std::string& path, std::span<const Real> values);
  void put_doubles(const std::string& path, std::vector<double> values);
  void put_counts(const std::string& path, std::vector<std::uint64_t> values);
  void put_text(const std::string& path, std::string text);
  void put_double(const std::string& path, double value) { put_doubles(path, {value}); }
  void put_count(const std::string& path, std::uint64_t value) { put_counts(path, {value}); }

  /// The entry at `path`; std::runtime_error naming the path and its kind when there is none, or
  /// (for the single values) when it holds other than one value.
  std::span<const Real> reals(const std::string& path) const;
  std::span<const double> doubles(const std::string& path) const;
  std::span<const std::uint64_t> counts(const std::string& path) const;
  const std::string& text(const std::string& path) const;
  double double_value(const std::string& path) const;
  std::uint64_t count_value(const std::string& path) const;

  /// Every entry of a kind, by path: what a checkpoint file writes.
  const std::map<std::string, std::vector<Real>>& all_reals() const { return reals_; }
  const std::map<std::string, std::vector<double>>& all_doubles() const { return doubles_; }
  const std::map<std::string, std::vector<std::uint64_t>>& all_counts() const { return counts_; }
  const std::map<std::string, std::string>& all_texts() const { return texts_; }

 private:
  std::map<std::string, std::vector<Real>> reals_;
  std::map<std::string, std::vector<double>> doubles_;
  std::map<std::string, std::vector<std::uint64_t>> counts_;
  std::map<std::string, std::string> texts_;
};

}  // namespace tide
