#include <algorithm>
#include <array>
#include <cmath>
#include <nlohmann/json.hpp>
#include <string>

#include "scene_keys.hpp"
#include "scene_names.hpp"
#include "scene_sections.hpp"
#include "scene_shapes.hpp"

namespace tide::io {
namespace {

// An exit's name heads its column of crowd.csv ("out_<name>"), so it must need no CSV quoting.
bool is_column_name(const std::string& name) {
  const auto allowed = [](unsigned char c) { return std::isalnum(c) || c == '_' || c == '-' || c == '.'; };
  return !name.empty() && std::all_of(name.begin(), name.end(), allowed);
}

void read_agent_groups(const ValueReader& values, const Node& node, scene::Crowd& crowd) {
  for (const Node& entry : values.elements(node, 1, "a non-empty array of agent groups")) {
    scene::AgentGroup group;
    read_section(values, entry, crowd_agent_keys(), group);
    crowd.agents.push_back(group);
  }
}

// Required, and not empty, unless every group walks along a heading (read before the exits).
void read_exits(const ValueReader& values, const Node& node, scene::Crowd& crowd) {
  const bool all_headed = std::all_of(crowd.agents.begin(), crowd.agents.end(),
                                      [](const scene::AgentGroup& group) { return group.heading.has_value(); });
  if (all_headed && !node.present()) return;
  const std::string expected = all_headed ? "an array of exits" : "a non-empty array of exits (a group has no heading)";
  for (const Node& entry : values.elements(node, all_headed ? 0 : 1, expected)) {
    scene::CrowdExit exit;
    read_section(values, entry, crowd_exit_keys(), exit);
    const auto same_name = [&](const scene::CrowdExit& other) { return other.name == exit.name; };
    if (std::any_of(crowd.exits.begin(), crowd.exits.end(), same_name))
      values.fail(child(entry, "name"), "a name no earlier exit has");
    crowd.exits.push_back(exit);
  }
}

}  // namespace

std::span<const Key<scene::Crowd>> crowd_keys() {
  static constexpr std::array<Key<scene::Crowd>, 16> keys{{
      {"agents", "non-empty array of objects", "–", "", "Where the agents stand at the start.", Presence::required,
       read_agent_groups},
      {"exits", "array of objects, not empty unless every group has a `heading`", "–", "none",
       "Regions beyond the doors: an agent entering one is removed and counted. Required unless every group of "
       "`agents` has a `heading`.",
       Presence::always, read_exits},
      {"desired_speed", "object", "–", "see below", "Each agent's free walking speed, drawn once.", Presence::optional,
       [](const ValueReader& values, const Node& value, scene::Crowd& crowd) {
         read_section(values, value, crowd_speed_keys(), crowd.desired_speed);
       }},
      {"comfortable_density", "number > 0", "persons/m²", "`2`",
       "ρ_c: up to it agents feel no uneasiness (in the density of the other agents, ρ − W(0)); the end of Still's "
       "stable flow band (1–2.5 persons/m²).",
       Presence::optional,
       [](const ValueReader& values, const Node& value, scene::Crowd& crowd) {
         crowd.comfortable_density = values.number(value, positive);
       }},
      {"stiffness", "number > 0", "m⁴/s²", "`1`",
       "K of the uneasiness p = K max(ρ − W(0) − ρ_c, 0), on the density of the other agents "
       "([crowds.md](crowds.md#uneasiness-and-the-agents-own-term)); sqrt(K) is the speed of a small density "
       "disturbance. Not calibrated ([crowds.md](crowds.md#parameters)).",
       Presence::optional,
       [](const ValueReader& values, const Node& value, scene::Crowd& crowd) {
         crowd.stiffness = values.number(value, positive);
       }},
      {"relaxation_time", "number > 0", "s", "`0.5`",
       "τ: how fast an agent takes up its desired velocity (Helbing, Farkas & Vicsek 2000).", Presence::optional,
       [](const ValueReader& values, const Node& value, scene::Crowd& crowd) {
         crowd.relaxation_time = values.number(value, positive);
       }},
      {"time_gap", "number > 0", "s", "`1`",
       "T: an agent walks no faster than (s − ℓ)/T, s the distance to the nearest agent ahead in its way (the "
       "collision-free speed model of Tordeux, Chraibi & Seyfried 2016, [crowds.md](crowds.md#parameters)).",
       Presence::optional,
       [](const ValueReader& values, const Node& value, scene::Crowd& crowd) {
         crowd.time_gap = values.number(value, positive);
       }},
      {"agent_length", "number > 0", "m", "`0.4`",
       "ℓ: the headway at which an agent stops; the model's agent length is a body's diameter, 2 `body_radius` "
       "(Tordeux, Chraibi & Seyfried 2016).",
       Presence::optional,
       [](const ValueReader& values, const Node& value, scene::Crowd& crowd) {
         crowd.agent_length = values.number(value, positive);
       }},
      {"steering_strength", "number ≥ 0", "", "`8`",
       "a: the walking direction is the desired one plus Σ_j a exp((ℓ − s_ij)/D) away from each agent j s_ij "
       "away, normalised (the direction model of Tordeux, Chraibi & Seyfried 2016, eq. 5); 0 walks straight "
       "toward the goal ([crowds.md](crowds.md#parameters)).",
       Presence::optional,
       [](const ValueReader& values, const Node& value, scene::Crowd& crowd) {
         crowd.steering_strength = values.number(value, non_negative);
       }},
      {"steering_range", "number > 0", "m", "`0.1`", "D: the range of that turning away from the agents close by.",
       Presence::optional,
       [](const ValueReader& values, const Node& value, scene::Crowd& crowd) {
         crowd.steering_range = values.number(value, positive);
       }},
      {"agent_mass", "number > 0", "kg", "`80`", "m of the body forces (Helbing, Farkas & Vicsek 2000).",
       Presence::optional,
       [](const ValueReader& values, const Node& value, scene::Crowd& crowd) {
         crowd.agent_mass = values.number(value, positive);
       }},
      {"body_radius", "number > 0", "m", "`0.2`",
       "r: half a body's width (the default of JuPedSim's collision-free speed model; Helbing, Farkas & Vicsek "
       "2000 draw it from 0.25–0.35 m; [crowds.md](crowds.md#parameters)).",
       Presence::optional,
       [](const ValueReader& values, const Node& value, scene::Crowd& crowd) {
         crowd.body_radius = values.number(value, positive);
       }},
      {"repulsion_strength", "number ≥ 0", "N", "`2000`",
       "A of the social repulsion A exp(−gap/B) (Helbing, Farkas & Vicsek 2000).", Presence::optional,
       [](const ValueReader& values, const Node& value, scene::Crowd& crowd) {
         crowd.repulsion_strength = values.number(value, non_negative);
       }},
      {"repulsion_range", "number > 0", "m", "`0.08`", "B of the social repulsion (Helbing, Farkas & Vicsek 2000).",
       Presence::optional,
       [](const ValueReader& values, const Node& value, scene::Crowd& crowd) {
         crowd.repulsion_range = values.number(value, positive);
       }},
      {"body_stiffness", "number ≥ 0", "kg/s²", "`1.2e5`",
       "k of the body force k × overlap where bodies touch (Helbing, Farkas & Vicsek 2000).", Presence::optional,
       [](const ValueReader& values, const Node& value, scene::Crowd& crowd) {
         crowd.body_stiffness = values.number(value, non_negative);
       }},
      {"navigation_cell", "number > 0", "m", "`0.1`",
       "Cell of the distance field to the exits, computed once by fast marching; at most the body radius so that a "
       "door is resolved.",
       Presence::optional,
       [](const ValueReader& values, const Node& value, scene::Crowd& crowd) {
         const double radius = crowd.body_radius;
         crowd.navigation_cell =
             values.number(value, "a number > 0 and at most crowd.body_radius (" + format_number(radius) + ")",
                           [&](double x) { return x > 0 && x <= radius; });
       }},
  }};
  return keys;
}

std::span<const Key<scene::AgentGroup>> crowd_agent_keys() {
  static constexpr std::array<Key<scene::AgentGroup>, 4> keys{{
      {"region", "[box](#box)", "m", "", "Where the agents stand at the start (`placement`).", Presence::required,
       [](const ValueReader& values, const Node& value, scene::AgentGroup& group) {
         group.region = read_box(values, value);
       }},
      {"count", "integer in [1, 1000000]", "–", "", "How many agents.", Presence::required,
       [](const ValueReader& values, const Node& value, scene::AgentGroup& group) {
         group.count = static_cast<std::size_t>(values.count(value));
       }},
      {"heading", "non-zero vector", "–", "to the nearest exit",
       "A fixed desired direction (normalised) instead of the way to an exit: walkers in a periodic corridor.",
       Presence::optional,
       [](const ValueReader& values, const Node& value, scene::AgentGroup& group) {
         const scene::Vec v = values.vector(value);
         const double norm = std::hypot(v[0], v[1], v[2]);
         if (!(norm > 0) || !std::isfinite(norm)) values.fail(value, "a non-zero vector");
         group.heading = scene::Vec{v[0] / norm, v[1] / norm, v[2] / norm};
       }},
      {"placement", "`lattice` or `random`", "–", "`lattice`",
       "`lattice`: a square lattice centred in the region (a hexagonal one where too dense for it); `random`: "
       "uniformly at random, a body diameter or more apart (random sequential addition, seeded by "
       "`desired_speed.seed`; up to about 2.5 persons/m²). [crowds.md](crowds.md#model)",
       Presence::optional,
       [](const ValueReader& values, const Node& value, scene::AgentGroup& group) {
         group.placement = values.choice(value, agent_placement_names);
       }},
  }};
  return keys;
}

std::span<const Key<scene::CrowdExit>> crowd_exit_keys() {
  static constexpr std::array<Key<scene::CrowdExit>, 2> keys{{
      {"name", "string of letters, digits, `_`, `-`, `.`; unique", "–", "",
       "The exit's column in `crowd.csv` (`out_<name>`).", Presence::required,
       [](const ValueReader& values, const Node& value, scene::CrowdExit& exit) {
         const std::string name = value.present() && value.value->is_string() ? value.value->get<std::string>() : "";
         if (!is_column_name(name)) values.fail(value, "a name of letters, digits, '_', '-' and '.'");
         exit.name = name;
       }},
      {"region", "[box](#box)", "m", "", "Where agents leave: the space beyond a door, inside the domain.",
       Presence::required,
       [](const ValueReader& values, const Node& value, scene::CrowdExit& exit) {
         exit.region = read_box(values, value);
       }},
  }};
  return keys;
}

std::span<const Key<scene::DesiredSpeed>> crowd_speed_keys() {
  static constexpr std::array<Key<scene::DesiredSpeed>, 3> keys{{
      {"mean", "number > 0", "m/s", "`1.34`", "Mean of the normal distribution (Helbing & Molnár 1995).",
       Presence::optional,
       [](const ValueReader& values, const Node& value, scene::DesiredSpeed& speed) {
         speed.mean = values.number(value, positive);
       }},
      {"deviation", "number ≥ 0", "m/s", "`0.26`",
       "Its standard deviation (Helbing & Molnár 1995); draws beyond three deviations, or at or below 0, are drawn "
       "again.",
       Presence::optional,
       [](const ValueReader& values, const Node& value, scene::DesiredSpeed& speed) {
         speed.deviation = values.number(value, non_negative);
       }},
      {"seed", "integer in [0, 2⁵³]", "–", "`1`", "Seed of the generator: the same seed, the same speeds.",
       Presence::optional,
       [](const ValueReader& values, const Node& value, scene::DesiredSpeed& speed) {
         speed.seed =
             static_cast<std::uint64_t>(values.integer(value, 0, std::int64_t{1} << 53, "an integer in [0, 2^53]"));
       }},
  }};
  return keys;
}

void read_crowd(const ValueReader& values, const Node& node, scene::Scene& scene) {
  scene::Crowd crowd;
  read_section(values, node, crowd_keys(), crowd);
  scene.crowd = std::move(crowd);
}

}  // namespace tide::io
