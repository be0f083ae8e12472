#include "tide/io/scene_reader.hpp"

#include <algorithm>
#include <array>
#include <cctype>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <fstream>
#include <initializer_list>
#include <iterator>
#include <limits>
#include <nlohmann/json.hpp>
#include <set>
#include <system_error>
#include <utility>
#include <variant>
#include <vector>

namespace tide::io {

SceneError::SceneError(std::string file, std::string key_path, std::string expected, std::string found)
    : SceneError(file + (key_path.empty() ? "" : ": " + key_path) + ": expected " + expected + ", got " + found, file,
                 key_path, expected, found, 0, 0) {}

SceneError SceneError::syntax(std::string file, std::size_t line, std::size_t column, std::string found) {
  std::string message = file + ": line " + std::to_string(line) + ", column " + std::to_string(column) +
                        ": expected valid JSON, got " + found;
  return SceneError(std::move(message), std::move(file), "", "valid JSON", std::move(found), line, column);
}

SceneError::SceneError(std::string message, std::string file, std::string key_path, std::string expected,
                       std::string found, std::size_t line, std::size_t column)
    : std::runtime_error(message),
      file_(std::move(file)),
      key_path_(std::move(key_path)),
      expected_(std::move(expected)),
      found_(std::move(found)),
      line_(line),
      column_(column) {}

namespace {

using nlohmann::json;
using scene::Vec;

constexpr std::string_view missing_key = "nothing (the key is missing)";
constexpr double standard_gravity = 9.81;  // m/s²

// ---------------------------------------------------------------------------------------------
// Text for messages

/// A value as the user wrote it (compact JSON), cut short so that a message stays one line.
std::string describe(const json& value) {
  constexpr std::size_t longest = 60;
  std::string text = value.dump();
  if (text.size() > longest) text = text.substr(0, longest) + "...";
  return text;
}

/// A number the reader computed (a bound, a derived size): six significant digits are plenty.
std::string format_number(double value) {
  std::array<char, 32> buffer{};
  std::snprintf(buffer.data(), buffer.size(), "%g", value);
  return buffer.data();
}

std::string format_vector(const Vec& v, int dimension) {
  std::string text = "[";
  for (int d = 0; d < dimension; ++d) text += (d > 0 ? ", " : "") + format_number(v[d]);
  return text + "]";
}

std::string format_box(const scene::Box& box, int dimension) {
  std::string text;
  for (int d = 0; d < dimension; ++d) {
    text += (d > 0 ? " x [" : "[") + format_number(box.min[d]) + ", " + format_number(box.max[d]) + "]";
  }
  return text;
}

std::string format_shape(const std::variant<scene::Box, scene::Ball>& shape, int dimension) {
  if (const auto* box = std::get_if<scene::Box>(&shape)) return "the box " + format_box(*box, dimension);
  const auto& ball = std::get<scene::Ball>(shape);
  return "the ball of centre " + format_vector(ball.centre, dimension) + " and radius " + format_number(ball.radius);
}

/// "[d]", built by appending: GCC 12 warns falsely (-Wrestrict) on "[" + std::to_string(d).
std::string axis_index(int d) {
  std::string text = "[";
  text += std::to_string(d);
  text += ']';
  return text;
}

template <class Names>
std::string quoted_list(const Names& names) {
  std::string text;
  for (const std::string_view name : names) text += (text.empty() ? "\"" : ", \"") + std::string(name) + "\"";
  return text;
}

/// A key as one JSON pointer token (RFC 6901): '~' and '/' are escaped.
std::string pointer_token(std::string_view key) {
  std::string token;
  for (const char c : key) {
    if (c == '~') {
      token += "~0";
    } else if (c == '/') {
      token += "~1";
    } else {
      token += c;
    }
  }
  return token;
}

// ---------------------------------------------------------------------------------------------
// Parsing the text

/// nlohmann::json keeps only the last of two equal keys in an object, without a word. In a scene
/// that is an editing mistake (two "solver" blocks, one of them ignored), so the parser's
/// callback refuses it. It follows the path of the value being read, for the message.
/// It also refuses nesting deeper than max_nesting: a scene needs 6 levels, and describing a
/// value nested thousands deep in a message (json::dump recurses) would overflow the stack.
class DuplicateKeyGuard {
 public:
  static constexpr std::size_t max_nesting = 64;

  explicit DuplicateKeyGuard(const std::string& file) : file_(file) {}

  void on_event(json::parse_event_t event, const json& parsed) {
    switch (event) {
      case json::parse_event_t::object_start:
      case json::parse_event_t::array_start:
        if (open_.size() == max_nesting) {
          throw SceneError(file_, current_path(),
                           "at most " + std::to_string(max_nesting) + " levels of nested arrays and objects",
                           "deeper nesting");
        }
        open_.emplace_back();
        open_.back().is_array = event == json::parse_event_t::array_start;
        break;
      case json::parse_event_t::key:
        on_key(parsed.get<std::string>());
        break;
      case json::parse_event_t::object_end:
      case json::parse_event_t::array_end:
        open_.pop_back();
        finish_value();
        break;
      case json::parse_event_t::value:
        finish_value();
        break;
    }
  }

 private:
  /// An object or array whose end the parser has not reached yet.
  struct OpenContainer {
    bool is_array = false;
    std::size_t index = 0;  // of the element being read, in an array
    std::string key;        // of the member being read, in an object
    std::set<std::string> keys;
  };

  void on_key(std::string key) {
    OpenContainer& object = open_.back();
    object.key = std::move(key);
    if (!object.keys.insert(object.key).second) {
      throw SceneError(file_, current_path(), "each key at most once in an object",
                       "\"" + object.key + "\" a second time");
    }
  }

  void finish_value() {
    if (!open_.empty() && open_.back().is_array) ++open_.back().index;
  }

  std::string current_path() const {
    std::string path;
    for (const OpenContainer& container : open_) {
      path += "/" + (container.is_array ? std::to_string(container.index) : pointer_token(container.key));
    }
    return path;
  }

