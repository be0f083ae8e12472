#pragma once

// The commands a page sends to `tide serve` (docs/serve.md, "Commands"): JSON text messages,
// each checked here before the simulation sees it. A number outside its documented limits is
// clamped to them (and the reply says so); an unknown command, a missing field or a field of the
// wrong type is refused with a message.

#include <cstddef>
#include <optional>
#include <string>
#include <string_view>
#include <variant>

#include "tide/core/scene.hpp"

namespace tide::serve {

/// The largest command message, in bytes; a longer one closes its connection.
inline constexpr std::size_t largest_command_bytes = 4096;

/// The documented limits of the commands' numbers.
struct CommandLimits {
  static constexpr double least_viscosity = 1e-6;  // m²/s, water
  static constexpr double most_viscosity = 1e-2;   // m²/s, ten thousand times water's
  static constexpr double most_gravity = 20;       // m/s², about 2 g
  static constexpr double most_tilt = 180;         // degrees either way from straight down
  static constexpr int least_particles = 200;
  static constexpr int most_particles = 40000;
  static constexpr double most_obstacle_coordinate = 1e3;  // m; the core keeps it inside the domain
};

/// What the particles are coloured by.
enum class ColourField { speed, density, pressure };

struct SetViscosity {
  double kinematic_viscosity;  // m²/s
};
/// Gravity of `magnitude` m/s², turned by `tilt` degrees counter-clockwise from straight down.
struct SetGravity {
  double magnitude;
  double tilt;
};
struct SetParticleCount {
  int count;
};
struct SetSurfaceTension {
  bool on;
};
struct SetScheme {
  scene::Scheme scheme;  // wcsph or dfsph
};
struct SetColour {
  ColourField field;
};
struct Pause {
  bool paused;
};
struct Step {};
struct Reset {};
/// Where the centre of the dragged obstacle should go, in m.
struct MoveObstacle {
  double x, y;
};

using Command = std::variant<SetViscosity, SetGravity, SetParticleCount, SetSurfaceTension, SetScheme, SetColour, Pause,
                             Step, Reset, MoveObstacle>;

/// A message read: the command, or the reason it was refused, and a note when a number was clamped.
struct ParsedCommand {
  std::string name;                // the "command" field, or "" where there is none
  std::optional<Command> command;  // empty: refused
  std::string message;             // why it was refused, or what was clamped; "" otherwise
  bool garbage = false;            // not JSON, or over largest_command_bytes: not a command at all
};

/// Reads one command message (a JSON object with a "command" field).
ParsedCommand parse_command(std::string_view text);

/// "speed", "density" or "pressure".
std::string_view colour_field_name(ColourField field);

}  // namespace tide::serve
