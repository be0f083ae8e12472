#pragma once

// Typed reads of scene values: each reader returns the value at a node or throws a SceneError at
// the node's key path saying what was expected there.

#include <algorithm>
#include <array>
#include <cstddef>
#include <cstdint>
#include <span>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "geometry_checks.hpp"
#include "scene_json.hpp"
#include "scene_names.hpp"
#include "scene_text.hpp"
#include "tide/core/kernels/kernel.hpp"
#include "tide/core/scene.hpp"

namespace tide::io {

struct NumberRule {
  std::string_view expected;
  bool (*accepts)(double);
};

inline constexpr NumberRule any_number{"a number", [](double) { return true; }};
inline constexpr NumberRule positive{"a number > 0", [](double x) { return x > 0; }};
inline constexpr NumberRule non_negative{"a number >= 0", [](double x) { return x >= 0; }};
inline constexpr NumberRule in_unit_interval{"a number in (0, 1]", [](double x) { return x > 0 && x <= 1; }};
inline constexpr NumberRule above_one{"a number > 1", [](double x) { return x > 1; }};

/// Iteration and step counts: at least 1, and small enough that a typo cannot stall a run.
inline constexpr std::int64_t largest_count = 1'000'000;

inline constexpr std::string_view missing_key = "nothing (the key is missing)";

class ValueReader {
 public:
  /// Messages name `file`; vectors have as many numbers as `scene` (the scene being read) has
  /// dimensions, once its dimension is read.
  ValueReader(std::string file, const scene::Scene& scene) : file_(std::move(file)), scene_(scene) {}

  /// The scene read so far.
  const scene::Scene& scene() const { return scene_; }
  int dimension() const { return scene_.dimension; }
  double spacing() const { return scene_.particle_spacing; }
  const std::string& file() const { return file_; }

  double tolerance() const { return coordinate_slack(scene_); }

  [[noreturn]] void fail(std::string path, std::string expected, std::string found) const;

  /// Fails at `node`, describing what is there.
  [[noreturn]] void fail(const Node& node, std::string expected) const;

  /// An object with no keys but `keys`.
  void expect_object(const Node& node, std::span<const std::string_view> keys) const;

  /// An array of at least `least` elements.
  std::vector<Node> elements(const Node& node, std::size_t least, std::string expected) const;

  template <class Accepts>
  double number(const Node& node, std::string_view expected, Accepts accepts) const {
    const double value = finite_number(node, expected);
    if (!accepts(value)) fail(node, std::string(expected));
    return value;
  }

  double number(const Node& node, const NumberRule& rule) const { return number(node, rule.expected, rule.accepts); }

  /// An integer in [least, most]; `expected` says so.
  std::int64_t integer(const Node& node, std::int64_t least, std::int64_t most, const std::string& expected) const;

  /// An iteration or step count in [1, largest_count].
  int count(const Node& node) const;

  bool boolean(const Node& node) const;

  /// A non-empty string.
  std::string text(const Node& node) const;

  template <class E, std::size_t N>
  E choice(const Node& node, const std::array<Named<E>, N>& names) const {
    std::array<std::string_view, N> spellings;
    std::transform(names.begin(), names.end(), spellings.begin(), [](const Named<E>& named) { return named.name; });
    const std::string expected = "one of " + quoted_list(spellings);
    const std::string& given = string_at(node, expected);
    for (const Named<E>& named : names) {
      if (named.name == given) return named.value;
    }
    fail(node, expected);
  }

  KernelType kernel_type(const Node& node) const;

  /// Exactly `dimension` numbers; a 2D vector's third component stays 0.
  scene::Vec vector(const Node& node) const;

  /// One boolean per axis.
  std::array<bool, 3> flags(const Node& node) const;

  /// The index of the material `node` names.
  std::size_t material_index(const Node& node, const std::vector<scene::Material>& materials) const;

 private:
  static bool is_finite_number(const Node& node);
  // The number at `node`, or a failure expecting `expected` where there is no finite number.
  double finite_number(const Node& node, std::string_view expected) const;
  // The string at `node`, or a failure expecting `expected` where there is none.
  const std::string& string_at(const Node& node, const std::string& expected) const;

  std::string file_;
  const scene::Scene& scene_;
};

}  // namespace tide::io