  const std::string& file_;
  std::vector<OpenContainer> open_;
};

/// nlohmann's message without its "[json.exception.parse_error.101] parse error at line L,
/// column C: " prefix, which the SceneError's own location replaces.
std::string error_detail(const json::exception& error) {
  const std::string message = error.what();
  const std::size_t id_end = message.find("] ");
  const std::size_t start = id_end == std::string::npos ? 0 : id_end + 2;
  const std::size_t column = message.find("column ", start);
  const std::size_t detail = column == std::string::npos ? column : message.find(": ", column);
  return detail == std::string::npos ? message.substr(start) : message.substr(detail + 2);
}

json parse_json(std::string_view text, const std::string& file) {
  DuplicateKeyGuard guard(file);
  const json::parser_callback_t callback = [&guard](int, json::parse_event_t event, json& parsed) {
    guard.on_event(event, parsed);
    return true;
  };
  try {
    return json::parse(text.begin(), text.end(), callback, /*allow_exceptions=*/true, /*ignore_comments=*/true);
  } catch (const json::parse_error& error) {
    // error.byte counts the characters read, the offending one included.
    const std::string_view before = text.substr(0, error.byte > 0 ? std::min(error.byte - 1, text.size()) : 0);
    const std::size_t line = 1 + static_cast<std::size_t>(std::count(before.begin(), before.end(), '\n'));
    const std::size_t line_start = before.rfind('\n') == std::string_view::npos ? 0 : before.rfind('\n') + 1;
    throw SceneError::syntax(file, line, before.size() - line_start + 1, error_detail(error));
  } catch (const json::out_of_range& error) {
    // A number too large for a double is refused by the parser with no position.
    throw SceneError(file, "", "valid JSON", error_detail(error));
  }
}

// ---------------------------------------------------------------------------------------------
// Checking the document

/// A JSON value with its JSON pointer from the document root.
struct Node {
  const json* value = nullptr;  // null where the key is absent
  std::string path;

  bool present() const { return value != nullptr; }
};

/// `object` must be a checked object.
Node child(const Node& object, std::string_view key) {
  const auto member = object.value->find(std::string(key));
  return {member == object.value->end() ? nullptr : &*member, object.path + "/" + pointer_token(key)};
}

/// `array` must be a checked array.
Node element(const Node& array, std::size_t index) {
  return {&(*array.value)[index], array.path + "/" + std::to_string(index)};
}

struct NumberRule {
  std::string_view expected;
  bool (*accepts)(double);
};

constexpr NumberRule any_number{"a number", [](double) { return true; }};
constexpr NumberRule positive{"a number > 0", [](double x) { return x > 0; }};
constexpr NumberRule non_negative{"a number >= 0", [](double x) { return x >= 0; }};
constexpr NumberRule in_unit_interval{"a number in (0, 1]", [](double x) { return x > 0 && x <= 1; }};
constexpr NumberRule above_one{"a number > 1", [](double x) { return x > 1; }};

/// An enumerator with its spelling in scene files.
template <class E>
struct Named {
  std::string_view name;
  E value;
};

constexpr std::array<Named<scene::Scheme>, 3> scheme_names{
    {{"wcsph", scene::Scheme::wcsph}, {"dfsph", scene::Scheme::dfsph}, {"iisph", scene::Scheme::iisph}}};

/// Iteration and step counts: at least 1, and small enough that a typo cannot stall a run.
constexpr std::int64_t largest_count = 1'000'000;
constexpr std::array<Named<scene::EquationOfState>, 2> equation_of_state_names{
    {{"tait", scene::EquationOfState::tait}, {"linear", scene::EquationOfState::linear}}};
constexpr std::array<Named<scene::DensityMethod>, 2> density_method_names{
    {{"summation", scene::DensityMethod::summation}, {"continuity", scene::DensityMethod::continuity}}};
constexpr std::array<Named<scene::ViscosityModel>, 2> viscosity_model_names{
    {{"artificial", scene::ViscosityModel::artificial}, {"laminar", scene::ViscosityModel::laminar}}};
constexpr std::array<Named<scene::Shifting>, 2> shifting_names{
    {{"none", scene::Shifting::none}, {"fickian", scene::Shifting::fickian}}};
constexpr std::array<Named<scene::SurfaceTensionModel>, 3> surface_tension_model_names{
    {{"csf", scene::SurfaceTensionModel::csf},
     {"akinci", scene::SurfaceTensionModel::akinci},
     {"pairwise", scene::SurfaceTensionModel::pairwise}}};
constexpr std::array<Named<scene::WallSlip>, 2> wall_slip_names{
    {{"no_slip", scene::WallSlip::no_slip}, {"free_slip", scene::WallSlip::free_slip}}};
constexpr std::array<Named<scene::ProbeType>, 2> probe_type_names{
    {{"pressure", scene::ProbeType::pressure}, {"water_height", scene::ProbeType::water_height}}};

Vec default_gravity(int dimension) {
  Vec gravity{};
  gravity[dimension - 1] = -standard_gravity;  // up is the last axis
  return gravity;
}

// The solver places particles at anchor + (k + 1/2)·spacing on every axis (see
// solvers/particle_sampling.hpp); a fluid block holding none of those points would be silently
// empty, so the reader finds one. The loops try three steps from the point just below `lower`
// instead of stepping k: 2^53 spacings or more from the anchor, k + 1 == k and they would not end.

bool axis_holds_lattice_point(double anchor, double spacing, double lower, double upper) {
  const double first = std::floor((lower - anchor) / spacing - 0.5);
  for (int step = 0; step <= 2; ++step) {
    const double point = anchor + (first + step + 0.5) * spacing;
    if (point >= lower && point < upper) return true;
  }
  return false;
}

/// For a range [lower, upper) at most two spacings wide.
std::vector<double> lattice_points_between(double anchor, double spacing, double lower, double upper) {
  std::vector<double> points;
  const double first = std::floor((lower - anchor) / spacing - 0.5);
  for (int step = 0; step <= 2; ++step) {
    const double point = anchor + (first + step + 0.5) * spacing;
    if (point >= lower && point < upper) points.push_back(point);
  }
  return points;
}

bool holds_lattice_point(const scene::Box& box, const Vec& anchor, double spacing, int dimension) {
  for (int d = 0; d < dimension; ++d) {
    if (!axis_holds_lattice_point(anchor[d], spacing, box.min[d], box.max[d])) return false;
  }
  return true;
}

bool holds_lattice_point(const scene::Ball& ball, const Vec& anchor, double spacing, int dimension) {
  // Every point of space lies within half a cell diagonal of a lattice point.
  const double half_diagonal = 0.5 * spacing * std::sqrt(static_cast<double>(dimension));
  if (ball.radius > half_diagonal * (1 + 1e-9)) return true;
  // A smaller ball spans at most two lattice points per axis: try them all.
  std::array<std::vector<double>, 3> candidates{std::vector<double>{0}, std::vector<double>{0}, std::vector<double>{0}};
  for (int d = 0; d < dimension; ++d) {
    candidates[d] =
        lattice_points_between(anchor[d], spacing, ball.centre[d] - ball.radius, ball.centre[d] + ball.radius);
  }
  for (const double x : candidates[0]) {
    for (const double y : candidates[1]) {
      for (const double z : candidates[2]) {
        const double dx = x - ball.centre[0], dy = y - ball.centre[1], dz = z - ball.centre[2];
        if (dx * dx + dy * dy + dz * dz < ball.radius * ball.radius) return true;
      }
    }
  }
  return false;
}

/// Reads a parsed document into a scene, refusing the first thing that is wrong.
class SceneParser {
 public:
  explicit SceneParser(std::string file) : file_(std::move(file)) {}

