#pragma once

// A frame of the live simulation as `tide serve` sends it to its pages: a binary WebSocket
// message of a 64-byte header and float32 arrays, all little-endian (docs/serve.md, "Frames").

#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include "tide/serve/command.hpp"

namespace tide::serve {

inline constexpr std::uint32_t frame_magic = 0x48505354;  // the bytes "TSPH"
inline constexpr std::uint32_t frame_version = 1;
inline constexpr std::size_t frame_header_bytes = 64;

struct Frame {
  std::uint32_t number = 0;  // counts the frames the simulation published
  double time = 0;           // simulated, s
  std::uint64_t steps = 0;
  ColourField colour = ColourField::speed;
  float colour_low = 0, colour_high = 1;  // the colour field's values at the two ends of the colour map
  std::array<float, 4> view{};            // lower x, lower y, upper x, upper y of the domain, m
  float particle_spacing = 0;             // m
  std::vector<float> fluid;               // x, y of each fluid particle
  std::vector<float> colour_values;       // the colour field of each fluid particle
  std::vector<float> walls;               // x, y of each particle of the still walls
  std::vector<float> obstacle;            // x, y of each particle of the moving walls (the dragged obstacle)
};

/// The message of `frame`: header words (u32 unless said) magic, version, fluid particles N,
/// wall particles W, obstacle particles B, colour field (0 speed, 1 density, 2 pressure),
/// colour_low (f32), colour_high (f32), time (f32), steps (low 32 bits), frame number, view
/// (4 f32), particle spacing (f32); then fluid x, y (2N f32), colour values (N f32), walls (2W f32),
/// obstacle (2B f32). std::invalid_argument when the arrays do not match one another.
std::string encode_frame(const Frame& frame);

}  // namespace tide::serve
