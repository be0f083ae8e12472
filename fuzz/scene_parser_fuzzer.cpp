// libFuzzer target: any bytes given to tide::io::parse_scene either give a scene or a SceneError
// with a message. A crash, a sanitizer report, a hang or any other exception is a finding.

#include <cstddef>
#include <cstdint>
#include <string_view>

#include "tide/io/scene_reader.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string_view text(reinterpret_cast<const char*>(data), size);
  try {
    const tide::scene::Scene scene = tide::io::parse_scene(text, "fuzz.json");
    if (scene.dimension != 2 && scene.dimension != 3) __builtin_trap();
  } catch (const tide::io::SceneError& error) {
    if (std::string_view(error.what()).empty()) __builtin_trap();
  }
  return 0;
}