  scene::Scene parse(const json& document) {
    const Node root{&document, ""};
    expect_object(root, {"dimension", "particle_spacing", "kernel", "domain", "materials", "fluid", "walls", "gravity",
                         "solver", "time", "output", "probes"});
    scene::Scene scene;
    scene.source = file_;
    scene.dimension = dimension_ = read_dimension(child(root, "dimension"));
    scene.particle_spacing = spacing_ = number(child(root, "particle_spacing"), positive);
    if (const Node kernel = child(root, "kernel"); kernel.present()) read_kernel(kernel, scene);
    scene.walls.layers = scene::required_wall_layers(scene.kernel, scene.smoothing_ratio);
    scene.materials = read_materials(child(root, "materials"));
    scene.fluid = read_fluid(child(root, "fluid"), scene.materials);
    if (const Node walls = child(root, "walls"); walls.present()) read_walls(walls, scene);
    scene.domain = read_domain(child(root, "domain"), scene.walls, scene.materials);
    scene.gravity = default_gravity(dimension_);
    read_optional(root, "gravity", scene.gravity);
    if (const Node solver = child(root, "solver"); solver.present()) read_solver(solver, scene.solver);
    scene.time = read_time(child(root, "time"));
    scene.output.probe_interval = scene.time.output_interval;
    if (const Node output = child(root, "output"); output.present()) read_output(output, scene);
    if (const Node probes = child(root, "probes"); probes.present()) scene.probes = read_probes(probes, scene.domain);
    check_geometry(scene);
    check_phases(scene);
    if (scene.domain.inflow && scene.solver.scheme != scene::Scheme::wcsph)
      fail("/solver/scheme", "\"wcsph\" with a domain inflow",
           "\"" + std::string(scheme_names[static_cast<std::size_t>(scene.solver.scheme)].name) + "\"");
    return scene;
  }

 private:
  [[noreturn]] void fail(std::string path, std::string expected, std::string found) const {
    throw SceneError(file_, std::move(path), std::move(expected), std::move(found));
  }

  /// Fails at `node`, describing what is there.
  [[noreturn]] void fail(const Node& node, std::string expected) const {
    fail(node.path, std::move(expected), node.present() ? describe(*node.value) : std::string(missing_key));
  }

  // --- Values. Each reader fails with its expectation where the value is absent or wrong.

  /// An object with no keys but `keys`.
  void expect_object(const Node& node, std::initializer_list<std::string_view> keys) const {
    if (!node.present() || !node.value->is_object()) fail(node, "an object with the keys " + quoted_list(keys));
    for (const auto& member : node.value->items()) {
      if (std::find(keys.begin(), keys.end(), member.key()) == keys.end()) {
        fail(node.path + "/" + pointer_token(member.key()), "one of the keys " + quoted_list(keys),
             "the unknown key \"" + member.key() + "\"");
      }
    }
  }

  /// An array of at least `least` elements.
  std::vector<Node> elements(const Node& node, std::size_t least, std::string expected) const {
    if (!node.present() || !node.value->is_array() || node.value->size() < least) fail(node, std::move(expected));
    std::vector<Node> result;
    for (std::size_t i = 0; i < node.value->size(); ++i) result.push_back(element(node, i));
    return result;
  }

  template <class Accepts>
  double number(const Node& node, std::string_view expected, Accepts accepts) const {
    const bool is_finite_number = node.present() && node.value->is_number() && std::isfinite(node.value->get<double>());
    if (!is_finite_number || !accepts(node.value->get<double>())) fail(node, std::string(expected));
    return node.value->get<double>();
  }

  double number(const Node& node, const NumberRule& rule) const { return number(node, rule.expected, rule.accepts); }

  int read_dimension(const Node& node) const {
    if (!node.present() || !node.value->is_number_integer()) fail(node, "2 or 3");
    const auto dimension = node.value->get<std::int64_t>();
    if (dimension != 2 && dimension != 3) fail(node, "2 or 3");
    return static_cast<int>(dimension);
  }

  bool boolean(const Node& node) const {
    if (!node.present() || !node.value->is_boolean()) fail(node, "true or false");
    return node.value->get<bool>();
  }

