#pragma once

// Small crowd scenes for the tests, written as scene files so that the reader is part of what
// they check: a walled room with one door in its right wall, and the exit region beyond it.

#include <sstream>
#include <string>

#include "tide/core/scene.hpp"
#include "tide/io/scene_reader.hpp"

namespace tide::test {

struct CrowdRoom {
  double length = 12;  // m, inner x extent
  double width = 6;    // m, inner y extent
  double door = 1.2;   // m, centred in the right wall
  double wall = 0.3;   // m, thickness
  std::string agents = R"([{"region": {"min": [1, 1], "max": [5, 5]}, "count": 20}])";
  std::string speed = R"({"mean": 1.34, "deviation": 0.26, "seed": 7})";
  double end = 10;  // s
};

/// The scene file text of `room`: walls as obstacle boxes (the right one in two pieces around
/// the door), the exit a box beyond the door, spacing 0.1 m and h = 0.5 m.
inline std::string crowd_room_json(const CrowdRoom& room) {
  const double L = room.length, W = room.width, t = room.wall;
  const double door_low = (W - room.door) / 2, door_high = (W + room.door) / 2;
  const auto box = [](double x0, double y0, double x1, double y1) {
    std::ostringstream text;
    text << R"({"box": {"min": [)" << x0 << ", " << y0 << "], \"max\": [" << x1 << ", " << y1 << "]}}";
    return text.str();
  };
  std::ostringstream json;
  json << R"({"dimension": 2, "particle_spacing": 0.1, "kernel": {"type": "wendland_c2", "smoothing_ratio": 5},)"
       << R"("crowd": {"agents": )" << room.agents << R"(, "exits": [{"name": "door", "region": {"min": [)" << L + t
       << ", " << door_low - 1 << "], \"max\": [" << L + t + 1.5 << ", " << door_high + 1 << "]}}], "
       << R"("desired_speed": )" << room.speed << "}, "
       << R"("walls": {"obstacles": [)" << box(-t, -t, L + t, 0) << ", " << box(-t, W, L + t, W + t) << ", "
       << box(-t, 0, 0, W) << ", " << box(L, 0, L + t, door_low) << ", " << box(L, door_high, L + t, W) << "]}, "
       << R"("domain": {"min": [)" << -t - 0.2 << ", " << -t - 0.2 << "], \"max\": [" << L + t + 2 << ", "
       << W + t + 0.2 << "]}, "
       << R"("gravity": [0, 0], "solver": {"scheme": "crowd"}, "time": {"end": )" << room.end
       << R"(, "output_interval": 1}})";
  return json.str();
}

inline scene::Scene crowd_room(const CrowdRoom& room) { return io::parse_scene(crowd_room_json(room), "crowd_room"); }

/// A corridor periodic along x, `length` × `width` inside walls 0.3 m thick below and above,
/// `count` agents spread over it (a body radius and a half spacing from the walls) walking along +x,
/// placed as `placement` ("lattice" or "random") says.
inline scene::Scene crowd_corridor(std::size_t count, double length, double width, double end,
                                   const std::string& placement = "lattice") {
  std::ostringstream json;
  json << R"({"dimension": 2, "particle_spacing": 0.1, "kernel": {"type": "wendland_c2", "smoothing_ratio": 5},)"
       << R"("crowd": {"agents": [{"region": {"min": [0, 0.3], "max": [)" << length << ", " << width - 0.3
       << R"(]}, "count": )" << count << R"(, "heading": [1, 0], "placement": ")" << placement << R"("}]}, )"
       << R"("walls": {"obstacles": [{"box": {"min": [0, -0.3], "max": [)" << length << R"(, 0]}}, )"
       << R"({"box": {"min": [0, )" << width << R"(], "max": [)" << length << ", " << width + 0.3 << "]}}]}, "
       << R"("domain": {"min": [0, -0.5], "max": [)" << length << ", " << width + 0.5
       << R"(], "periodic": [true, false]}, "gravity": [0, 0], "solver": {"scheme": "crowd"}, "time": {"end": )" << end
       << "}}";
  return io::parse_scene(json.str(), "crowd_corridor");
}

}  // namespace tide::test
