#include "scene_values.hpp"

#include <cmath>
#include <nlohmann/json.hpp>

#include "tide/core/scene_error.hpp"

namespace tide::io {

void ValueReader::fail(std::string path, std::string expected, std::string found) const {
  throw scene::SceneError(file_, std::move(path), std::move(expected), std::move(found));
}

void ValueReader::fail(const Node& node, std::string expected) const {
  fail(node.path, std::move(expected), node.present() ? describe(*node.value) : std::string(missing_key));
}

void ValueReader::expect_object(const Node& node, std::span<const std::string_view> keys) const {
  if (!node.present() || !node.value->is_object()) fail(node, "an object with the keys " + quoted_list(keys));
  for (const auto& member : node.value->items()) {
    if (std::find(keys.begin(), keys.end(), member.key()) == keys.end()) {
      fail(node.path + "/" + pointer_token(member.key()), "one of the keys " + quoted_list(keys),
           "the unknown key \"" + member.key() + "\"");
    }
  }
}

std::vector<Node> ValueReader::elements(const Node& node, std::size_t least, std::string expected) const {
  if (!node.present() || !node.value->is_array() || node.value->size() < least) fail(node, std::move(expected));
  std::vector<Node> result;
  for (std::size_t i = 0; i < node.value->size(); ++i) result.push_back(element(node, i));
  return result;
}

bool ValueReader::is_finite_number(const Node& node) {
  return node.present() && node.value->is_number() && std::isfinite(node.value->get<double>());
}

std::int64_t ValueReader::integer(const Node& node, std::int64_t least, std::int64_t most,
                                  const std::string& expected) const {
  if (!node.present() || !node.value->is_number_integer()) fail(node, expected);
  // An integer above INT64_MAX is held unsigned; get<std::int64_t> would wrap it round.
  if (node.value->is_number_unsigned() && node.value->get<std::uint64_t>() > static_cast<std::uint64_t>(most))
    fail(node, expected);
  const auto value = node.value->get<std::int64_t>();
  if (value < least || value > most) fail(node, expected);
  return value;
}

int ValueReader::count(const Node& node) const {
  return static_cast<int>(integer(node, 1, largest_count, "an integer in [1, " + std::to_string(largest_count) + "]"));
}

double ValueReader::finite_number(const Node& node, std::string_view expected) const {
  if (!is_finite_number(node)) fail(node, std::string(expected));
  return node.value->get<double>();
}

const std::string& ValueReader::string_at(const Node& node, const std::string& expected) const {
  if (!node.present() || !node.value->is_string()) fail(node, expected);
  return node.value->get_ref<const std::string&>();
}

bool ValueReader::boolean(const Node& node) const {
  if (!node.present() || !node.value->is_boolean()) fail(node, "true or false");
  return node.value->get<bool>();
}

std::string ValueReader::text(const Node& node) const {
  if (!node.present() || !node.value->is_string() || node.value->get_ref<const std::string&>().empty()) {
    fail(node, "a non-empty string");
  }
  return node.value->get<std::string>();
}

KernelType ValueReader::kernel_type(const Node& node) const {
  std::array<std::string_view, all_kernel_types.size()> spellings;
  std::transform(all_kernel_types.begin(), all_kernel_types.end(), spellings.begin(), kernel_name);
  const std::string expected = "one of " + quoted_list(spellings);
  if (!node.present() || !node.value->is_string()) fail(node, expected);
  const auto type = kernel_from_name(node.value->get_ref<const std::string&>());
  if (!type) fail(node, expected);
  return *type;
}

scene::Vec ValueReader::vector(const Node& node) const {
  const std::string expected = dimension() == 2 ? "an array of 2 numbers [x, y]" : "an array of 3 numbers [x, y, z]";
  if (!node.present() || !node.value->is_array() || node.value->size() != static_cast<std::size_t>(dimension())) {
    fail(node, expected);
  }
  scene::Vec result{};
  for (int d = 0; d < dimension(); ++d) result[d] = number(element(node, d), any_number);
  return result;
}

std::array<bool, 3> ValueReader::flags(const Node& node) const {
  const std::string expected = "an array of " + std::to_string(dimension()) + " booleans, one per axis";
  if (!node.present() || !node.value->is_array() || node.value->size() != static_cast<std::size_t>(dimension())) {
    fail(node, expected);
  }
  std::array<bool, 3> result{};
  for (int d = 0; d < dimension(); ++d) result[d] = boolean(element(node, d));
  return result;
}

std::size_t ValueReader::material_index(const Node& node, const std::vector<scene::Material>& materials) const {
  std::vector<std::string_view> names;
  for (const scene::Material& material : materials) names.push_back(material.name);
  const std::string expected = "the name of a material: " + quoted_list(names);
  if (!node.present() || !node.value->is_string()) fail(node, expected);
  const auto found = std::find(names.begin(), names.end(), node.value->get_ref<const std::string&>());
  if (found == names.end()) fail(node, expected);
  return static_cast<std::size_t>(found - names.begin());
}

}  // namespace tide::io