  std::string text(const Node& node) const {
    if (!node.present() || !node.value->is_string() || node.value->get_ref<const std::string&>().empty()) {
      fail(node, "a non-empty string");
    }
    return node.value->get<std::string>();
  }

  template <class E, std::size_t N>
  E choice(const Node& node, const std::array<Named<E>, N>& names) const {
    std::array<std::string_view, N> spellings;
    std::transform(names.begin(), names.end(), spellings.begin(), [](const Named<E>& named) { return named.name; });
    const std::string expected = "one of " + quoted_list(spellings);
    if (!node.present() || !node.value->is_string()) fail(node, expected);
    for (const Named<E>& named : names) {
      if (named.name == node.value->get_ref<const std::string&>()) return named.value;
    }
    fail(node, expected);
  }

  KernelType kernel_type(const Node& node) const {
    std::array<std::string_view, all_kernel_types.size()> spellings;
    std::transform(all_kernel_types.begin(), all_kernel_types.end(), spellings.begin(), kernel_name);
    const std::string expected = "one of " + quoted_list(spellings);
    if (!node.present() || !node.value->is_string()) fail(node, expected);
    const auto type = kernel_from_name(node.value->get_ref<const std::string&>());
    if (!type) fail(node, expected);
    return *type;
  }

  /// Exactly `dimension` numbers; a 2D vector's third component stays 0.
  Vec vector(const Node& node) const {
    const std::string expected = dimension_ == 2 ? "an array of 2 numbers [x, y]" : "an array of 3 numbers [x, y, z]";
    if (!node.present() || !node.value->is_array() || node.value->size() != static_cast<std::size_t>(dimension_)) {
      fail(node, expected);
    }
    Vec result{};
    for (int d = 0; d < dimension_; ++d) result[d] = number(element(node, d), any_number);
    return result;
  }

  std::array<bool, 3> flags(const Node& node) const {
    const std::string expected = "an array of " + std::to_string(dimension_) + " booleans, one per axis";
    if (!node.present() || !node.value->is_array() || node.value->size() != static_cast<std::size_t>(dimension_)) {
      fail(node, expected);
    }
    std::array<bool, 3> result{};
    for (int d = 0; d < dimension_; ++d) result[d] = boolean(element(node, d));
    return result;
  }

  // Optional keys keep the model's default where they are absent.

  void read_optional(const Node& object, std::string_view key, double& target, const NumberRule& rule) const {
    if (const Node node = child(object, key); node.present()) target = number(node, rule);
  }

  void read_optional(const Node& object, std::string_view key, bool& target) const {
    if (const Node node = child(object, key); node.present()) target = boolean(node);
  }

  void read_optional(const Node& object, std::string_view key, Vec& target) const {
    if (const Node node = child(object, key); node.present()) target = vector(node);
  }

  void read_optional(const Node& object, std::string_view key, int& target) const {
    const Node node = child(object, key);
    if (!node.present()) return;
    const std::string expected = "an integer in [1, " + std::to_string(largest_count) + "]";
    if (!node.value->is_number_integer()) fail(node, expected);
    const auto count = node.value->get<std::int64_t>();
    if (count < 1 || count > largest_count) fail(node, expected);
    target = static_cast<int>(count);
  }

  template <class E, std::size_t N>
  void read_optional(const Node& object, std::string_view key, E& target, const std::array<Named<E>, N>& names) const {
    if (const Node node = child(object, key); node.present()) target = choice(node, names);
  }

  // --- Shapes

  /// The "min" and "max" corners of an object already checked for its keys.
  scene::Box corners(const Node& object) const {
    const scene::Box box{vector(child(object, "min")), vector(child(object, "max"))};
    for (int d = 0; d < dimension_; ++d) {
      if (!(box.max[d] > box.min[d])) {
        fail(element(child(object, "max"), d),
             "a number > min" + axis_index(d) + " (" + format_number(box.min[d]) + ")");
      }
    }
    return box;
  }

  scene::Box read_box(const Node& node) const {
    expect_object(node, {"min", "max"});
    return corners(node);
  }

  scene::Ball read_ball(const Node& node) const {
    expect_object(node, {"centre", "radius"});
    return {vector(child(node, "centre")), number(child(node, "radius"), positive)};
  }

  scene::Plane read_plane(const Node& node) const {
    expect_object(node, {"point", "normal"});
    const Node normal = child(node, "normal");
    const scene::Plane plane{vector(child(node, "point")), vector(normal)};
    if (plane.normal == Vec{}) fail(normal, "a non-zero vector");
    return plane;
  }

  /// The one key of `object` among `shapes`.
  std::string_view shape_key(const Node& object, std::initializer_list<std::string_view> shapes) const {
    std::vector<std::string_view> given;
    std::copy_if(shapes.begin(), shapes.end(), std::back_inserter(given),
                 [&](std::string_view shape) { return child(object, shape).present(); });
    if (given.size() != 1) {
      fail(object.path, "exactly one shape key of " + quoted_list(shapes), given.empty() ? "none" : quoted_list(given));
    }
    return given.front();
  }

  // --- Sections

  void read_kernel(const Node& node, scene::Scene& scene) const {
    expect_object(node, {"type", "smoothing_ratio"});
    if (const Node type = child(node, "type"); type.present()) scene.kernel = kernel_type(type);
    // The wall layers this ratio needs, ceil(support / spacing), are counted in an int.
    const double support = static_cast<double>(kernel_support_factor(scene.kernel));
    const double most_layers = std::numeric_limits<int>::max();
    if (const Node ratio = child(node, "smoothing_ratio"); ratio.present()) {
      scene.smoothing_ratio = number(ratio, "a number > 0 and < " + format_number(most_layers / support),
                                     [&](double x) { return x > 0 && support * x < most_layers; });
    }
  }

  std::vector<scene::Material> read_materials(const Node& node) const {
    std::vector<scene::Material> materials;
    for (const Node& entry : elements(node, 1, "a non-empty array of materials")) {
      materials.push_back(read_material(entry, materials));
    }
    return materials;
  }

