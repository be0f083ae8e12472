#include "tide/serve/command.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <initializer_list>
#include <nlohmann/json.hpp>
#include <sstream>
#include <stdexcept>

namespace tide::serve {
namespace {

using Json = nlohmann::json;

// A refusal: thrown while reading a message, caught in parse_command.
struct Refusal : std::runtime_error {
  using std::runtime_error::runtime_error;
};

std::string format_number(double x) {
  std::ostringstream text;
  text << x;
  return text.str();
}

// Reads the fields of one command, refusing one it does not know and noting clamped numbers.
class Fields {
 public:
  Fields(const Json& message, std::initializer_list<std::string_view> expected) : message_(message) {
    for (const auto& [key, value] : message.items()) {
      if (key == "command") continue;
      if (std::find(expected.begin(), expected.end(), key) == expected.end())
        throw Refusal("unknown field \"" + key + "\"");
    }
  }

  const Json& field(const std::string& key) const {
    const auto found = message_.find(key);
    if (found == message_.end()) throw Refusal("missing field \"" + key + "\"");
    return *found;
  }

  double number(const std::string& key, double least, double most) {
    const Json& value = field(key);
    if (!value.is_number()) throw Refusal("\"" + key + "\" must be a number");
    const double x = value.get<double>();
    if (!std::isfinite(x)) throw Refusal("\"" + key + "\" must be finite");
    const double clamped = std::clamp(x, least, most);
    if (clamped != x) {
      note_ += (note_.empty() ? "" : "; ") + key + " " + format_number(x) + " clamped to " + format_number(clamped) +
               " (limits " + format_number(least) + " to " + format_number(most) + ")";
    }
    return clamped;
  }

  int integer(const std::string& key, int least, int most) {
    if (!field(key).is_number_integer()) throw Refusal("\"" + key + "\" must be an integer");
    return static_cast<int>(number(key, least, most));
  }

  bool boolean(const std::string& key) const {
    const Json& value = field(key);
    if (!value.is_boolean()) throw Refusal("\"" + key + "\" must be true or false");
    return value.get<bool>();
  }

  template <std::size_t N>
  std::size_t choice(const std::string& key, const std::array<std::string_view, N>& names) const {
    const Json& value = field(key);
    if (value.is_string()) {
      const std::string text = value.get<std::string>();
      for (std::size_t k = 0; k < N; ++k)
        if (names[k] == text) return k;
    }
    std::string expected;
    for (std::size_t k = 0; k < N; ++k) expected += (k > 0 ? ", \"" : "\"") + std::string(names[k]) + "\"";
    throw Refusal("\"" + key + "\" must be one of " + expected);
  }

  const std::string& note() const { return note_; }

 private:
  const Json& message_;
  std::string note_;
};

constexpr std::array<std::string_view, 3> colour_names{"speed", "density", "pressure"};
constexpr std::array<std::string_view, 2> scheme_names{"wcsph", "dfsph"};

Command read_command(const std::string& name, const Json& message, std::string& note) {
  using L = CommandLimits;
  const auto with = [&](std::initializer_list<std::string_view> expected, auto read) -> Command {
    Fields fields(message, expected);
    Command command = read(fields);
    note = fields.note();
    return command;
  };
  if (name == "viscosity")
    return with({"value"},
                [](Fields& f) { return SetViscosity{f.number("value", L::least_viscosity, L::most_viscosity)}; });
  if (name == "gravity") {
    return with({"magnitude", "tilt"}, [](Fields& f) {
      return SetGravity{f.number("magnitude", 0, L::most_gravity), f.number("tilt", -L::most_tilt, L::most_tilt)};
    });
  }
  if (name == "particles")
    return with({"value"},
                [](Fields& f) { return SetParticleCount{f.integer("value", L::least_particles, L::most_particles)}; });
  if (name == "surface_tension")
    return with({"value"}, [](Fields& f) { return SetSurfaceTension{f.boolean("value")}; });
  if (name == "scheme") {
    return with({"value"}, [](Fields& f) {
      return SetScheme{f.choice("value", scheme_names) == 0 ? scene::Scheme::wcsph : scene::Scheme::dfsph};
    });
  }
  if (name == "colour")
    return with({"value"},
                [](Fields& f) { return SetColour{static_cast<ColourField>(f.choice("value", colour_names))}; });
  if (name == "pause") return with({"value"}, [](Fields& f) { return Pause{f.boolean("value")}; });
  if (name == "step") return with({}, [](Fields&) { return Step{}; });
  if (name == "reset") return with({}, [](Fields&) { return Reset{}; });
  if (name == "obstacle") {
    return with({"x", "y"}, [](Fields& f) {
      return MoveObstacle{f.number("x", -L::most_obstacle_coordinate, L::most_obstacle_coordinate),
                          f.number("y", -L::most_obstacle_coordinate, L::most_obstacle_coordinate)};
    });
  }
  throw Refusal("unknown command \"" + name +
                "\" (expected viscosity, gravity, particles, surface_tension, scheme, colour, pause, step, reset or "
                "obstacle)");
}

}  // namespace

ParsedCommand parse_command(std::string_view text) {
  ParsedCommand parsed;
  if (text.size() > largest_command_bytes) {
    parsed.message = "message of " + std::to_string(text.size()) + " bytes, over the limit of " +
                     std::to_string(largest_command_bytes);
    parsed.garbage = true;
    return parsed;
  }
  const Json message = Json::parse(text, nullptr, false);
  if (message.is_discarded()) {
    parsed.message = "not JSON";
    parsed.garbage = true;
    return parsed;
  }
  if (!message.is_object()) {
    parsed.message = "expected a JSON object with a \"command\" field";
    return parsed;
  }
  const auto name = message.find("command");
  if (name == message.end() || !name->is_string()) {
    parsed.message = "expected a string field \"command\"";
    return parsed;
  }
  parsed.name = name->get<std::string>();
  try {
    parsed.command = read_command(parsed.name, message, parsed.message);
  } catch (const Refusal& refusal) {
    parsed.message = refusal.what();
  }
  return parsed;
}

std::string_view colour_field_name(ColourField field) { return colour_names[static_cast<std::size_t>(field)]; }

}  // namespace tide::serve
