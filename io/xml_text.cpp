#include "xml_text.hpp"

#include <charconv>
#include <map>

namespace tide::io {

std::string xml_escaped(std::string_view text) {
  static const std::map<char, std::string_view> entities = {
      {'&', "&amp;"}, {'<', "&lt;"}, {'>', "&gt;"}, {'"', "&quot;"}};
  std::string escaped;
  for (const char c : text) {
    const auto entity = entities.find(c);
    if (entity == entities.end())
      escaped += c;
    else
      escaped += entity->second;
  }
  return escaped;
}

std::string exact_text(double value) {
  char text[32];
  const auto result = std::to_chars(text, text + sizeof text, value);
  return std::string(text, result.ptr);
}

}  // namespace tide::io