  scene::Material read_material(const Node& node, const std::vector<scene::Material>& earlier) const {
    expect_object(node, {"name", "rest_density", "kinematic_viscosity", "sound_speed", "max_speed"});
    scene::Material material;
    const Node name = child(node, "name");
    material.name = text(name);
    const auto same_name = [&](const scene::Material& other) { return other.name == material.name; };
    if (std::any_of(earlier.begin(), earlier.end(), same_name)) fail(name, "a name no earlier material has");
    read_optional(node, "rest_density", material.rest_density, positive);
    read_optional(node, "kinematic_viscosity", material.kinematic_viscosity, non_negative);
    // The speed of sound is either given or derived from the expected maximum speed, never both.
    const Node sound_speed = child(node, "sound_speed");
    const Node max_speed = child(node, "max_speed");
    if (sound_speed.present() == max_speed.present()) {
      fail(node.path, "exactly one of \"sound_speed\" and \"max_speed\"", sound_speed.present() ? "both" : "neither");
    }
    if (sound_speed.present()) {
      material.sound_speed = number(sound_speed, positive);
    } else {
      material.max_speed = number(max_speed, positive);
    }
    return material;
  }

  std::vector<scene::FluidBlock> read_fluid(const Node& node, const std::vector<scene::Material>& materials) const {
    std::vector<scene::FluidBlock> fluid;
    for (const Node& entry : elements(node, 1, "a non-empty array of fluid blocks")) {
      expect_object(entry, {"material", "box", "ball", "velocity"});
      scene::FluidBlock block;
      block.material = material_index(child(entry, "material"), materials);
      const std::string_view shape = shape_key(entry, {"box", "ball"});
      if (shape == "box") {
        block.shape = read_box(child(entry, shape));
      } else {
        block.shape = read_ball(child(entry, shape));
      }
      if (const Node velocity = child(entry, "velocity"); velocity.present())
        block.velocity = initial_velocity(velocity);
      fluid.push_back(block);
    }
    return fluid;
  }

  /// A uniform velocity [vx, vy(, vz)] or a named field: {"taylor_green": {...}} or
  /// {"rotation": {...}}, both two-dimensional.
  std::variant<Vec, scene::TaylorGreenVelocity, scene::RigidRotation> initial_velocity(const Node& node) const {
    if (node.value->is_array()) return vector(node);
    const std::string expected = "a velocity array of " + std::to_string(dimension_) +
                                 " numbers, {\"taylor_green\": {...}} or {\"rotation\": {...}}";
    if (!node.value->is_object()) fail(node, expected);
    expect_object(node, {"taylor_green", "rotation"});
    if (node.value->size() != 1) fail(node, expected);
    if (const Node field = child(node, "rotation"); field.present()) {
      if (dimension_ != 2) fail(field, "a 2D scene (the rotation field turns about the z axis)");
      expect_object(field, {"centre", "angular_velocity"});
      scene::RigidRotation rotation;
      rotation.centre = vector(child(field, "centre"));
      read_optional(field, "angular_velocity", rotation.angular_velocity, any_number);
      return rotation;
    }
    const Node field = child(node, "taylor_green");
    if (dimension_ != 2) fail(field, "a 2D scene (the Taylor-Green field is two-dimensional)");
    expect_object(field, {"amplitude", "length"});
    scene::TaylorGreenVelocity taylor_green;
    read_optional(field, "amplitude", taylor_green.amplitude, positive);
    read_optional(field, "length", taylor_green.length, positive);
    return taylor_green;
  }

  std::size_t material_index(const Node& node, const std::vector<scene::Material>& materials) const {
    std::vector<std::string_view> names;
    for (const scene::Material& material : materials) names.push_back(material.name);
    const std::string expected = "the name of a material: " + quoted_list(names);
    if (!node.present() || !node.value->is_string()) fail(node, expected);
    const auto found = std::find(names.begin(), names.end(), node.value->get_ref<const std::string&>());
    if (found == names.end()) fail(node, expected);
    return static_cast<std::size_t>(found - names.begin());
  }

  void read_walls(const Node& node, scene::Scene& scene) const {
    expect_object(node, {"layers", "slip", "container", "obstacles"});
    scene::Walls& walls = scene.walls;
    if (const Node layers = child(node, "layers"); layers.present()) {
      walls.layers = read_layers(layers, scene);
    }
    read_optional(node, "slip", walls.slip, wall_slip_names);
    if (const Node container = child(node, "container"); container.present()) {
      expect_object(container, {"min", "max", "open_top"});
      walls.container = scene::Container{corners(container)};
      read_optional(container, "open_top", walls.container->open_top);
    }
    if (const Node obstacles = child(node, "obstacles"); obstacles.present()) {
      for (const Node& entry : elements(obstacles, 0, "an array of obstacles")) {
        walls.obstacles.push_back(read_obstacle(entry));
      }
    }
  }

  /// Fewer layers than the kernel support leave a fluid particle at a wall with a truncated
  /// kernel: the wall lets fluid through or pushes it too weakly.
  int read_layers(const Node& node, const scene::Scene& scene) const {
    const int least = scene::required_wall_layers(scene.kernel, scene.smoothing_ratio);
    const double support_in_spacings = static_cast<double>(kernel_support_factor(scene.kernel)) * scene.smoothing_ratio;
    const std::string expected = "an integer >= " + std::to_string(least) + " (ceil(kernel support / spacing), " +
                                 "the support being " + format_number(support_in_spacings) + " spacings)";
    if (!node.present() || !node.value->is_number_integer()) fail(node, expected);
    const auto layers = node.value->get<std::int64_t>();
    if (layers < least || layers > std::numeric_limits<int>::max()) fail(node, expected);
    return static_cast<int>(layers);
  }

