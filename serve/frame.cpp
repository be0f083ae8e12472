#include "tide/serve/frame.hpp"

#include <bit>
#include <cstring>
#include <stdexcept>

namespace tide::serve {
namespace {

static_assert(std::endian::native == std::endian::little, "frames are little-endian: this host writes them as is");

class Writer {
 public:
  explicit Writer(std::size_t bytes) { text_.reserve(bytes); }
  template <class T>
  void put(T value) {
    static_assert(sizeof(T) == 4);
    char bytes[4];
    std::memcpy(bytes, &value, 4);
    text_.append(bytes, 4);
  }
  void put(const std::vector<float>& values) {
    text_.append(reinterpret_cast<const char*>(values.data()), values.size() * sizeof(float));
  }
  std::string take() { return std::move(text_); }

 private:
  std::string text_;
};

}  // namespace

std::string encode_frame(const Frame& frame) {
  const std::size_t n = frame.fluid.size() / 2;
  if (frame.fluid.size() % 2 != 0 || frame.walls.size() % 2 != 0 || frame.obstacle.size() % 2 != 0 ||
      frame.colour_values.size() != n)
    throw std::invalid_argument("encode_frame: position arrays of odd length, or not one colour value per particle");
  const std::size_t floats =
      frame.fluid.size() + frame.colour_values.size() + frame.walls.size() + frame.obstacle.size();
  Writer out(frame_header_bytes + 4 * floats);
  out.put(frame_magic);
  out.put(frame_version);
  out.put(static_cast<std::uint32_t>(n));
  out.put(static_cast<std::uint32_t>(frame.walls.size() / 2));
  out.put(static_cast<std::uint32_t>(frame.obstacle.size() / 2));
  out.put(static_cast<std::uint32_t>(frame.colour));
  out.put(frame.colour_low);
  out.put(frame.colour_high);
  out.put(static_cast<float>(frame.time));
  out.put(static_cast<std::uint32_t>(frame.steps));
  out.put(frame.number);
  for (const float v : frame.view) out.put(v);
  out.put(frame.particle_spacing);
  out.put(frame.fluid);
  out.put(frame.colour_values);
  out.put(frame.walls);
  out.put(frame.obstacle);
  return out.take();
}

}  // namespace tide::serve
