// tide serve's frame messages (tide/serve/frame.hpp): read back here word by word, as the page
// reads them (web/frame.js), independently of the encoder.

#include <gtest/gtest.h>

#include <cstdint>
#include <cstring>
#include <stdexcept>
#include <string>

#include "tide/serve/frame.hpp"

namespace tide::serve {
namespace {

template <class T>
T word(const std::string& message, std::size_t index) {
  T value;
  std::memcpy(&value, message.data() + 4 * index, 4);
  return value;
}

TEST(ServeFrame, HeaderThenFluidColoursWallsObstacle) {
  Frame frame;
  frame.number = 7;
  frame.time = 1.25;
  frame.steps = (std::uint64_t{1} << 32) + 5;
  frame.colour = ColourField::pressure;
  frame.colour_low = -1;
  frame.colour_high = 2500;
  frame.view = {-0.1f, -0.2f, 1.1f, 0.9f};
  frame.particle_spacing = 0.02f;
  frame.fluid = {0.1f, 0.2f, 0.3f, 0.4f};
  frame.colour_values = {10, 20};
  frame.walls = {5, 6, 7, 8, 9, 10};
  frame.obstacle = {-3, -4};
  const std::string message = encode_frame(frame);
  ASSERT_EQ(message.size(), frame_header_bytes + 4 * (4 + 2 + 6 + 2));
  EXPECT_EQ(message.substr(0, 4), "TSPH");
  EXPECT_EQ(word<std::uint32_t>(message, 0), frame_magic);
  EXPECT_EQ(word<std::uint32_t>(message, 1), 1u);
  EXPECT_EQ(word<std::uint32_t>(message, 2), 2u);  // fluid
  EXPECT_EQ(word<std::uint32_t>(message, 3), 3u);  // walls
  EXPECT_EQ(word<std::uint32_t>(message, 4), 1u);  // obstacle
  EXPECT_EQ(word<std::uint32_t>(message, 5), 2u);  // pressure
  EXPECT_EQ(word<float>(message, 6), -1.0f);
  EXPECT_EQ(word<float>(message, 7), 2500.0f);
  EXPECT_EQ(word<float>(message, 8), 1.25f);
  EXPECT_EQ(word<std::uint32_t>(message, 9), 5u) << "the low 32 bits of the step count";
  EXPECT_EQ(word<std::uint32_t>(message, 10), 7u);
  EXPECT_EQ(word<float>(message, 11), -0.1f);
  EXPECT_EQ(word<float>(message, 14), 0.9f);
  EXPECT_EQ(word<float>(message, 15), 0.02f);
  const float expected[] = {0.1f, 0.2f, 0.3f, 0.4f, 10, 20, 5, 6, 7, 8, 9, 10, -3, -4};
  for (std::size_t k = 0; k < std::size(expected); ++k) EXPECT_EQ(word<float>(message, 16 + k), expected[k]) << k;
}

TEST(ServeFrame, AnEmptyFrameIsItsHeader) { EXPECT_EQ(encode_frame(Frame{}).size(), frame_header_bytes); }

TEST(ServeFrame, MismatchedArraysAreRefused) {
  Frame odd;
  odd.fluid = {1, 2, 3};
  odd.colour_values = {1};
  EXPECT_THROW(encode_frame(odd), std::invalid_argument);
  Frame uncoloured;
  uncoloured.fluid = {1, 2};
  EXPECT_THROW(encode_frame(uncoloured), std::invalid_argument);
}

}  // namespace
}  // namespace tide::serve