  scene::Obstacle read_obstacle(const Node& node) const {
    expect_object(node, {"box", "ball", "plane", "velocity", "slip"});
    scene::Obstacle obstacle;
    const std::string_view shape = shape_key(node, {"box", "ball", "plane"});
    if (shape == "box") {
      obstacle.shape = read_box(child(node, shape));
    } else if (shape == "ball") {
      obstacle.shape = read_ball(child(node, shape));
    } else {
      obstacle.shape = read_plane(child(node, shape));
    }
    read_optional(node, "velocity", obstacle.velocity);
    if (const Node slip = child(node, "slip"); slip.present()) obstacle.slip = choice(slip, wall_slip_names);
    return obstacle;
  }

  scene::Domain read_domain(const Node& node, const scene::Walls& walls,
                            const std::vector<scene::Material>& materials) const {
    if (!node.present()) {
      if (!walls.container) {
        fail(node,
             "an object with the keys \"min\", \"max\", \"periodic\" (only a scene with a wall container, "
             "from which the domain is derived, may leave it out)");
      }
      return scene::domain_around(*walls.container, walls.layers * spacing_, dimension_);
    }
    expect_object(node, {"min", "max", "periodic", "inflow"});
    scene::Domain domain{corners(node)};
    if (const Node periodic = child(node, "periodic"); periodic.present()) domain.periodic = flags(periodic);
    if (const Node inflow = child(node, "inflow"); inflow.present())
      domain.inflow = read_inflow(inflow, domain, materials);
    return domain;
  }

  /// Pseudo-periodic inflow/outflow: needs x periodic and a buffer shorter than the domain; with
  /// `phase`, the fluid re-enters as that material.
  scene::Inflow read_inflow(const Node& node, const scene::Domain& domain,
                            const std::vector<scene::Material>& materials) const {
    expect_object(node, {"velocity", "length", "phase"});
    if (!domain.periodic[0])
      fail(node, "no inflow unless the x axis is periodic (\"periodic\": [true, ...]): the outflow re-enters there");
    scene::Inflow inflow;
    inflow.velocity = number(child(node, "velocity"), any_number);
    const double width = domain.box.max[0] - domain.box.min[0];
    inflow.length =
        number(child(node, "length"), "a number > 0 and < the domain's length along x (" + format_number(width) + ")",
               [&](double length) { return length > 0 && length < width; });
    if (const Node phase = child(node, "phase"); phase.present()) inflow.phase = material_index(phase, materials);
    return inflow;
  }

  void read_solver(const Node& node, scene::Solver& solver) const {
    expect_object(node, {"scheme",
                         "equation_of_state",
                         "tait_exponent",
                         "density",
                         "delta_sph",
                         "viscosity",
                         "alpha",
                         "beta",
                         "cfl",
                         "viscous_number",
                         "force_number",
                         "max_density_ratio",
                         "clamp_negative_pressure",
                         "gravity_ramp_time",
                         "background_pressure",
                         "shifting",
                         "artificial_stress",
                         "neighbor_skin",
                         "max_mach_number",
                         "max_density_error",
                         "max_divergence_error",
                         "max_solver_iterations",
                         "max_failed_solves",
                         "surface_tension"});
    read_optional(node, "scheme", solver.scheme, scheme_names);
    read_optional(node, "equation_of_state", solver.equation_of_state, equation_of_state_names);
    read_optional(node, "tait_exponent", solver.tait_exponent, positive);
    read_optional(node, "density", solver.density, density_method_names);
    read_optional(node, "delta_sph", solver.delta_sph, non_negative);
    read_optional(node, "viscosity", solver.viscosity, viscosity_model_names);
    read_optional(node, "alpha", solver.alpha, non_negative);
    read_optional(node, "beta", solver.beta, non_negative);
    read_optional(node, "cfl", solver.cfl, positive);
    read_optional(node, "viscous_number", solver.viscous_number, positive);
    read_optional(node, "force_number", solver.force_number, positive);
    read_optional(node, "max_density_ratio", solver.max_density_ratio, above_one);
    read_optional(node, "max_mach_number", solver.max_mach_number, positive);
    if (const Node clamp = child(node, "clamp_negative_pressure"); clamp.present()) {
      solver.clamp_negative_pressure = boolean(clamp);
    }
    read_optional(node, "gravity_ramp_time", solver.gravity_ramp_time, non_negative);
    read_optional(node, "background_pressure", solver.background_pressure, non_negative);
    read_optional(node, "shifting", solver.shifting, shifting_names);
    read_optional(node, "max_density_error", solver.max_density_error, in_unit_interval);
    read_optional(node, "max_divergence_error", solver.max_divergence_error, in_unit_interval);
    read_optional(node, "max_solver_iterations", solver.max_solver_iterations);
    read_optional(node, "max_failed_solves", solver.max_failed_solves);
    read_optional(node, "artificial_stress", solver.artificial_stress, non_negative);
    if (const Node skin = child(node, "neighbor_skin"); skin.present())
      solver.neighbor_skin = number(skin, non_negative);
    if (const Node tension = child(node, "surface_tension"); tension.present())
      read_surface_tension(tension, solver.surface_tension);
  }

  void read_surface_tension(const Node& node, scene::SurfaceTension& tension) const {
    expect_object(node, {"model", "coefficient", "contact_angle", "adhesion", "unlike_attraction"});
    tension.model = choice(child(node, "model"), surface_tension_model_names);
    tension.coefficient = number(child(node, "coefficient"), positive);
    const Node angle = child(node, "contact_angle");
    if (angle.present()) {
      if (tension.model != scene::SurfaceTensionModel::pairwise)
        fail(angle, "no contact_angle: only the pairwise model sets the wetting by an angle (akinci: adhesion)");
      tension.contact_angle =
          number(angle, "an angle in degrees in (0, 180)", [](double x) { return x > 0 && x < 180; });
    }
    const Node adhesion = child(node, "adhesion");
    if (adhesion.present()) {
      if (tension.model != scene::SurfaceTensionModel::akinci)
        fail(adhesion, "no adhesion: only the akinci model has a wall adhesion coefficient (pairwise: contact_angle)");
      tension.adhesion = number(adhesion, non_negative);
    }
    const Node unlike = child(node, "unlike_attraction");
    if (unlike.present()) {
      if (tension.model != scene::SurfaceTensionModel::pairwise)
        fail(unlike, "no unlike_attraction: only the pairwise model has pair strengths between fluids");
      tension.unlike_attraction = boolean(unlike);
    }
  }

