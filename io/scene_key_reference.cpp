#include "tide/io/scene_key_reference.hpp"

#include <algorithm>
#include <set>
#include <stdexcept>
#include <vector>

#include "scene_keys.hpp"
#include "scene_names.hpp"
#include "tide/core/kernels/kernel.hpp"

namespace tide::io {
namespace {

constexpr std::string_view open_marker = "<!-- scene keys: ";
constexpr std::string_view marker_end = " -->";
constexpr std::string_view close_marker = "<!-- end scene keys -->";

/// A table cell: '|' would end the cell.
std::string cell(std::string_view text) {
  std::string escaped;
  for (const char c : text) {
    if (c == '|') escaped += '\\';
    escaped += c;
  }
  return escaped;
}

std::string markdown_table(const SectionDoc& section) {
  std::string table = "| Key | Type | Unit | Default | Meaning |\n|---|---|---|---|---|\n";
  for (const KeyDoc& key : section.keys) {
    table += "| `" + std::string(key.name) + "` | " + cell(key.type) + " | " + cell(key.unit) + " | " +
             (key.required ? std::string("*required*") : cell(key.default_value)) + " | " + cell(key.meaning) + " |\n";
  }
  return table;
}

const SectionDoc& find_section(const std::vector<SectionDoc>& sections, std::string_view name) {
  const auto found =
      std::find_if(sections.begin(), sections.end(), [&](const SectionDoc& section) { return section.name == name; });
  if (found == sections.end()) throw std::invalid_argument("scene keys: no section \"" + std::string(name) + "\"");
  return *found;
}

template <class E, std::size_t N>
void add_names(std::vector<std::string_view>& names, const std::array<Named<E>, N>& table) {
  for (const Named<E>& named : table) names.push_back(named.name);
}

/// Every name a string value may take, in a fixed order, each once.
std::vector<std::string_view> value_names() {
  std::vector<std::string_view> names;
  for (const KernelType type : all_kernel_types) names.push_back(kernel_name(type));
  add_names(names, scheme_names);
  add_names(names, equation_of_state_names);
  add_names(names, density_method_names);
  add_names(names, viscosity_model_names);
  add_names(names, shifting_names);
  add_names(names, riemann_solver_names);
  add_names(names, surface_tension_model_names);
  add_names(names, wall_slip_names);
  add_names(names, probe_type_names);
  names.insert(names.end(), scene::output_field_names.begin(), scene::output_field_names.end());
  std::vector<std::string_view> unique;
  for (const std::string_view name : names)
    if (std::find(unique.begin(), unique.end(), name) == unique.end()) unique.push_back(name);
  return unique;
}

}  // namespace

std::string with_generated_key_tables(std::string_view markdown) {
  const std::vector<SectionDoc> sections = section_docs();
  std::set<std::string_view> shown;
  std::string result;
  std::size_t at = 0;
  while (true) {
    const std::size_t open = markdown.find(open_marker, at);
    if (open == std::string_view::npos) break;
    const std::size_t name_start = open + open_marker.size();
    const std::size_t name_end = markdown.find(marker_end, name_start);
    const std::size_t close = markdown.find(close_marker, name_start);
    if (name_end == std::string_view::npos || close == std::string_view::npos || name_end > close)
      throw std::invalid_argument("scene keys: a marker at byte " + std::to_string(open) + " is not closed");
    const SectionDoc& section = find_section(sections, markdown.substr(name_start, name_end - name_start));
    shown.insert(section.name);
    result += markdown.substr(at, name_end + marker_end.size() - at);
    result += '\n';
    result += markdown_table(section);
    at = close;
  }
  result += markdown.substr(at);
  for (const SectionDoc& section : sections) {
    if (!shown.contains(section.name))
      throw std::invalid_argument("scene keys: no marker " + std::string(open_marker) + std::string(section.name) +
                                  std::string(marker_end));
  }
  return result;
}

std::string scene_fuzz_dictionary() {
  std::string dictionary =
      "# libFuzzer dictionary for scene files (docs/scenes.md): keys, names and JSON tokens.\n"
      "# Generated from the scene reader's key tables: " +
      std::string(scene_keys_regenerate_command) + "\n# Keys\n";
  std::vector<std::string_view> keys;
  for (const SectionDoc& section : section_docs()) {
    for (const KeyDoc& key : section.keys)
      if (std::find(keys.begin(), keys.end(), key.name) == keys.end()) keys.push_back(key.name);
  }
  for (const std::string_view key : keys)
    dictionary += "key_" + std::string(key) + "=\"\\\"" + std::string(key) + "\\\":\"\n";
  dictionary += "# Names\n";
  for (const std::string_view name : value_names())
    dictionary += "name_" + std::string(name) + "=\"\\\"" + std::string(name) + "\\\"\"\n";
  dictionary += R"(# JSON tokens and numbers near the edges of what the reader accepts
true="true"
false="false"
null="null"
object_open="{"
object_close="}"
array_open="["
array_close="]"
pair_2d="[0, 1]"
pair_3d="[0, 0, 1]"
comment_line="//"
comment_block="/*"
comment_end="*/"
zero="0"
minus_one="-1"
tiny="1e-300"
huge="1e308"
minus_huge="-1e308"
too_big="1e400"
integer_max="9223372036854775807"
unsigned_max="18446744073709551615"
fraction="0.5"
)";
  return dictionary;
}

}  // namespace tide::io