  /// What several fluid materials (a multiphase scene) and surface tension need of the solver.
  void check_phases(const scene::Scene& scene) const {
    const std::size_t fluids = scene::fluid_material_count(scene);
    const scene::Solver& solver = scene.solver;
    if (fluids > 1) {
      const double ratio = scene::fluid_density_ratio(scene);
      if (solver.scheme != scene::Scheme::wcsph && ratio > scene::max_incompressible_density_ratio)
        fail("/solver/scheme",
             "\"wcsph\" for fluids whose rest densities differ by more than " +
                 format_number(scene::max_incompressible_density_ratio) + " times (multiphase dfsph and iisph take " +
                 format_number(scene::max_incompressible_density_ratio) + ")",
             "\"" + std::string(scheme_names[static_cast<std::size_t>(solver.scheme)].name) + "\" with a ratio of " +
                 format_number(ratio));
      if (solver.density != scene::DensityMethod::summation)
        fail("/solver/density", "\"summation\" for a scene with several fluid materials (number density)",
             "\"continuity\"");
      if (solver.artificial_stress > 0)
        fail("/solver/artificial_stress", "0 for a scene with several fluid materials",
             format_number(solver.artificial_stress));
    }
    const scene::SurfaceTensionModel model = solver.surface_tension.model;
    if (model != scene::SurfaceTensionModel::none) {
      if (solver.scheme != scene::Scheme::wcsph)
        fail("/solver/scheme", "\"wcsph\" with surface tension",
             "\"" + std::string(scheme_names[static_cast<std::size_t>(solver.scheme)].name) + "\"");
      if (model == scene::SurfaceTensionModel::csf && fluids != 2)
        fail("/solver/surface_tension/model", "a model for this scene: \"csf\" needs exactly two fluid materials",
             "\"csf\" with " + std::to_string(fluids) + " fluid material" + (fluids == 1 ? "" : "s"));
      if (fluids > 2)
        fail("/solver/surface_tension/model", "surface tension between at most two fluid materials",
             std::to_string(fluids) + " fluid materials");
    }
    for (std::size_t k = 0; k < scene.output.fields.size(); ++k) {
      if (scene.output.fields[k] == "phase" && fluids < 2)
        fail("/output/fields/" + std::to_string(k), "a field this scene has (\"phase\" needs several fluid materials)",
             "\"phase\"");
    }
  }

  scene::Time read_time(const Node& node) const {
    expect_object(node, {"start", "end", "output_interval"});
    scene::Time time;
    read_optional(node, "start", time.start, any_number);
    time.end = number(child(node, "end"), "a number > the start time (" + format_number(time.start) + ")",
                      [&](double end) { return end > time.start; });
    read_optional(node, "output_interval", time.output_interval, positive);
    return time;
  }

  void read_output(const Node& node, scene::Scene& scene) const {
    expect_object(node, {"fields", "probe_interval", "recovery"});
    scene::Output& output = scene.output;
    if (const Node fields = child(node, "fields"); fields.present()) {
      output.fields.clear();
      for (const Node& entry : elements(fields, 1, "a non-empty array of field names")) {
        output.fields.push_back(field_name(entry, output.fields));
      }
    }
    read_optional(node, "probe_interval", output.probe_interval, positive);
    if (const Node recovery = child(node, "recovery"); recovery.present())
      output.recovery = read_recovery(recovery, scene);
  }

  /// The recovery of a material from a region: a material some fluid block starts with, and a
  /// region inside the domain.
  scene::Recovery read_recovery(const Node& node, const scene::Scene& scene) const {
    expect_object(node, {"material", "region"});
    scene::Recovery recovery;
    const Node material = child(node, "material");
    recovery.material = material_index(material, scene.materials);
    const auto starts_with = [&](const scene::FluidBlock& block) { return block.material == recovery.material; };
    if (std::none_of(scene.fluid.begin(), scene.fluid.end(), starts_with))
      fail(material, "a material that some fluid block starts with");
    const Node region = child(node, "region");
    recovery.region = read_box(region);
    for (int d = 0; d < dimension_; ++d) {
      if (recovery.region.min[d] < scene.domain.box.min[d] - tolerance() ||
          recovery.region.max[d] > scene.domain.box.max[d] + tolerance()) {
        fail(region, "a box inside the domain [" + format_number(scene.domain.box.min[d]) + ", " +
                         format_number(scene.domain.box.max[d]) + "] on axis " + std::to_string(d));
      }
    }
    return recovery;
  }

  std::vector<scene::Probe> read_probes(const Node& node, const scene::Domain& domain) const {
    std::vector<scene::Probe> probes;
    for (const Node& entry : elements(node, 0, "an array of probes")) {
      expect_object(entry, {"name", "type", "position"});
      scene::Probe probe;
      probe.name = probe_name(child(entry, "name"), probes);
      probe.type = choice(child(entry, "type"), probe_type_names);
      const Node position = child(entry, "position");
      probe.position = vector(position);
      for (int d = 0; d < dimension_; ++d) {
        if (probe.position[d] < domain.box.min[d] - tolerance() ||
            probe.position[d] > domain.box.max[d] + tolerance()) {
          fail(element(position, d), "a number in [" + format_number(domain.box.min[d]) + ", " +
                                         format_number(domain.box.max[d]) + "] (the domain's extent on axis " +
                                         std::to_string(d) + ")");
        }
      }
      probes.push_back(probe);
    }
    return probes;
  }

  /// A probe's name heads its column of probes.csv, so it must need no CSV quoting.
  std::string probe_name(const Node& node, const std::vector<scene::Probe>& earlier) const {
    const std::string expected =
        "a name of letters, digits, '_', '-' and '.', other than \"time\", that no earlier probe has";
    const std::string name = node.present() && node.value->is_string() ? node.value->get<std::string>() : "";
    const auto allowed = [](unsigned char c) { return std::isalnum(c) || c == '_' || c == '-' || c == '.'; };
    const auto same_name = [&](const scene::Probe& other) { return other.name == name; };
    if (name.empty() || name == "time" || !std::all_of(name.begin(), name.end(), allowed) ||
        std::any_of(earlier.begin(), earlier.end(), same_name)) {
      fail(node, expected);
    }
    return name;
  }

  std::string field_name(const Node& node, const std::vector<std::string>& earlier) const {
    const std::string expected = "one of " + quoted_list(scene::output_field_names);
    if (!node.present() || !node.value->is_string()) fail(node, expected);
    const std::string& name = node.value->get_ref<const std::string&>();
    if (std::find(scene::output_field_names.begin(), scene::output_field_names.end(), name) ==
        scene::output_field_names.end()) {
      fail(node, expected);
    }
    if (std::find(earlier.begin(), earlier.end(), name) != earlier.end()) fail(node, "a field not listed before");
    return name;
  }

  // --- Geometry: does the scene leave the solver something sensible to do?

  void check_geometry(const scene::Scene& scene) const {
    if (scene.walls.container) check_container_in_domain(*scene.walls.container, scene.walls.layers, scene.domain.box);
    const Vec& lattice_anchor = scene.walls.container ? scene.walls.container->inner.min : scene.domain.box.min;
    for (std::size_t k = 0; k < scene.fluid.size(); ++k) {
      const auto& shape = scene.fluid[k].shape;
      const std::string path =
          "/fluid/" + std::to_string(k) + (std::holds_alternative<scene::Box>(shape) ? "/box" : "/ball");
      if (scene.walls.container) check_inside(shape, path, scene.walls.container->inner, "the container's inner box");
      check_inside(shape, path, scene.domain.box, "the domain");
      const bool holds_point = std::visit(
          [&](const auto& s) { return holds_lattice_point(s, lattice_anchor, spacing_, dimension_); }, shape);
      if (!holds_point) {
        fail(path,
             "a shape holding at least one particle position (a lattice point " +
                 format_vector(lattice_anchor, dimension_) + " + (k + 1/2) x " + format_number(spacing_) + ")",
             format_shape(shape, dimension_));
      }
    }
  }

  /// The wall particles must lie inside the domain, which would otherwise remove them. An open
  /// top has no wall above the container's rim.
  void check_container_in_domain(const scene::Container& container, int layers, const scene::Box& domain) const {
    const double wall = layers * spacing_;
    const std::string wall_text = std::to_string(layers) + " wall layers of " + format_number(spacing_);
    for (int d = 0; d < dimension_; ++d) {
      const std::string axis = axis_index(d);
      if (container.inner.min[d] - wall < domain.min[d] - tolerance()) {
        fail("/walls/container/min/" + std::to_string(d),
             "a number >= " + format_number(domain.min[d] + wall) + " (the domain's min" + axis + " plus " + wall_text +
                 ")",
             format_number(container.inner.min[d]));
      }
      const bool open_above = container.open_top && d == dimension_ - 1;
      const double wall_above = open_above ? 0 : wall;
      if (container.inner.max[d] + wall_above > domain.max[d] + tolerance()) {
        fail("/walls/container/max/" + std::to_string(d),
             "a number <= " + format_number(domain.max[d] - wall_above) + " (the domain's max" + axis +
                 (open_above ? "" : " minus " + wall_text) + ")",
             format_number(container.inner.max[d]));
      }
    }
  }

  void check_inside(const std::variant<scene::Box, scene::Ball>& shape, const std::string& path,
                    const scene::Box& region, const std::string& region_name) const {
    if (const auto* ball = std::get_if<scene::Ball>(&shape)) {
      for (int d = 0; d < dimension_; ++d) {
        if (ball->centre[d] - ball->radius < region.min[d] - tolerance() ||
            ball->centre[d] + ball->radius > region.max[d] + tolerance()) {
          fail(path, "a ball inside " + region_name + " " + format_box(region, dimension_),
               format_shape(shape, dimension_));
        }
      }
      return;
    }
    const auto& box = std::get<scene::Box>(shape);
    for (int d = 0; d < dimension_; ++d) {
      const std::string axis = axis_index(d);
      if (box.min[d] < region.min[d] - tolerance()) {
        fail(path + "/min/" + std::to_string(d),
             "a number >= " + format_number(region.min[d]) + " (the min" + axis + " of " + region_name + ")",
             format_number(box.min[d]));
      }
      if (box.max[d] > region.max[d] + tolerance()) {
        fail(path + "/max/" + std::to_string(d),
             "a number <= " + format_number(region.max[d]) + " (the max" + axis + " of " + region_name + ")",
             format_number(box.max[d]));
      }
    }
  }

  /// Slack for comparing coordinates the user wrote as decimals (0.1 + 0.2 is not 0.3).
  double tolerance() const { return 1e-9 * spacing_; }

  std::string file_;
  int dimension_ = 2;
  double spacing_ = 0;
};

}  // namespace

scene::Scene parse_scene(std::string_view json_text, std::string source_name) {
  const json document = parse_json(json_text, source_name);
  return SceneParser(std::move(source_name)).parse(document);
}

scene::Scene read_scene_file(const std::filesystem::path& file) {
  const std::string name = file.string();
  std::error_code error;
  if (!std::filesystem::is_regular_file(file, error)) {
    const char* found = !std::filesystem::exists(file, error)        ? "no such file"
                        : std::filesystem::is_directory(file, error) ? "a directory"
                                                                     : "something other than a regular file";
    throw SceneError(name, "", "a scene file", found);
  }
  std::ifstream stream(file, std::ios::binary);
  const std::string contents{std::istreambuf_iterator<char>(stream), std::istreambuf_iterator<char>()};
  if (!stream.is_open() || stream.bad())
    throw SceneError(name, "", "a readable scene file", "a file that cannot be read");
  return parse_scene(contents, name);
}

}  // namespace tide::io
